#include "tests/gl/InheritedStateCases.h"

#include <algorithm>
#include <cmath>

namespace ivshadow::test {
namespace {

constexpr double kPixel = 1.0 / 100.0;    // floor units per pixel of a ShadowScene picture
constexpr double kMargin = 2.0 * kPixel;  // ShadowPicture's margin around every edge

double lambert(double x, double y) {
  return 255.0 / std::sqrt(1.0 + x * x + y * y);
}

Expectation grey(double value) {
  Expectation e;
  e.checked = true;
  e.rgb.fill(value);
  return e;
}

// The floor's edge and the background, as ShadowPicture has them; true when (x, y) is decided.
bool outsideFloor(double x, double y, Expectation& e) {
  const double extent = std::max(std::abs(x), std::abs(y));
  if (extent >= 1.0 + kMargin) {
    e = grey(0.0);
    return true;
  }
  return extent > 1.0 - kMargin;
}

ShadowScene redGlass() {
  ShadowScene scene;
  scene.filters = {kRedGlass};
  return scene;
}

// The picture of `expected` (ShadowPicture, eq. 5.3).
ExpectedImage pictureOf(const ShadowScene& expected, bool checkFilters = false) {
  return [expected, checkFilters](int px, int py) {
    ShadowPicture picture{&expected, ColourModel::Saturate};
    picture.checkFilters = checkFilters;
    return picture(px, py);
  };
}

// The red glass's picture with the glass letting all light through: no shadow anywhere.
ShadowScene withoutShadow(ShadowScene scene) {
  for (Filter& f : scene.filters) f.transparency = 1.0;
  return scene;
}

// The floor under the checkerboard glass (checkerboardFilter) held 0.5 above it. Floor point
// (x, y) takes the light through glass point (x, y) / 2; Coin's default texture coordinates
// put texel (0, 0) at the glass's lower left corner: the lower left and upper right quarters
// are opaque, the others clear (`swapped`: the other way round).
ExpectedImage checkerboardShadow(bool swapped) {
  return [swapped](int px, int py) {
    const double x = -1.2 + (px + 0.5) * kPixel, y = 1.2 - (py + 0.5) * kPixel;
    Expectation e;
    if (outsideFloor(x, y, e)) return e;
    const double extent = std::max(std::abs(x), std::abs(y));
    if (extent < 0.3 + kMargin || std::abs(extent - 0.6) < kMargin || std::abs(x) < kMargin ||
        std::abs(y) < kMargin)
      return e;
    const bool opaque = extent < 0.6 && ((x < 0.0) == (y < 0.0)) != swapped;
    return grey(opaque ? 0.0 : lambert(x, y));
  };
}

}  // namespace

double floorX(int px) {
  return -1.2 + (px + 0.5) * kPixel;
}

double floorY(int py) {
  return 1.2 - (py + 0.5) * kPixel;
}

// Ambient and specular off, so that a material's diffuse colour alone lights the picture.
const std::string kNoAmbient = "ambientColor 0 0 0 specularColor 0 0 0 ";

// Materials and textures above the group.
void addMaterialCases(std::vector<InheritedCase>& cases) {
  {  // The glass has no material of its own: the red, half transparent one above applies.
    ShadowScene scene = redGlass();
    scene.filters[0].ownMaterial = false;
    scene.aboveGroup =
        "DEF Above Material { " + kNoAmbient + "diffuseColor 1 0 0 transparency 0.5 }";
    cases.push_back({"MaterialAbove", scene, pictureOf(redGlass())});
  }
  {  // A BaseColor above replaces only the diffuse colour of the material above it.
    ShadowScene scene = redGlass();
    scene.filters[0].ownMaterial = false;
    scene.aboveGroup = "Material { " + kNoAmbient +
                       "diffuseColor 0 0 1 transparency 0.5 } BaseColor { rgb 1 0 0 }";
    cases.push_back({"BaseColorAbove", scene, pictureOf(redGlass())});
  }
  {  // The checkerboard texture (and its nearest sampling) above; the floor turns it off.
    ShadowScene scene;
    Filter glass = checkerboardFilter();
    scene.aboveGroup = glass.nodes;
    glass.nodes.clear();
    scene.filters = {glass};
    scene.floorNodes = "Texture2 { }";
    cases.push_back({"TextureAbove", scene, checkerboardShadow(false)});
    // A texture matrix above moving s by half the texture: REPEAT brings the other column.
    scene.aboveGroup += " Texture2Transform { translation 0.5 0 }";
    cases.push_back({"TextureTransformAbove", scene, checkerboardShadow(true)});
    // Texture coordinates above, mirrored in s (the glass's corners are listed from its
    // lower left, counter-clockwise); the floor takes them too, untextured.
    scene.aboveGroup =
        checkerboardFilter().nodes + " TextureCoordinate2 { point [ 1 0, 0 0, 0 1, 1 1 ] }";
    cases.push_back({"TextureCoordinatesAbove", scene, checkerboardShadow(true)});
  }
}

// What shapes above the group become: complexity, units and transforms.
void addGeometryCases(std::vector<InheritedCase>& cases) {
  {  // Complexity 0.1 above: Coin's sphere with int(30 * 0.1) = 3 slices and stacks, raised
     // to its minimum of 4 slices and 3 stacks (SoSphere, sogen_generate_sphere), is an
     // octahedron: vertices at the poles and at 4 points of the equator, here (+-r, 0, h),
     // (0, 0, h +- r) and the poles (0, +-r, h). From the light 1 above the floor the
     // equator's vertices fall at (+-r / (1 - h), 0) and (0, +-r / (1 - h)): the shadow is
     // the square |x| + |y| < 0.4 turned by 45 degrees, where a fine sphere's would be the
     // disc of radius tan(asin(0.4)) = 0.436 (floor point (0.3, 0.3) lies between the two).
     // The camera sees the octahedron as |x| + |y| < 0.2.
    ShadowScene scene;
    scene.aboveGroup = "Complexity { value 0.1 }";
    scene.groupNodes = "Separator { Material { " + kNoAmbient +
                       "diffuseColor 1 1 1 } Translation { translation 0 0 0.5 } "
                       "Sphere { radius 0.2 } }";
    cases.push_back({"ComplexityAbove", scene, [](int px, int py) {
                       const double x = floorX(px), y = floorY(py);
                       Expectation e;
                       if (outsideFloor(x, y, e)) return e;
                       // Distances to the diamonds' edges: |x| + |y| - d over sqrt(2).
                       const double diamond = (std::abs(x) + std::abs(y)) / std::sqrt(2.0);
                       if (diamond < (0.2 / std::sqrt(2.0)) + kMargin) return e;
                       const double edge = 0.4 / std::sqrt(2.0);
                       if (std::abs(diamond - edge) < kMargin) return e;
                       return grey(diamond < edge ? 0.0 : lambert(x, y));
                     }});
  }
  {  // Units: the scale above undoes the centimetres above, and the glass's own Units node
     // names the units already in force, which changes nothing (a default state would
     // shrink the glass to a hundredth).
    ShadowScene scene = redGlass();
    scene.aboveGroup = "Scale { scaleFactor 100 100 100 } Units { units CENTIMETERS }";
    scene.filters[0].nodes = "Units { units CENTIMETERS }";
    cases.push_back({"UnitsAbove", scene, pictureOf(redGlass())});
  }
  {  // A transform above moves and shrinks lights and casters together: the picture is the
     // red glass's, at half size and moved. The cosine of Lambert's law is scale free, and
     // the light has no attenuation.
    ShadowScene scene = redGlass();
    scene.aboveGroup = "DEF Move Transform { translation 0.3 -0.2 0 scaleFactor 0.5 0.5 0.5 }";
    const ShadowScene expected = redGlass();
    cases.push_back({"TransformAbove", scene, [expected](int px, int py) {
                       const ShadowPicture picture{&expected, ColourModel::Saturate};
                       return picture.at((floorX(px) - 0.3) / 0.5, (floorY(py) + 0.2) / 0.5,
                                         kPixel / 0.5);
                     }});
  }
}

// Styles above the group: shadow style, draw style, light model and shape hints.
void addStyleCases(std::vector<InheritedCase>& cases) {
  {  // Shapes that only receive cast nothing.
    ShadowScene scene = redGlass();
    scene.aboveGroup = "ShadowStyle { style SHADOWED }";
    cases.push_back({"ShadowStyleShadowedAbove", scene, pictureOf(withoutShadow(redGlass()))});
  }
  {  // The glass casts (the style above), the floor receives (its own style).
    ShadowScene scene = redGlass();
    scene.aboveGroup = "ShadowStyle { style CASTS_SHADOW }";
    scene.floorNodes = "ShadowStyle { style SHADOWED }";
    cases.push_back({"ShadowStyleCastsAbove", scene, pictureOf(redGlass())});
  }
  {  // The glass drawn as its outline casts nothing, and the floor is seen inside it; the
     // floor draws itself filled. Pixels within 3 of the outline (1 pixel wide) are left out.
    ShadowScene scene = redGlass();
    scene.aboveGroup = "DrawStyle { style LINES }";
    scene.floorNodes = "DrawStyle { style FILLED }";
    const ExpectedImage plain = pictureOf(withoutShadow(redGlass()), true);
    cases.push_back({"DrawStyleLinesAbove", scene, [plain](int px, int py) {
                       const double x = floorX(px), y = floorY(py);
                       const double extent = std::max(std::abs(x), std::abs(y));
                       if (std::abs(extent - kRedGlass.halfSize) < 3.0 * kPixel)
                         return Expectation{};
                       return plain(px, py);
                     }});
  }
  {  // BASE_COLOR above: the floor is its diffuse white, unlit and so unshadowed.
    ShadowScene scene = redGlass();
    scene.aboveGroup = "LightModel { model BASE_COLOR }";
    cases.push_back({"LightModelBaseColorAbove", scene, [](int px, int py) {
                       const double x = floorX(px), y = floorY(py);
                       Expectation e;
                       if (outsideFloor(x, y, e)) return e;
                       if (std::max(std::abs(x), std::abs(y)) < kRedGlass.halfSize + kMargin)
                         return e;
                       return grey(255.0);
                     }});
  }
  {  // An unlit glass above a lit floor still casts: a shadow is light passing the glass.
    ShadowScene scene = redGlass();
    scene.aboveGroup = "LightModel { model BASE_COLOR }";
    scene.floorNodes = "LightModel { model PHONG }";
    cases.push_back({"LightModelBaseColorAboveLitFloor", scene, pictureOf(redGlass())});
  }
  {  // Known vertex order, unknown shape type: two-sided lighting. The floor's normal points
     // down, away from the light; its vertices run counter-clockwise seen from above, which
     // the clockwise order above makes its back: two-sided lighting turns the normal up, and
     // the floor takes the light (and the shadow) as if its normal were up. Without the hints
     // it would be dark.
    ShadowScene scene = redGlass();
    scene.aboveGroup = "ShapeHints { vertexOrdering CLOCKWISE shapeType UNKNOWN_SHAPE_TYPE }";
    scene.floorNodes = "Normal { vector 0 0 -1 } NormalBinding { value OVERALL }";
    cases.push_back({"ShapeHintsAbove", scene, pictureOf(redGlass())});
  }
}

std::vector<InheritedCase> inheritedStateCases() {
  std::vector<InheritedCase> cases;
  addMaterialCases(cases);
  addGeometryCases(cases);
  addStyleCases(cases);
  return cases;
}

std::string inheritedCaseName(const ::testing::TestParamInfo<InheritedCase>& info) {
  return info.param.name;
}

}  // namespace ivshadow::test
