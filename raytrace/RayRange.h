#pragma once

#include "scene/ShapeValidation.h"

#include <glm/vec3.hpp>

#include <cmath>

namespace ivshadow {

// Whether Embree takes a ray from `origin` along `direction`: both finite and within
// kLargestTracedCoordinate in every component (Embree's ray.valid() assertion aborts the
// process otherwise). Shapes past that range are left out where scenes are loaded and
// extracted; this guards what reaches Embree from elsewhere (a camera placed that far, a
// capture texel a driver left undefined) so that such a ray is not traced instead.
inline bool embreeTakesRay(const glm::vec3& origin, const glm::vec3& direction) {
  for (int i = 0; i < 3; ++i)
    if (!(std::fabs(origin[i]) <= kLargestTracedCoordinate) ||
        !(std::fabs(direction[i]) <= kLargestTracedCoordinate))
      return false;
  return true;
}

}  // namespace ivshadow
