// The GLSL light equation and the CPU scene tracer's give the same numbers: a compute program,
// composed as every program of the plugin is (composeShader, tests/gl/ComputeTwin.h),
// evaluates lightIncidence() and directLight() on a grid of lights, surfaces and colours, and
// raytrace/LightEquation evaluates them in C++. Both compile scene/light_equation.glsl, so
// what this holds apart is each side's setting: the C++ wrappers and their records, the order
// the shaders are put together in, and the two compilers' arithmetic.
#include "raytrace/LightEquation.h"
#include "tests/gl/ComputeTwin.h"
#include "tests/gl/GlContextTest.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace ivshadow::test {
namespace {

class LightEquationTwinGLTest : public GlContextTest {};

// One evaluation, as the program reads it (std430: ten vec4s).
struct Case {
  glm::vec4 light{0.0f};       // GL's homogeneous light position
  glm::vec4 falloff{0.0f};     // constant, linear, quadratic attenuation; w: a spot light (1)
  glm::vec4 spot{0.0f};        // the spot direction; w: the cosine of its cutoff
  glm::vec4 position{0.0f};    // the shaded point; w: the spot exponent
  glm::vec4 normal{0.0f};      // the surface's unit normal; w: its shininess
  glm::vec4 towardsEye{0.0f};  // the viewer's direction
  glm::vec4 diffuse{0.0f};
  glm::vec4 specular{0.0f};
  glm::vec4 lightDiffuse{0.0f};
  glm::vec4 lightSpecular{0.0f};
};
static_assert(sizeof(Case) == 160, "Case must match the program's std430 layout");

// The incidence (direction, attenuation), the direct light, and the light's unshadowed
// contribution (attenuation x direct) that the shading program and the tracer add up.
struct Result {
  glm::vec4 incidence{0.0f};
  glm::vec4 direct{0.0f};
  glm::vec4 contribution{0.0f};
};
static_assert(sizeof(Result) == 48, "Result must match the program's std430 layout");

constexpr const char* kProgram = R"glsl(
struct Case {
  vec4 light; vec4 falloff; vec4 spot; vec4 position; vec4 normal; vec4 towardsEye;
  vec4 diffuse; vec4 specular; vec4 lightDiffuse; vec4 lightSpecular;
};
struct Result { vec4 incidence; vec4 direct; vec4 contribution; };
Result evaluate(Case c) {
  vec4 incidence = lightIncidence(c.light, c.position.xyz, c.falloff.xyz, c.falloff.w != 0.0,
                                  c.spot.xyz, c.spot.w, c.position.w);
  vec3 direct = directLight(c.normal.xyz, incidence.xyz, c.towardsEye.xyz, c.diffuse.rgb,
                            c.lightDiffuse.rgb, c.specular.rgb, c.lightSpecular.rgb, c.normal.w);
  return Result(incidence, vec4(direct, 0.0), vec4(incidence.w * direct, 0.0));
}
)glsl";

LightPlacement placementOf(const Case& c) {
  LightPlacement light;
  light.position = c.light;
  light.falloff = glm::vec3(c.falloff);
  light.spot = c.falloff.w != 0.0f;
  light.spotDirection = glm::vec3(c.spot);
  light.spotCosCutoff = c.spot.w;
  light.spotExponent = c.position.w;
  return light;
}

Result onCpu(const Case& c) {
  const LightIncidence in = lightIncidence(placementOf(c), glm::vec3(c.position));
  const Reflectance surface{glm::vec3(c.diffuse), glm::vec3(c.specular), c.normal.w};
  const glm::vec3 direct =
      directLight(glm::vec3(c.normal), in.toLight, glm::vec3(c.towardsEye), surface,
                  glm::vec3(c.lightDiffuse), glm::vec3(c.lightSpecular));
  return {glm::vec4(in.toLight, in.attenuation), glm::vec4(direct, 0.0f),
          glm::vec4(in.attenuation * direct, 0.0f)};
}

// Comparisons at their edge (N.L or N.H at 0, the spot's cosine at its cutoff) may fall either
// way by an ulp of their inputs: a step the picture shows at one pixel's edge, not a
// difference of the equation. The grid keeps 1e-3 away from them, and from pow(0, 0), which
// GLSL leaves undefined.
bool nearAnEdge(const Case& c) {
  const LightIncidence in = lightIncidence(placementOf(c), glm::vec3(c.position));
  const glm::vec3 normal(c.normal);
  const float nDotL = glm::dot(normal, in.toLight);
  const float nDotH = glm::dot(normal, glm::normalize(in.toLight + glm::vec3(c.towardsEye)));
  const bool spot = c.light.w != 0.0f && c.falloff.w != 0.0f;
  const float spotCos = glm::dot(-in.toLight, glm::normalize(glm::vec3(c.spot)));
  return std::abs(nDotL) < 1e-3f || (nDotL > 0.0f && std::abs(nDotH) < 1e-3f) ||
         (spot && (std::abs(spotCos - c.spot.w) < 1e-3f || std::abs(spotCos) < 1e-3f));
}

// The grid's lights: GL's kinds (directional, point, spot) at a few directions, positions,
// attenuations, cutoffs and dropoffs, a point light's position given with w = 2 as well.
std::vector<Case> gridLights() {
  const std::array<glm::vec3, 3> directions = {
      glm::vec3(0.0f, 0.0f, 1.0f), glm::vec3(0.3f, -0.5f, 0.8f), glm::vec3(-2.0f, 1.0f, 0.5f)};
  const std::array<glm::vec4, 3> places = {glm::vec4(0.0f, 0.0f, 5.0f, 1.0f),
                                           glm::vec4(3.0f, 4.0f, 2.0f, 1.0f),
                                           glm::vec4(-6.0f, 2.0f, 8.0f, 2.0f)};
  const std::array<glm::vec3, 4> falloffs = {
      glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(0.5f, 0.2f, 0.0f), glm::vec3(1.0f, 0.1f, 0.05f),
      glm::vec3(0.0f, 0.0f, 1.0f)};
  std::vector<Case> lights;
  for (const glm::vec3& d : directions) lights.push_back({glm::vec4(d, 0.0f), {1, 0, 0, 0}});
  for (const glm::vec4& p : places)
    for (const glm::vec3& f : falloffs) {
      lights.push_back({p, glm::vec4(f, 0.0f)});
      // A spot aimed at the grid's surface points from above, at cutoffs 20, 45 and 80
      // degrees, with dropoffs from none to GL's largest exponent.
      for (float cutoff : {20.0f, 45.0f, 80.0f})
        for (float exponent : {0.0f, 1.0f, 10.0f, 128.0f}) {
          Case spot{p, glm::vec4(f, 1.0f)};
          spot.spot = glm::vec4(glm::vec3(0.1f, 0.0f, -1.0f), std::cos(glm::radians(cutoff)));
          spot.position.w = exponent;
          lights.push_back(spot);
        }
    }
  return lights;
}

// Each light on each surface point, normal (and the opposite normal, as two-sided lighting
// turns a back face's), viewer, colours and shininess.
std::vector<Case> gridCases() {
  const std::array<glm::vec3, 4> points = {glm::vec3(0.0f), glm::vec3(1.0f, -0.5f, 0.2f),
                                           glm::vec3(-2.0f, 1.5f, -1.0f),
                                           glm::vec3(0.4f, 0.3f, 1.0f)};
  const std::array<glm::vec3, 3> normals = {glm::vec3(0.0f, 0.0f, 1.0f),
                                            glm::normalize(glm::vec3(0.5f, 0.2f, 0.8f)),
                                            glm::normalize(glm::vec3(-0.7f, 0.6f, 0.3f))};
  const std::array<glm::vec3, 2> eyes = {glm::vec3(0.0f, 0.0f, 1.0f),
                                         glm::normalize(glm::vec3(0.2f, 0.4f, 0.9f))};
  const std::array<std::array<glm::vec4, 4>, 2> colours = {{
      {glm::vec4(0.8f, 0.5f, 0.2f, 1.0f), glm::vec4(1.0f), glm::vec4(1.0f), glm::vec4(1.0f)},
      {glm::vec4(0.1f, 0.9f, 0.4f, 1.0f), glm::vec4(0.3f, 0.3f, 0.6f, 1.0f),
       glm::vec4(0.9f, 0.7f, 0.5f, 1.0f), glm::vec4(0.2f, 0.4f, 1.0f, 1.0f)},
  }};
  std::vector<Case> cases;
  for (const Case& light : gridLights())
    for (const glm::vec3& point : points)
      for (const glm::vec3& normal : normals)
        for (float side : {1.0f, -1.0f})
          for (const glm::vec3& eye : eyes)
            for (const auto& colour : colours)
              for (float shininess : {0.0f, 1.0f, 12.8f, 128.0f}) {
                Case c = light;
                c.position = glm::vec4(point, light.position.w);
                c.normal = glm::vec4(side * normal, shininess);
                c.towardsEye = glm::vec4(eye, 0.0f);
                c.diffuse = colour[0];
                c.specular = colour[1];
                c.lightDiffuse = colour[2];
                c.lightSpecular = colour[3];
                if (!nearAnEdge(c)) cases.push_back(c);
              }
  return cases;
}

// How far apart the two compilers' arithmetic may leave a component of size `value`, when the
// case raises to the powers `spotExponent` and `shininess`. Each side's +, -, * and
// comparisons are exact to the ulp (llvmpipe, as IEEE float); GLSL lets division, sqrt and
// inversesqrt (length, normalize) be a few ulp off, about 5e-7 relatively in a direction,
// distance or attenuation. pow(x, e) is exp2(e log2 x) in GLSL, which turns a relative error
// d of x into e d, and adds e times log2's own (2^-21 absolute near 1) x ln 2, about
// 3.3e-7 e: with d = 5e-7, both together are about 8.3e-7 e. So a component may be
// 2e-6 (1 + e) times its size off, with e the sum of the case's exponents, about twice the
// bound; a different model (a swapped falloff, specular for diffuse, a dropped spot or
// distance term) moves the grid's values by a percent or more.
float tolerance(const Case& c, float value) {
  const float exponents = c.position.w * c.falloff.w + c.normal.w;
  return 2e-6f * (1.0f + exponents) * std::max(std::abs(value), 1e-2f);
}

TEST_F(LightEquationTwinGLTest, GlslAndCppAgreeOnAGridOfInputs) {
  const std::vector<Case> cases = gridCases();
  ASSERT_GT(cases.size(), 10000u);
  std::string error;
  const std::vector<Result> gpu = computeCases<Result>(kProgram, cases, error);
  ASSERT_EQ(gpu.size(), cases.size()) << error;
  int failures = 0;
  for (std::size_t i = 0; i < cases.size() && failures < 10; ++i) {
    const Result cpu = onCpu(cases[i]);
    const std::array<std::pair<glm::vec4, glm::vec4>, 3> pairs = {
        {{cpu.incidence, gpu[i].incidence},
         {cpu.direct, gpu[i].direct},
         {cpu.contribution, gpu[i].contribution}}};
    for (std::size_t r = 0; r < pairs.size(); ++r)
      for (int k = 0; k < 4; ++k) {
        const float a = pairs[r].first[k], b = pairs[r].second[k];
        if (std::abs(a - b) <= tolerance(cases[i], a)) continue;
        ++failures;
        ADD_FAILURE() << "case " << i << " (light " << cases[i].light.x << ' ' << cases[i].light.y
                      << ' ' << cases[i].light.z << ' ' << cases[i].light.w << ", spot "
                      << cases[i].falloff.w << ", exponent " << cases[i].position.w
                      << ", shininess " << cases[i].normal.w << "): result " << r << " component "
                      << k << " is " << a << " in C++, " << b << " in GLSL";
      }
  }
}

}  // namespace
}  // namespace ivshadow::test
