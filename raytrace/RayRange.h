#pragma once

#include "scene/ShapeValidation.h"

#include <glm/vec3.hpp>

#include <cmath>

namespace ivshadow {

// Whether Embree takes a ray from `origin` along `direction`: both finite and within
// kLargestTracedCoordinate in every component (Embree's ray.valid() assertion aborts the
// process otherwise). Shapes reaching past that range in world coordinates are left out where
// scenes are loaded and extracted; this guards everything else that reaches Embree (a group's
// own coordinates, which may lie farther than the world's under a scale, a camera placed that
// far, a capture texel a driver left undefined): such a ray is not traced.
inline bool embreeTakesRay(const glm::vec3& origin, const glm::vec3& direction) {
  for (int i = 0; i < 3; ++i)
    if (!(std::fabs(origin[i]) <= kLargestTracedCoordinate) ||
        !(std::fabs(direction[i]) <= kLargestTracedCoordinate))
      return false;
  return true;
}

}  // namespace ivshadow
