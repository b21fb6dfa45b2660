// The light's fields as the map builder takes them: the extremes of resolution (issue: "resolution
// 1 and the GL maximum"; rendering at the maximum, 16384^2 texels per face, would take gigabytes
// and minutes on llvmpipe, so the clamping to it is what is tested).
#include "ivshadow/IvShadowInit.h"
#include "ivshadow/SoDeepShadowLight.h"
#include "nodes/DeepShadowSettings.h"
#include "raytrace/CastingLight.h"
#include "scene_input/CoinMessageCapture.h"

#include <gtest/gtest.h>

namespace ivshadow {
namespace {

struct Resolved {
  DeepShadowSettings settings;
  std::vector<std::string> messages;
};

Resolved resolve(int resolution, int maxTextureSize) {
  init();
  auto* light = new SoDeepShadowLight;
  light->ref();
  light->setName("Lamp");
  light->resolution = resolution;
  Resolved out;
  {
    CoinMessageCapture capture;
    out.settings = resolveSettings(*light, maxTextureSize);
    for (const auto& message : capture.messages()) out.messages.push_back(message.raw);
  }
  light->unref();
  return out;
}

TEST(DeepShadowSettings, ResolutionAboveTheGlMaximumIsClampedToItWithOneWarning) {
  const Resolved r = resolve(1000000, 16384);
  EXPECT_EQ(r.settings.resolution, 16384);
  ASSERT_EQ(r.messages.size(), 1u);
  EXPECT_NE(r.messages[0].find("resolution"), std::string::npos) << r.messages[0];
  EXPECT_NE(r.messages[0].find("16384"), std::string::npos) << r.messages[0];
}

TEST(DeepShadowSettings, ResolutionOneAndTheMaximumItselfAreTakenAsTheyAre) {
  for (const int resolution : {1, 16384}) {
    const Resolved r = resolve(resolution, 16384);
    EXPECT_EQ(r.settings.resolution, resolution);
    EXPECT_TRUE(r.messages.empty()) << r.messages.front();
  }
}

TEST(DeepShadowSettings, MethodIsPassedOnUnresolved) {
  init();
  auto* light = new SoDeepShadowLight;
  light->ref();
  EXPECT_EQ(resolveSettings(*light, 16384).method, ShadowMethod::Auto);
  light->method = SoDeepShadowLight::RAYS;
  EXPECT_EQ(resolveSettings(*light, 16384).method, ShadowMethod::Rays);
  // A value that no name spells, set from C++, builds a map.
  light->method = 7;
  EXPECT_EQ(resolveSettings(*light, 16384).method, ShadowMethod::Map);
  light->unref();
}

// The table of SoDeepShadowLight's documentation: shadowColor decides whether the shadow is
// coloured (AUTO: when some transparent caster is coloured), colorModel how.
TEST(ShadowColourModel, FollowsShadowColorThenColorModel) {
  using L = SoDeepShadowLight;
  EXPECT_EQ(shadowColourModel(L::MONOCHROME, L::POWER, true), ShadowColourModel::Monochrome);
  EXPECT_EQ(shadowColourModel(L::COLORED, L::POWER, false), ShadowColourModel::Power);
  EXPECT_EQ(shadowColourModel(L::COLORED, L::SATURATE, false), ShadowColourModel::Saturate);
  EXPECT_EQ(shadowColourModel(L::AUTO, L::SATURATE, false), ShadowColourModel::Monochrome);
  EXPECT_EQ(shadowColourModel(L::AUTO, L::SATURATE, true), ShadowColourModel::Saturate);
  EXPECT_EQ(shadowColourModel(L::AUTO, L::POWER, true), ShadowColourModel::Power);
}

}  // namespace
}  // namespace ivshadow
