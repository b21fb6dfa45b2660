#include "cli/RenderMemory.h"

#include "ivshadow/SoDeepShadowLight.h"
#include "ivshadow/SoPeelingSeparator.h"
#include "ivshadow/SoTransparentShadowGroup.h"
#include "nodes/NodesOfType.h"

namespace ivshadow {

RenderMemory RenderMemory::of(SoNode* root, bool softwareRenderer, bool traced) {
  bool rays = traced, volumes = false;
  forEachNodeOfType<SoDeepShadowLight>(root, [&](SoDeepShadowLight& light) {
    const int method = light.method.getValue();
    volumes = volumes || method == SoDeepShadowLight::VOLUMES;
    rays = rays || method == SoDeepShadowLight::RAYS || volumes ||
           (method == SoDeepShadowLight::AUTO_METHOD && softwareRenderer);
  });
  int separators = 0;
  forEachNodeOfType<SoPeelingSeparator>(root, [&](SoPeelingSeparator&) { ++separators; });
  // A group that peels (its default) keeps the same targets once it meets a transparent
  // fragment; counted whether or not it will, as the budget must hold for any view.
  int groups = 0;
  forEachNodeOfType<SoTransparentShadowGroup>(root, [&](SoTransparentShadowGroup& group) {
    if (group.isActive.getValue() &&
        group.transparency.getValue() == SoTransparentShadowGroup::PEELED)
      ++groups;
  });

  RenderMemory memory{{kFrameBytesPerPixel, kFrameFixedBytes}, "a render"};
  memory.cost.bytesPerPixel +=
      (kPeelingBytesPerPixel + kFragmentListBytesPerPixel) * (separators + groups);
  if (rays) memory.cost.bytesPerPixel += kRaysBytesPerPixel;
  if (volumes) memory.cost.bytesPerPixel += kVolumesBytesPerPixel;
  if (rays) memory.what += " with traced (RAYS) shadows";
  std::string peelers;
  if (separators > 0)
    peelers =
        std::to_string(separators) + (separators == 1 ? " PeelingSeparator" : " PeelingSeparators");
  if (groups > 0)
    peelers += (peelers.empty() ? "" : " and ") + std::to_string(groups) +
               (groups == 1 ? " peeling group" : " peeling groups");
  if (!peelers.empty()) memory.what += std::string(rays ? " and " : " with ") + peelers;
  return memory;
}

}  // namespace ivshadow
