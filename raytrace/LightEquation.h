#pragma once

#include "ivshadow/Export.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace ivshadow {

// The CPU side of scene/light_equation.glsl: Coin's light equation, which the shading program
// evaluates per pixel in eye space and the CPU scene tracer at each shaded point in world
// space, so that only the space differs between them, never the formula.

// A GL light as the equation reads it, in the space the caller shades in.
struct LightPlacement {
  glm::vec4 position{0.0f, 0.0f, 1.0f, 0.0f};  // homogeneous; w = 0: xyz is towards the light
  glm::vec3 falloff{1.0f, 0.0f, 0.0f};         // constant, linear, quadratic attenuation
  bool spot = false;
  glm::vec3 spotDirection{0.0f, 0.0f, -1.0f};
  float spotCosCutoff = -1.0f;
  float spotExponent = 0.0f;
};

// Where a light is seen from a point: the unit direction towards it and GL's distance and spot
// attenuation of its light there.
struct LightIncidence {
  glm::vec3 toLight{0.0f};
  float attenuation = 0.0f;
};
IVSHADOW_INTERNAL LightIncidence lightIncidence(const LightPlacement& light,
                                                const glm::vec3& position);

// A surface's colours for the light equation: GL's diffuse (the vertex colour under Coin),
// specular and shininess (GL's exponent, 0 to 128).
struct Reflectance {
  glm::vec3 diffuse{0.0f};
  glm::vec3 specular{0.0f};
  float shininess = 0.0f;
};

// The light a surface of unit normal `normal` sends towards the eye (`towardsEye`, one
// direction for the whole picture) from a light of diffuse and specular colours
// `lightDiffuse` and `lightSpecular` in unit direction `toLight`, before the attenuation and
// the shadow; zero where the light is behind the surface.
IVSHADOW_INTERNAL glm::vec3 directLight(const glm::vec3& normal, const glm::vec3& toLight,
                                        const glm::vec3& towardsEye, const Reflectance& surface,
                                        const glm::vec3& lightDiffuse,
                                        const glm::vec3& lightSpecular);

}  // namespace ivshadow
