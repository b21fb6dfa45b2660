#include "nodes/DepthPrecision.h"

#include "scene/SceneTriangles.h"
#include "scene/WarnOnce.h"

#include <Inventor/SbViewVolume.h>
#include <Inventor/elements/SoViewVolumeElement.h>
#include <Inventor/errors/SoDebugError.h>

#include <algorithm>
#include <sstream>
#include <string>

namespace ivshadow {
namespace {

std::string number(float value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

}  // namespace

void warnCoarseDepth(const SoNode* where, SoState* state) {
  const SbViewVolume& volume = SoViewVolumeElement::get(state);
  const float nearDistance = volume.getNearDist();
  const float depth = volume.getDepth();
  std::string why;
  if (volume.getProjectionType() == SbViewVolume::PERSPECTIVE) {
    const float ratio = (nearDistance + depth) / nearDistance;
    if (nearDistance > 0.0f && ratio > kMaxDepthRatio)
      why = "the camera's far/near ratio of " + number(ratio) + " (above " +
            number(kMaxDepthRatio) + ")";
  } else {
    // Linear depth: a step of the buffer against the view's size.
    const float step = depth / float(1 << 24);
    const float size = std::max(volume.getWidth(), volume.getHeight());
    if (step > kMaxOrthographicDepthStep * size)
      why = "the camera's depth of " + number(depth) + " over a view " + number(size) + " wide";
  }
  if (why.empty() || !firstWarning(where, "coarse depth")) return;
  SoDebugError::postWarning("ivshadow",
                            "%s: %s leaves GL's depth buffer too coarse to order its surfaces; "
                            "renderer TRACER draws them exactly, or bring nearDistance and "
                            "farDistance closer to the scene",
                            describeNode(where).c_str(), why.c_str());
}

}  // namespace ivshadow
