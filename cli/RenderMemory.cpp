#include "cli/RenderMemory.h"

#include "nodes/NodesOfType.h"
#include "ivshadow/SoDeepShadowLight.h"
#include "ivshadow/SoPeelingSeparator.h"

namespace ivshadow {

RenderMemory RenderMemory::of(SoNode* root, bool softwareRenderer, bool traced) {
  bool rays = traced;
  forEachNodeOfType<SoDeepShadowLight>(root, [&](SoDeepShadowLight& light) {
    const int method = light.method.getValue();
    rays = rays || method == SoDeepShadowLight::RAYS ||
           (method == SoDeepShadowLight::AUTO_METHOD && softwareRenderer);
  });
  int separators = 0;
  forEachNodeOfType<SoPeelingSeparator>(root, [&](SoPeelingSeparator&) { ++separators; });

  RenderMemory memory{{kFrameBytesPerPixel, kFrameFixedBytes}, "a render"};
  memory.cost.bytesPerPixel += kPeelingBytesPerPixel * separators;
  if (rays) memory.cost.bytesPerPixel += kRaysBytesPerPixel;
  if (rays) memory.what += " with traced (RAYS) shadows";
  if (separators > 0)
    memory.what += std::string(rays ? " and " : " with ") + std::to_string(separators) +
                   (separators == 1 ? " PeelingSeparator" : " PeelingSeparators");
  return memory;
}

}  // namespace ivshadow
