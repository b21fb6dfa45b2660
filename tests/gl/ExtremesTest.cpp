// Numerical behaviour at the extremes (issue: ground truth and the trade). Each case states
// what it expects: the analytic picture where one exists, and the exact CPU reference beside
// the GL path. Whatever the input, no pixel may be NaN or infinite, and more surfaces between
// a point and the light never let more light through.
#include "ivshadow/DeepShadowStatistics.h"
#include "tests/gl/ShadowScene.h"

#include <Inventor/nodes/SoNode.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <sstream>

namespace ivshadow::test {
namespace {

// One 8-bit step, as in DeepShadowTest: per-pixel float shading rounded once.
constexpr double kTolerance = 1.0;

// The GL path and the exact reference of `text` against one expectation; every reference
// pixel finite.
void expectBoth(const std::string& text, const ExpectedImage& expected) {
  const std::string gl =
      compareWithExpectation(renderIv(text, ShadowScene::kSize), expected, kTolerance);
  EXPECT_TRUE(gl.empty()) << "GL: " << gl;
  std::vector<float> floats;
  const std::string exact =
      compareWithExpectation(referenceIv(text, ShadowScene::kSize, &floats), expected, kTolerance);
  EXPECT_TRUE(exact.empty()) << "reference: " << exact;
  for (float v : floats) ASSERT_TRUE(std::isfinite(v)) << "a reference pixel is not finite";
}

void expectBoth(const ShadowScene& scene, const ExpectedImage& expected, const std::string& what) {
  SCOPED_TRACE(what);
  expectBoth(scene.text(), expected);
}

// The floor of ShadowScene lit through one uniform tint everywhere (Lambert x tint), the
// background black; not checked: the floor's edge and what `hidden` says is covered.
ExpectedImage tintedFloor(std::array<double, 3> tint, std::function<bool(double, double)> hidden) {
  return [tint, hidden](int x, int y) {
    Expectation e;
    const double px = -1.2 + (x + 0.5) / 100.0, py = 1.2 - (y + 0.5) / 100.0;
    const double extent = std::max(std::abs(px), std::abs(py));
    if (extent >= 1.02) {
      e.checked = true;
      return e;
    }
    if (extent > 0.98 || hidden(px, py)) return e;
    const double lambert = 255.0 / std::sqrt(1.0 + px * px + py * py);
    e.checked = true;
    for (std::size_t c = 0; c < 3; ++c) e.rgb[c] = lambert * tint[c];
    return e;
  };
}

TEST(Extremes, OpacityAndColourChannelsAtTheirLimitsInBothColourModels) {
  // Coin sends colours as 8 bits: opacity 1e-6 reaches GL as 0 and 1 - 1e-6 as 1; the
  // analytic values of the true opacities differ from those by less than a step.
  for (const double opacity : {0.0, 1e-6, 0.5, 1.0 - 1e-6, 1.0})
    for (const std::array<double, 3>& colour :
         {std::array<double, 3>{0, 0, 0}, std::array<double, 3>{1, 1, 1},
          std::array<double, 3>{1, 0, 1}})
      for (const ColourModel model : {ColourModel::Saturate, ColourModel::Power}) {
        ShadowScene scene;
        Filter filter{0.3, 0.5, colour, 1.0 - opacity, ""};
        scene.filters = {filter};
        scene.lightFields = model == ColourModel::Power ? "shadowColor COLORED colorModel POWER"
                                                        : "shadowColor COLORED";
        ShadowPicture picture{&scene, model};
        picture.checkFilters = opacity < 0.5 / 255.0;  // an invisible filter shows the floor
        std::ostringstream what;
        what << "opacity " << opacity << " colour " << colour[0] << ' ' << colour[1] << ' '
             << colour[2] << (model == ColourModel::Power ? " POWER" : " SATURATE");
        expectBoth(scene, picture, what.str());
      }
}

// 64 filters whose shadows coincide: halfSize (1 - h) / 2 puts every footprint at 0.5.
ShadowScene stackOf64(const std::string& lightFields) {
  ShadowScene scene;
  for (int i = 0; i < 64; ++i) {
    const double h = 0.2 + 0.6 * i / 63.0;
    scene.filters.push_back(Filter{(1.0 - h) / 2.0, h, {0.5, 0.5, 0.5}, 0.95, ""});
  }
  scene.lightFields = lightFields;
  return scene;
}

TEST(Extremes, SixtyFourStackedFiltersInHalfAndFloat) {
  // 0.95^64 = 0.0375 of the light: about 9 steps, well above half precision's resolution
  // (64 roundings of 2^-11 each move it by under 0.2 step).
  for (const char* precision : {"FLOAT", "HALF"}) {
    ShadowScene scene =
        stackOf64(std::string("resolution 128 maxLayers 64 precision ") + precision);
    ShadowPicture picture{&scene, ColourModel::Monochrome};
    expectBoth(scene, picture, precision);
  }
}

TEST(Extremes, OneLayerTruncatedKeepsOnlyTheNearestOfSixtyFour) {
  ShadowScene scene = stackOf64("resolution 128 maxLayers 1 layerOverflow TRUNCATE");
  ShadowPicture picture{&scene, ColourModel::Monochrome};
  picture.maxLayers = 1;
  const std::string gl =
      compareWithExpectation(renderIv(scene.text(), ShadowScene::kSize), picture, kTolerance);
  EXPECT_TRUE(gl.empty()) << gl;
}

// Merged (the default), the one layer holds all sixty-four: the floor behind them gets
// 0.95^64 as with 64 layers, in FLOAT and HALF (one product, one rounding to half).
TEST(Extremes, OneLayerMergedHoldsAllSixtyFour) {
  for (const char* precision : {"FLOAT", "HALF"}) {
    ShadowScene scene = stackOf64(std::string("resolution 128 maxLayers 1 precision ") + precision);
    ShadowPicture picture{&scene, ColourModel::Monochrome};
    const std::string gl =
        compareWithExpectation(renderIv(scene.text(), ShadowScene::kSize), picture, kTolerance);
    EXPECT_TRUE(gl.empty()) << precision << ": " << gl;
  }
}

TEST(Extremes, MoreSurfacesNeverLetMoreLightThrough) {
  // Visibility never increases with depth: each added filter can only darken the floor.
  Image previous;
  for (int count = 0; count <= 6; ++count) {
    ShadowScene scene;
    for (int i = 0; i < count; ++i) {
      const double h = 0.2 + 0.1 * i;
      scene.filters.push_back(Filter{(1.0 - h) / 2.0, h, {1.0, 0.3 * i, 0.2}, 0.7, ""});
    }
    scene.lightFields = "maxLayers 8";
    const Image image = renderIv(scene.text(), ShadowScene::kSize);
    if (!previous.empty()) {
      for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
          const double px = -1.2 + (x + 0.5) / 100.0, py = 1.2 - (y + 0.5) / 100.0;
          const double extent = std::max(std::abs(px), std::abs(py));
          if (extent < 0.45 || extent > 0.98) continue;  // the filters themselves, floor edge
          for (int c = 0; c < 3; ++c)
            ASSERT_LE(image.pixel(x, y)[c], previous.pixel(x, y)[c] + kTolerance)
                << count << " filters, pixel " << x << "," << y << " channel " << c;
        }
    }
    previous = image;
  }
}

// The red-glass scene written at scale s about the light's foot: floor, light, filter and
// orthographic camera all scaled, so the picture is the unscaled one (the point light has no
// distance attenuation).
std::string scaledScene(double s, const char* method) {
  std::ostringstream iv;
  iv << "#Inventor V2.1 ascii\nSeparator {\n"
     << "  OrthographicCamera { position 0 0 " << 5 * s << " nearDistance " << s << " farDistance "
     << 10 * s << " height " << 2.4 * s << " }\n"
     << "  TransparentShadowGroup { renderer RASTER\n    DeepShadowLight { location 0 0 " << s
     << " method " << method << " }\n"
     << "    Separator { Material { ambientColor 0 0 0 diffuseColor 1 1 1 specularColor 0 0 0 }\n"
     << "      Coordinate3 { point [ " << -s << ' ' << s << " 0, " << s << ' ' << s << " 0, " << -s
     << ' ' << -s << " 0, " << s << ' ' << -s << " 0 ] }\n"
     << "      QuadMesh { verticesPerRow 2 verticesPerColumn 2 } }\n"
     << "    Separator { Material { ambientColor 0 0 0 specularColor 0 0 0 diffuseColor 1 0 0 "
        "transparency 0.5 }\n"
     << "      Coordinate3 { point [ " << -0.3 * s << ' ' << -0.3 * s << ' ' << 0.5 * s << ", "
     << 0.3 * s << ' ' << -0.3 * s << ' ' << 0.5 * s << ", " << 0.3 * s << ' ' << 0.3 * s << ' '
     << 0.5 * s << ", " << -0.3 * s << ' ' << 0.3 * s << ' ' << 0.5 * s << " ] }\n"
     << "      FaceSet { numVertices 4 } }\n  }\n}\n";
  return iv.str();
}

TEST(Extremes, SceneScaleFromOneThousandthToTenThousand) {
  ShadowScene unit;
  unit.filters = {Filter{0.3, 0.5, {1.0, 0.0, 0.0}, 0.5, ""}};
  const ShadowPicture picture{&unit, ColourModel::Saturate};
  for (const double s : {1e-3, 1e4})
    for (const char* method : {"MAP", "RAYS"}) {
      SCOPED_TRACE("scale " + std::to_string(s) + " " + method);
      const std::string text = scaledScene(s, method);
      expectBoth(text, picture);
    }
}

TEST(Extremes, NearToFarRatioOfOneMillion) {
  // Reversed floating-point depth keeps relative precision over the whole range.
  ShadowScene scene;
  scene.filters = {Filter{0.3, 0.5, {1.0, 0.0, 0.0}, 0.5, ""}};
  scene.lightFields = "nearRadius 1e-5 farRadius 10";
  expectBoth(scene, ShadowPicture{&scene, ColourModel::Saturate}, "near 1e-5, far 10");
}

TEST(Extremes, LightATenThousandthFromACaster) {
  // A filter 1e-4 below the light, 3e-5 in half size: its shadow has half size 0.3 on the
  // floor, as a 0.3 filter half-way down would; the filter itself is far below a pixel.
  ShadowScene scene;
  scene.filters = {Filter{0.3e-4, 1.0 - 1e-4, {1.0, 0.0, 0.0}, 0.5, ""}};
  ShadowScene expected;
  expected.filters = {Filter{0.15, 0.5, {1.0, 0.0, 0.0}, 0.5, ""}};
  ShadowPicture picture{&expected, ColourModel::Saturate};
  picture.checkFilters = true;  // nothing of the tiny filter is seen from the camera
  const ExpectedImage shadowOnly = [&](int x, int y) {
    Expectation e = picture(x, y);
    const double px = -1.2 + (x + 0.5) / 100.0, py = 1.2 - (y + 0.5) / 100.0;
    if (std::max(std::abs(px), std::abs(py)) < 0.03) e.checked = false;  // under the dot
    return e;
  };
  expectBoth(scene, shadowOnly, "light 1e-4 from the filter");
}

TEST(Extremes, LightInsideAClosedTransparentSphere) {
  // Every ray from the light leaves the sphere through exactly one surface: the whole floor
  // gets one red glass's transmittance, (1 - a) clamp(1 - a + c) = 0.5 x (1, 0.5, 0.5).
  ShadowScene scene;
  scene.lightFields = "resolution 256";
  std::string text = scene.text();
  const std::string sphere =
      "    Separator { Translation { translation 0 0 1 } Material { ambientColor 0 0 0 "
      "specularColor 0 0 0 diffuseColor 1 0 0 transparency 0.5 } Complexity { value 0.6 } "
      "Sphere { radius 0.2 } }\n";
  text.insert(text.rfind("  }\n}"), sphere);
  // The sphere itself is seen within 0.24 of the centre.
  const ExpectedImage expected = tintedFloor(
      {0.5, 0.25, 0.25}, [](double px, double py) { return std::hypot(px, py) < 0.24; });

  SCOPED_TRACE("light inside a sphere");
  expectBoth(text, expected);
}

TEST(Extremes, DegenerateAndZeroAreaTrianglesChangeNothing) {
  // Three collinear points and a triangle with a repeated vertex inside the filter's face
  // set: they cover no area, so the picture is the plain red glass's.
  ShadowScene scene;
  Filter glass{0.3, 0.5, {1.0, 0.0, 0.0}, 0.5, ""};
  glass.faceNodes =
      "Coordinate3 { point [ -0.3 -0.3 0.5, 0.3 -0.3 0.5, 0.3 0.3 0.5, -0.3 0.3 0.5, "
      "-0.2 -0.2 0.5, 0 0 0.5, 0.2 0.2 0.5 ] } IndexedFaceSet { coordIndex [ 0, 1, 2, 3, -1, "
      "4, 5, 6, -1, 1, 1, 2, -1 ] }";
  scene.filters = {glass};
  // The filter's own FaceSet follows the IndexedFaceSet; give it nothing to draw.
  std::string text = scene.text();
  const std::string face = "FaceSet { numVertices 4 }";
  text.replace(text.find(face), face.size(), "");
  ShadowScene expected;
  expected.filters = {Filter{0.3, 0.5, {1.0, 0.0, 0.0}, 0.5, ""}};
  const ShadowPicture picture{&expected, ColourModel::Saturate};
  expectBoth(text, picture);
}

TEST(Extremes, CoincidentCoplanarFilters) {
  // Two identical panes at one place are two surfaces: the reference multiplies both, and so
  // does the map, whose peel orders surfaces at one distance by their triangles' numbers
  // (dsm_build.frag). It used to keep one of them, as depth peeling does.
  ShadowScene twice;
  const Filter red{0.3, 0.5, {1.0, 0.0, 0.0}, 0.5, ""};
  twice.filters = {red, red};
  // The camera view blends both panes; only the shadow is compared.
  const auto shadowOnly = [](const ShadowPicture& picture) {
    return [picture](int x, int y) {
      Expectation e = picture(x, y);
      const double px = -1.2 + (x + 0.5) / 100.0, py = 1.2 - (y + 0.5) / 100.0;
      if (std::max(std::abs(px), std::abs(py)) < 0.32) e.checked = false;
      return e;
    };
  };
  ShadowPicture both{&twice, ColourModel::Saturate};
  both.checkFilters = true;
  const std::string exact = compareWithExpectation(referenceIv(twice.text(), ShadowScene::kSize),
                                                   shadowOnly(both), kTolerance);
  EXPECT_TRUE(exact.empty()) << "reference: " << exact;
  const std::string gl = compareWithExpectation(renderIv(twice.text(), ShadowScene::kSize),
                                                shadowOnly(both), kTolerance);
  EXPECT_TRUE(gl.empty()) << "GL: " << gl;
}

TEST(Extremes, ResolutionOneGivesTheCentreTexelToTheWholeFace) {
  // One texel per face: the -z face's only texel looks along the light's axis through the
  // glass, so every floor point seen through that face (all of it) gets the glass's colour.
  ShadowScene scene;
  scene.filters = {Filter{0.3, 0.5, {1.0, 0.0, 0.0}, 0.5, ""}};
  scene.lightFields = "resolution 1 bias 0";
  // (1 - a) clamp(1 - a + c) for red glass of opacity 0.5; the glass is seen within 0.32.
  const ExpectedImage expected = tintedFloor({0.5, 0.25, 0.25}, [](double px, double py) {
    return std::max(std::abs(px), std::abs(py)) < 0.32;
  });

  const std::string gl =
      compareWithExpectation(renderIv(scene.text(), ShadowScene::kSize), expected, kTolerance);
  EXPECT_TRUE(gl.empty()) << "GL: " << gl;
}

}  // namespace
}  // namespace ivshadow::test
