#pragma once

#include "tests/gl/ShadowScene.h"

#include <ostream>
#include <string>
#include <vector>

namespace ivshadow::test {

// A ShadowScene with state set above its group, outside it, and the picture that state must
// give: the shadows of the casters as Coin draws them there. Each picture is computed in the
// test (similar triangles, Lambert, eq. 5.3), not from the plugin's extraction.
struct InheritedCase {
  std::string name;
  ShadowScene scene;
  ExpectedImage expected;
};

// One case per kind of inherited state: Material (transparency), BaseColor, Texture2 with
// Complexity's textureQuality, a texture matrix, texture coordinates, Complexity (a sphere's
// facets), Units, ShadowStyle (both ways), DrawStyle LINES, LightModel (both ways), ShapeHints and
// a transform above the group.
std::vector<InheritedCase> inheritedStateCases();
std::string inheritedCaseName(const ::testing::TestParamInfo<InheritedCase>& info);
// How gtest names a case in its messages (instead of the object's bytes).
inline void PrintTo(const InheritedCase& c, std::ostream* os) {
  *os << c.name;
}

// The floor point at the centre of pixel (px, py) of a ShadowScene picture.
double floorX(int px);
double floorY(int py);

}  // namespace ivshadow::test
