// GL lights with the first eight lights in force and Coin drops the others, so plain Coin
// lights a white floor under twelve equal lights as under eight. Every path of the plugin
// draws what Coin draws: the group by GL (RASTER), by the tracer (TRACER) and the reference,
// with lights inside the group, outside it, and outside any group; and each says once that
// lights were dropped (issue 36: the tracer and the reference lit with all of them).
#include "ivshadow/IvShadowInit.h"
#include "scene/CoinRef.h"
#include "scene_input/CoinMessageCapture.h"
#include "tests/gl/CheckedRenderer.h"
#include "tests/gl/ShadowScene.h"

#include <Inventor/nodes/SoSeparator.h>

#include <gtest/gtest.h>

#include <sstream>
#include <vector>

namespace ivshadow::test {
namespace {

constexpr int kSize = 32;
// Equal lights straight down onto the floor: each adds intensity x diffuse (1) to it.
constexpr double kIntensity = 0.05;

std::string lights(int count) {
  std::ostringstream iv;
  for (int i = 0; i < count; ++i)
    iv << "DirectionalLight { direction 0 0 -1 intensity " << kIntensity << " }\n";
  return iv.str();
}

// A white floor filling the view, no ambient and no specular: its grey is the lights' sum.
std::string scene(int outside, int inside, const std::string& group) {
  const std::string floor =
      "Material { ambientColor 0 0 0 diffuseColor 1 1 1 specularColor 0 0 0 }\n"
      "Coordinate3 { point [ -2 -2 0, 2 -2 0, 2 2 0, -2 2 0 ] }\n"
      "FaceSet { numVertices 4 }\n";
  std::ostringstream iv;
  iv << "#Inventor V2.1 ascii\nSeparator {\n"
     << "OrthographicCamera { position 0 0 5 nearDistance 1 farDistance 10 height 2 }\n"
     << lights(outside);
  if (group.empty())
    iv << lights(inside) << floor;
  else
    iv << "TransparentShadowGroup { " << group << "\n" << lights(inside) << floor << "}\n";
  iv << "}\n";
  return iv.str();
}

// Eight lights' worth, in 8-bit steps.
const double kEightLights = 255.0 * 8 * kIntensity;

int centreGrey(const Image& image) {
  return image.pixel(kSize / 2, kSize / 2)[1];
}

int limitWarnings(const CoinMessageCapture& messages, int inForce) {
  int count = 0;
  for (const CoinMessageCapture::Message& m : messages.messages())
    if (m.text.find(std::to_string(inForce) + " lights are in force") != std::string::npos &&
        m.text.find("GL lights with the first 8") != std::string::npos)
      ++count;
  return count;
}

// Plain Coin is the oracle the analytic value is checked against first: 12 lights outside
// any group of the plugin light as 8.
TEST(LightLimit, PlainCoinLightsWithTheFirstEight) {
  const Image image = renderIv(scene(0, 12, ""), kSize);
  // One 8-bit step: Coin sends the light colours as floats; GL rounds the sum once.
  EXPECT_NEAR(centreGrey(image), kEightLights, 1.0);
}

TEST(LightLimit, TheReferenceLightsOutsideGroupsWithTheFirstEightAndSaysSo) {
  init();
  CoinMessageCapture messages;
  const Image image = referenceIv(scene(0, 12, ""), kSize);
  EXPECT_NEAR(centreGrey(image), kEightLights, 1.0);  // one 8-bit step of rounding
  EXPECT_EQ(limitWarnings(messages, 12), 1);
}

struct Case {
  const char* name;
  int outside;
  int inside;
};

class LightLimitGroup : public ::testing::TestWithParam<Case> {};

TEST_P(LightLimitGroup, EveryPathLightsWithTheFirstEightInForceAndSaysSoOnce) {
  init();
  const Case c = GetParam();
  const int inForce = c.outside + c.inside;
  const int warnings = inForce > 8 ? 1 : 0;
  // Warnings are said once per node (scene/WarnOnce.h), and a node made where a freed one was
  // would be taken for it: every scene stays in memory until the end.
  std::vector<CoinRef<SoSeparator>> roots;
  for (const char* renderer : {"RASTER", "TRACER"}) {
    SCOPED_TRACE(renderer);
    CoinMessageCapture messages;
    std::string error;
    auto offscreen = CheckedRenderer::create(kSize, kSize, error);
    ASSERT_TRUE(offscreen) << error;
    SoSeparator* root = readIv(scene(c.outside, c.inside, std::string("renderer ") + renderer));
    roots.emplace_back(root);
    root->unref();  // readIv's reference: the list holds it now
    // Two frames: the warning is said once, not every frame.
    offscreen->render(root);
    offscreen->render(root);
    // One 8-bit step of rounding; the tracer adds the same terms in another order.
    EXPECT_NEAR(centreGrey(offscreen->read()), kEightLights, 1.0);
    EXPECT_EQ(limitWarnings(messages, inForce), warnings);
  }
  CoinMessageCapture messages;
  const Image image = referenceIv(scene(c.outside, c.inside, "renderer RASTER"), kSize);
  EXPECT_NEAR(centreGrey(image), kEightLights, 1.0);  // one 8-bit step of rounding
  EXPECT_EQ(limitWarnings(messages, inForce), warnings);
}

INSTANTIATE_TEST_SUITE_P(Cases, LightLimitGroup,
                         ::testing::Values(Case{"Inside", 0, 12}, Case{"OutsideAndInside", 3, 9},
                                           Case{"EightAreNotTooMany", 0, 8}),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           return std::string(info.param.name);
                         });

}  // namespace
}  // namespace ivshadow::test
