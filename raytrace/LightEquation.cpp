#include "raytrace/LightEquation.h"

#include <glm/common.hpp>
#include <glm/exponential.hpp>
#include <glm/geometric.hpp>

namespace ivshadow {
namespace {

// The equation the GLSL programs evaluate, compiled from their text: glm's names are GLSL's.
namespace shared {
using glm::dot;
using glm::isinf;
using glm::length;
using glm::max;
using glm::normalize;
using glm::pow;
using glm::vec3;
using glm::vec4;
#include "scene/light_equation.glsl"
}  // namespace shared

}  // namespace

LightIncidence lightIncidence(const LightPlacement& light, const glm::vec3& position) {
  const glm::vec4 in =
      shared::lightIncidence(light.position, position, light.falloff, light.spot,
                             light.spotDirection, light.spotCosCutoff, light.spotExponent);
  return {glm::vec3(in), in.w};
}

glm::vec3 directLight(const glm::vec3& normal, const glm::vec3& toLight,
                      const glm::vec3& towardsEye, const Reflectance& surface,
                      const glm::vec3& lightDiffuse, const glm::vec3& lightSpecular) {
  return shared::directLight(normal, toLight, towardsEye, surface.diffuse, lightDiffuse,
                             surface.specular, lightSpecular, surface.shininess);
}

}  // namespace ivshadow
