#include "nodes/DepthPrecision.h"

#include "scene/SceneTriangles.h"
#include "scene/WarnOnce.h"

#include <Inventor/SbViewVolume.h>
#include <Inventor/elements/SoViewVolumeElement.h>
#include <Inventor/errors/SoDebugError.h>

namespace ivshadow {

void warnCoarseDepth(const SoNode* where, SoState* state) {
  const SbViewVolume& volume = SoViewVolumeElement::get(state);
  if (volume.getProjectionType() != SbViewVolume::PERSPECTIVE) return;
  const float nearDistance = volume.getNearDist();
  const float ratio = (nearDistance + volume.getDepth()) / nearDistance;
  if (!(nearDistance > 0.0f) || !(ratio > kMaxDepthRatio) || !firstWarning(where, "coarse depth"))
    return;
  SoDebugError::postWarning("ivshadow",
                            "%s: the camera's far/near ratio of %g leaves GL's depth buffer too "
                            "coarse to order its surfaces (above %g); renderer TRACER draws them "
                            "exactly, or raise nearDistance",
                            describeNode(where).c_str(), double(ratio), double(kMaxDepthRatio));
}

}  // namespace ivshadow
