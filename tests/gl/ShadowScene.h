#pragma once

#include "image/Image.h"
#include "tests/support/TestSupport.h"

#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

class SoNode;
class SoSeparator;

namespace ivshadow::test {

// A filter held above the floor of ShadowScene: a square of half size `halfSize` at height
// `height`, centred over the light's foot.
struct Filter {
  double halfSize = 0.3;
  double height = 0.5;
  std::array<double, 3> diffuse{1.0, 0.0, 0.0};
  double transparency = 0.5;
  std::string nodes;        // Inventor nodes placed before the filter's material (a texture)
  std::string faceNodes;    // Inventor nodes placed after it, just before the face
  bool ownMaterial = true;  // false: no Material of its own (it takes the one in force)
};

enum class ColourModel { Monochrome, Saturate, Power };

// The filters most tests use: red glass half-way to the light, green glass nearer the floor.
inline const Filter kRedGlass{0.3, 0.5, {1.0, 0.0, 0.0}, 0.5, "", ""};
inline const Filter kGreenGlass{0.4, 0.25, {0.0, 1.0, 0.0}, 0.5, "", ""};

// A white, opaque glass with a luminance-alpha 2 x 2 texture (rows bottom-up: opaque
// bottom-left and top-right texels), sampled without filtering (texture quality 0.1).
Filter checkerboardFilter();
// Checks floor points around the seen checkerboard glass whose light passes each quadrant:
// (x, y) on the floor maps to (x, y) / 2 on the glass; lit ones get Lambert's value.
void expectCheckerboardShadow(const Image& image, double tolerance);

// Fraction of light per channel passing a surface of colour c and opacity a (seeds/000):
// eq. 5.1 (1 - a), eq. 5.3 (1 - a) clamp(1 - a + c, 0, 1), eq. 5.2 (1 - a)^(2 - c).
std::array<double, 3> transmittance(const Filter& filter, ColourModel model);

// The scene of iv_scenes/lit_plane.iv (a 2 x 2 white floor at z = 0 seen straight down by an
// orthographic camera, 100 pixels per unit at 240 x 240; a light 1 unit above the floor's
// centre; no ambient, no specular) inside a SoTransparentShadowGroup with a SoDeepShadowLight
// and filters between the light and the floor. `rotationAxis`/`rotationAngle` rotate the
// group's content inside the group and rotate it back outside: the picture stays the same
// while the light looks at the floor through a different cube face (or across seams).
struct ShadowScene {
  static constexpr int kSize = 240;
  std::vector<Filter> filters;
  std::string method = "MAP";  // the lights' method: these scenes test the map unless told
  std::string lightFields;     // extra fields of the DeepShadowLight, e.g. "maxLayers 1"
  std::string floorNodes;      // Inventor nodes placed before the floor's mesh
  std::string aboveGroup;      // Inventor nodes placed just before the group, outside it
  std::string groupNodes;      // Inventor nodes placed in the group after the filters
  // The group's renderer: GL's, since these scenes test the GL path unless told ("": the
  // node's default, AUTO).
  std::string renderer = "RASTER";
  std::string groupFields;  // other fields of the group, e.g. "castingLights DEEP_SHADOW_LIGHTS"
  std::string belowGroup;   // Inventor nodes placed just after the group, outside it
  std::array<double, 3> rotationAxis{0.0, 0.0, 1.0};
  double rotationAngle = 0.0;
  int floorCells = 1;  // quads per side of the floor mesh
  int lightCount = 1;  // deep shadow lights at the same place, intensity 1 / lightCount each
  bool shadowGroupActive = true;
  bool peelFilters = false;  // the filters inside a PeelingSeparator

  std::string text() const;
};

// The analytic picture of a ShadowScene: Lambert 255 / sqrt(1 + r^2) on the floor, times the
// transmittance of each filter whose shadow (similar triangles: half size s / (1 - h)) covers
// the point, counting only the first `maxLayers` surfaces seen from the light. Pixels within
// `edgeMargin` pixels of a shadow or floor edge, and pixels where a filter itself is seen,
// are not checked.
struct ShadowPicture {
  const ShadowScene* scene = nullptr;
  ColourModel model = ColourModel::Saturate;
  int maxLayers = 64;
  double edgeMarginPixels = 2.0;
  bool checkFilters = false;  // true when the filters are invisible (transparency 1)

  Expectation operator()(int px, int py) const;
  // The same at the floor point (x, y), `pixel` floor units a pixel (margins are in pixels).
  Expectation at(double x, double y, double pixel) const;
};

// A scene with the analytic picture it must give: the cases every shadow method (the map, the
// traced rays, the CPU reference) reproduces within one 8-bit step. `expected` is the scene
// the picture is computed from; it differs from `scene` only where a case says so.
struct AnalyticCase {
  std::string name;
  ShadowScene scene;
  ShadowScene expected;
  ColourModel model = ColourModel::Saturate;
  bool checkFilters = false;  // the filters are invisible: check the pixels seen through them
  ShadowPicture picture() const;
};
// Colour models, grey casters, two stacked filters, opaque, clear and per-vertex alpha
// casters, and the content turned so that the light looks across a cube-face seam, into a
// cube corner and through the +z face. None needs more layers than the maps keep by default.
std::vector<AnalyticCase> analyticCases();
// Test names for parameterised tests over analyticCases().
std::string analyticCaseName(const ::testing::TestParamInfo<AnalyticCase>& info);

// Reads Inventor text (after init()); returns the root, referenced. Throws when it does not
// parse.
SoSeparator* readIv(const std::string& text);

// Reads Inventor text and renders it headlessly at size x size; returns the root (referenced)
// through `root` when given so callers can inspect nodes afterwards. (RenderIv.cpp: GL tests
// only.)
Image renderIv(const std::string& text, int size, SoNode** root = nullptr);

// The exact CPU reference of the same text at size x size (ivshadow reference); `floats`
// receives the unrounded RGB when given.
Image referenceIv(const std::string& text, int size, std::vector<float>* floats = nullptr);

}  // namespace ivshadow::test
