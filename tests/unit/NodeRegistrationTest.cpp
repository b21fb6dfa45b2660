// The plugin's light classes derive from Coin's PointLight, SpotLight and DirectionalLight;
// registering them must leave Coin's own types as they were. Coin's initClass of a built-in
// class registers it again when called a second time (it only asserts against it, and release
// builds drop asserts): SoDeepShadowLight's init once made a second "PointLight" type, and
// with a SpotLight subclass Coin's SoShadowSpotLight stopped being a SoSpotLight, so
// SoShadowGroup's spot lights lit nothing.
#include "ivshadow/IvShadowInit.h"

#include <Inventor/SoDB.h>
#include <Inventor/SoType.h>
#include <Inventor/annex/FXViz/nodes/SoShadowDirectionalLight.h>
#include <Inventor/annex/FXViz/nodes/SoShadowGroup.h>
#include <Inventor/annex/FXViz/nodes/SoShadowSpotLight.h>
#include <Inventor/nodes/SoPointLight.h>

#include <gtest/gtest.h>

namespace ivshadow {
namespace {

TEST(NodeRegistration, CoinsLightTypesStayTheSameAfterInit) {
  SoDB::init();
  SoShadowGroup::init();  // Coin's shadow lights, derived from its spot and directional light
  const SoType point = SoPointLight::getClassTypeId();
  const SoType spot = SoSpotLight::getClassTypeId();
  const SoType directional = SoDirectionalLight::getClassTypeId();
  init();
  init();  // twice, as an application and Coin's loader may both call it
  EXPECT_EQ(SoPointLight::getClassTypeId(), point);
  EXPECT_EQ(SoSpotLight::getClassTypeId(), spot);
  EXPECT_EQ(SoDirectionalLight::getClassTypeId(), directional);
  EXPECT_EQ(SoType::fromName("SpotLight"), spot);
  EXPECT_TRUE(SoShadowSpotLight::getClassTypeId().isDerivedFrom(SoSpotLight::getClassTypeId()));
  EXPECT_TRUE(SoShadowDirectionalLight::getClassTypeId().isDerivedFrom(
      SoDirectionalLight::getClassTypeId()));
  EXPECT_TRUE(SoType::fromName("DeepShadowLight").isDerivedFrom(point));
  EXPECT_TRUE(SoType::fromName("DeepShadowSpotLight").isDerivedFrom(spot));
  EXPECT_TRUE(SoType::fromName("DeepShadowDirectionalLight").isDerivedFrom(directional));
}

}  // namespace
}  // namespace ivshadow

namespace ivshadow {
namespace {

// Issue 35: `render` refused a Selection that `view` (SoQt::init) drew. After init() every
// command reads what SoQt's programs read: selection nodes, node kits, draggers, manipulators.
TEST(NodeRegistration, InitRegistersWhatSoQtRegisters) {
  init();
  for (const char* name : {"Selection", "ExtSelection", "ShapeKit", "SeparatorKit",
                           "TrackballManip", "Translate1Dragger", "PointLightManip"}) {
    SCOPED_TRACE(name);
    const SoType type = SoType::fromName(name);
    ASSERT_FALSE(type.isBad());
    EXPECT_TRUE(type.canCreateInstance());
  }
}

}  // namespace
}  // namespace ivshadow
