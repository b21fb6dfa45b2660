// The GLSL shading and its CPU twins give the same numbers: a compute program, composed as
// every program of the plugin is (composeShader, tests/gl/ComputeTwin.h), evaluates
// transmittance(), applyTextureModel() and isOpaque() on a grid of inputs, and
// raytrace/SurfaceOptics evaluates them in C++. Both compile scene/surface_optics.glsl, so what
// this holds apart is each side's setting: the colour models' and texture models' ids, the opacity
// threshold, the C++ wrappers, the order the shaders are put together in, and the two compilers'
// arithmetic.
#include "raytrace/SurfaceOptics.h"
#include "tests/gl/ComputeTwin.h"
#include "tests/gl/GlContextTest.h"

#include <glm/common.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace ivshadow::test {
namespace {

class SurfaceOpticsTwinGLTest : public GlContextTest {};

enum Function : int { kTransmittance = 0, kTextureModel = 1, kOpaque = 2 };

// One evaluation, as the program reads it (std430: four vec4-sized members).
struct Case {
  glm::vec4 a{0.0f};            // the colour (kOpaque: the alpha in x)
  glm::vec4 b{0.0f};            // the texel
  glm::vec4 c{0.0f};            // the texture's blend colour
  std::array<int, 4> select{};  // the function, the model
};
static_assert(sizeof(Case) == 64, "Case must match the program's std430 layout");

constexpr const char* kProgram = R"glsl(
struct Case { vec4 a; vec4 b; vec4 c; ivec4 select; };
struct Result { vec4 value; };
Result evaluate(Case c) {
  if (c.select.x == 0) return Result(vec4(transmittance(c.a, c.select.y), 0.0));
  if (c.select.x == 1) return Result(applyTextureModel(c.a, c.b, c.select.y, c.c.rgb));
  return Result(vec4(isOpaque(c.a.x) ? 1.0 : 0.0));
}
)glsl";

// The grid: every colour and opacity of kLevels per channel in each colour model; colours and
// texels of kTexLevels in each texture model; opacities about the opaque threshold.
constexpr std::array<float, 7> kLevels = {0.0f, 0.1f, 0.25f, 0.5f, 0.75f, 0.9f, 1.0f};
constexpr std::array<float, 4> kTexLevels = {0.0f, 0.3f, 0.8f, 1.0f};
constexpr std::array<int, 5> kTextureModels = {0, 0x0BE2, 0x2100, 0x2101, 0x1E01};

std::vector<Case> gridCases() {
  std::vector<Case> cases;
  for (int model = 0; model < 3; ++model)
    for (float r : kLevels)
      for (float g : kLevels)
        for (float b : kLevels)
          for (float a : kLevels) cases.push_back({{r, g, b, a}, {}, {}, {kTransmittance, model}});
  const glm::vec4 blend(0.2f, 0.6f, 0.9f, 0.0f);
  for (int model : kTextureModels)
    for (float cr : kTexLevels)
      for (float ca : kTexLevels)
        for (float tr : kTexLevels)
          for (float tg : kTexLevels)
            for (float ta : kTexLevels)
              cases.push_back({{cr, 1.0f - cr, 0.5f, ca},
                               {tr, tg, 1.0f - tr, ta},
                               blend,
                               {kTextureModel, model}});
  for (int step = -4; step <= 4; ++step)
    cases.push_back({glm::vec4(kOpaqueAlpha + float(step) * 1e-7f), {}, {}, {kOpaque, 0}});
  return cases;
}

glm::vec4 onCpu(const Case& c) {
  switch (c.select[0]) {
    case kTransmittance:
      return glm::vec4(transmittance(c.a, ShadowColourModel(c.select[1])), 0.0f);
    case kTextureModel:
      return applyTextureModel(c.a, c.b, c.select[1], glm::vec3(c.c));
    default:
      return glm::vec4(isOpaque(c.a.x) ? 1.0f : 0.0f);
  }
}

// Every result lies in [0, 1]. GLSL lets pow() be exp2(y log2 x), each within a few ulp
// (log2 within 2^-21 absolute near 1), which for exponents up to 2 is about 1e-6 off; mix()
// may be x (1 - a) + y a or x + a (y - x), fused or not, a few ulp (2.4e-7 near 1) apart;
// the rest (+, -, *, clamp, comparisons) is exact in both (llvmpipe: at most 1.2e-7, one ulp
// below 1). 1e-5 is ten times that bound,
// and a hundred times below the smallest change a different model or id makes on the grid
// (a level step of 0.1 in a colour or opacity).
constexpr float kTolerance = 1e-5f;

TEST_F(SurfaceOpticsTwinGLTest, GlslAndCppAgreeOnAGridOfInputs) {
  const std::vector<Case> cases = gridCases();
  std::string error;
  const std::vector<glm::vec4> gpu = computeCases<glm::vec4>(kProgram, cases, error);
  ASSERT_EQ(gpu.size(), cases.size()) << error;
  int failures = 0;
  for (std::size_t i = 0; i < cases.size() && failures < 10; ++i) {
    const glm::vec4 cpu = onCpu(cases[i]);
    for (int k = 0; k < 4; ++k)
      if (!(std::abs(cpu[k] - gpu[i][k]) <= kTolerance)) {
        ++failures;
        ADD_FAILURE() << "case " << i << " (function " << cases[i].select[0] << ", model "
                      << cases[i].select[1] << ", inputs " << cases[i].a[0] << ' ' << cases[i].a[1]
                      << ' ' << cases[i].a[2] << ' ' << cases[i].a[3] << "): component " << k
                      << " is " << cpu[k] << " in C++, " << gpu[i][k] << " in GLSL";
        break;
      }
  }
}

}  // namespace
}  // namespace ivshadow::test
