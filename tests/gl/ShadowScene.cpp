#include "tests/gl/ShadowScene.h"

#include "ivshadow/IvShadowInit.h"
#include "reference/ReferenceRenderer.h"
#include "scene_input/ViewSetup.h"

#include <Inventor/SbViewportRegion.h>

#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/nodes/SoSeparator.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace ivshadow::test {

std::array<double, 3> transmittance(const Filter& filter, ColourModel model) {
  const double a = 1.0 - filter.transparency;
  std::array<double, 3> t{};
  for (int c = 0; c < 3; ++c) {
    const double colour = filter.diffuse[std::size_t(c)];
    switch (model) {
      case ColourModel::Monochrome:
        t[std::size_t(c)] = 1.0 - a;
        break;
      case ColourModel::Saturate:
        t[std::size_t(c)] = (1.0 - a) * std::clamp(1.0 - a + colour, 0.0, 1.0);
        break;
      case ColourModel::Power:
        t[std::size_t(c)] = std::pow(1.0 - a, 2.0 - colour);
        break;
    }
  }
  return t;
}

std::string ShadowScene::text() const {
  std::ostringstream iv;
  const auto& axis = rotationAxis;
  iv << "#Inventor V2.1 ascii\nSeparator {\n"
     << "  OrthographicCamera { position 0 0 5 nearDistance 1 farDistance 10 height 2.4 }\n"
     << "  Rotation { rotation " << axis[0] << ' ' << axis[1] << ' ' << axis[2] << ' '
     << -rotationAngle << " }\n"
     << "  " << aboveGroup << "\n"
     << "  DEF Group TransparentShadowGroup {\n"
     << "    isActive " << (shadowGroupActive ? "TRUE" : "FALSE")
     << (renderer.empty() ? std::string() : " renderer " + renderer)
     << (groupFields.empty() ? std::string() : " " + groupFields) << "\n"
     << "    Rotation { rotation " << axis[0] << ' ' << axis[1] << ' ' << axis[2] << ' '
     << rotationAngle << " }\n";
  for (int i = 0; i < lightCount; ++i)
    iv << "    DEF Lamp" << (i > 0 ? std::to_string(i) : std::string()) << " DeepShadowLight { "
       << "location 0 0 1 intensity " << 1.0 / lightCount << " method " << method << ' '
       << lightFields << " }\n";
  iv << "    DEF Floor Separator {\n      " << floorNodes << "\n"
     << "      Material { ambientColor 0 0 0 diffuseColor 1 1 1 specularColor 0 0 0 }\n"
     << "      Coordinate3 { point [\n";
  for (int row = 0; row <= floorCells; ++row)
    for (int column = 0; column <= floorCells; ++column)
      iv << "        " << -1.0 + 2.0 * column / floorCells << ' ' << 1.0 - 2.0 * row / floorCells
         << " 0,\n";
  iv << "      ] }\n      QuadMesh { verticesPerRow " << floorCells + 1 << " verticesPerColumn "
     << floorCells + 1 << " }\n    }\n";
  int index = 0;
  if (peelFilters) iv << "    PeelingSeparator {\n";
  for (const Filter& f : filters) {
    const double s = f.halfSize, h = f.height;
    iv << "    DEF Filter" << index++ << " Separator {\n      " << f.nodes << "\n"
       << "      ";
    if (f.ownMaterial)
      iv << "Material { ambientColor 0 0 0 specularColor 0 0 0 diffuseColor " << f.diffuse[0] << ' '
         << f.diffuse[1] << ' ' << f.diffuse[2] << " transparency " << f.transparency << " }";
    iv << "\n      Coordinate3 { point [ " << -s << ' ' << -s << ' ' << h << ", " << s << ' ' << -s
       << ' ' << h << ", " << s << ' ' << s << ' ' << h << ", " << -s << ' ' << s << ' ' << h
       << " ] }\n      " << f.faceNodes << "\n"
       << "      FaceSet { numVertices 4 }\n    }\n";
  }
  if (peelFilters) iv << "    }\n";
  iv << "    " << groupNodes << "\n  }\n";
  if (!belowGroup.empty()) iv << "  " << belowGroup << "\n";
  iv << "}\n";
  return iv.str();
}

Expectation ShadowPicture::operator()(int px, int py) const {
  return at(-1.2 + (px + 0.5) / 100.0, 1.2 - (py + 0.5) / 100.0, 1.0 / 100.0);
}

Expectation ShadowPicture::at(double x, double y, double pixel) const {
  const double margin = edgeMarginPixels * pixel;
  const double extent = std::max(std::abs(x), std::abs(y));
  Expectation e;
  if (extent >= 1.0 + margin) {
    e.checked = true;  // background, black
    return e;
  }
  if (extent > 1.0 - margin) return e;
  // Filters nearest to the light come first along the light's ray.
  std::vector<const Filter*> order;
  for (const Filter& f : scene->filters) order.push_back(&f);
  std::sort(order.begin(), order.end(),
            [](const Filter* a, const Filter* b) { return a->height > b->height; });
  std::array<double, 3> light{1.0, 1.0, 1.0};
  int layers = 0;
  for (const Filter* f : order) {
    if (!checkFilters && extent < f->halfSize + margin) return e;  // the filter is in view
    const double footprint = f->halfSize / (1.0 - f->height);
    if (std::abs(extent - footprint) < margin) return e;
    if (extent < footprint && f->transparency < 1.0 && layers++ < maxLayers) {
      const std::array<double, 3> t = transmittance(*f, model);
      for (int c = 0; c < 3; ++c) light[std::size_t(c)] *= t[std::size_t(c)];
    }
  }
  const double lambert = 255.0 / std::sqrt(1.0 + x * x + y * y);
  e.checked = true;
  for (int c = 0; c < 3; ++c) e.rgb[std::size_t(c)] = lambert * light[std::size_t(c)];
  return e;
}

ShadowPicture AnalyticCase::picture() const {
  ShadowPicture picture{&expected, model};
  picture.checkFilters = checkFilters;
  return picture;
}

std::vector<AnalyticCase> analyticCases() {
  std::vector<AnalyticCase> cases;
  const auto add = [&cases](const std::string& name, const ShadowScene& scene, ColourModel model,
                            bool checkFilters = false) {
    cases.push_back(AnalyticCase{name, scene, scene, model, checkFilters});
  };
  ShadowScene red;
  red.filters = {kRedGlass};
  add("RedGlassBySaturateModel", red, ColourModel::Saturate);

  // Opacity and colour near 0.4, where eq. 5.2 and 5.3 differ most (seeds/000): there
  // SATURATE passes 0.6 of the light in the 0.4 channels and POWER 0.6^1.6 = 0.44.
  ShadowScene power;
  power.filters = {Filter{0.3, 0.5, {0.4, 0.4, 1.0}, 0.6, "", ""}};
  power.lightFields = "colorModel POWER";
  add("PowerColourModel", power, ColourModel::Power);

  ShadowScene mono = red;
  mono.lightFields = "shadowColor MONOCHROME";
  add("MonochromeIgnoresTheColour", mono, ColourModel::Monochrome);

  ShadowScene grey;
  Filter greyGlass = kRedGlass;
  greyGlass.diffuse = {0.5, 0.5, 0.5};
  grey.filters = {greyGlass};
  add("GreyCastersInAutoModeAreMonochrome", grey, ColourModel::Monochrome);

  ShadowScene stacked;
  stacked.filters = {kRedGlass, kGreenGlass};
  add("StackedFiltersMultiply", stacked, ColourModel::Saturate);
  // Two filters in one plane (a cone's base lying on a cylinder's top): both filter the light
  // where they overlap. The map's layers used to lose one of two surfaces at exactly one
  // distance (the depth test's tie), in texels scattered by rounding: streaks.
  ShadowScene coincident;
  Filter green = kGreenGlass;
  green.height = kRedGlass.height;
  coincident.filters = {kRedGlass, green};
  add("CoincidentFiltersBothFilter", coincident, ColourModel::Saturate);

  ShadowScene opaque;
  Filter blocker = kRedGlass;
  blocker.transparency = 0.0;
  opaque.filters = {blocker};
  add("OpaqueCasterBlocksAllDirectLight", opaque, ColourModel::Saturate);

  ShadowScene clear;
  Filter nothing = kRedGlass;
  nothing.transparency = 1.0;
  clear.filters = {nothing};
  // Alpha 0 blends to nothing: the floor is seen through the filter too.
  add("FullyTransparentCasterCastsNothing", clear, ColourModel::Saturate, true);

  // Packed per-vertex colours replace the material's diffuse colour and transparency: red
  // with alpha 0x80, i.e. transparency 1 - 128/255.
  ShadowScene packed;
  Filter vertexAlpha = kRedGlass;
  vertexAlpha.faceNodes =
      "MaterialBinding { value PER_VERTEX } "
      "PackedColor { orderedRGBA [ 0xFF000080, 0xFF000080, 0xFF000080, 0xFF000080 ] }";
  packed.filters = {vertexAlpha};
  AnalyticCase perVertex{"PerVertexColourAlphaSetsOpacity", packed, packed, ColourModel::Saturate,
                         false};
  perVertex.expected.filters[0].transparency = 1.0 - 128.0 / 255.0;
  cases.push_back(perVertex);

  // The group's content turned inside it and back outside: the same picture, with the light
  // looking across a seam of two cube faces, into a cube corner, and through +z.
  const double halfPi = std::acos(0.0);
  const std::pair<const char*, std::pair<std::array<double, 3>, double>> turns[] = {
      {"AcrossACubeFaceSeam", {{0, 1, 0}, -halfPi / 2}},
      {"IntoACubeCorner", {{1, -1, 0}, std::acos(1.0 / std::sqrt(3.0))}},
      {"ThroughThePlusZFace", {{1, 0, 0}, 2 * halfPi}}};
  for (const auto& [name, turn] : turns) {
    ShadowScene turned = stacked;
    turned.rotationAxis = turn.first;
    turned.rotationAngle = turn.second;
    add(name, turned, ColourModel::Saturate);
  }
  return cases;
}

std::string analyticCaseName(const ::testing::TestParamInfo<AnalyticCase>& info) {
  return info.param.name;
}

Filter checkerboardFilter() {
  Filter checker = kRedGlass;
  checker.diffuse = {1.0, 1.0, 1.0};
  checker.transparency = 0.0;
  checker.nodes =
      "Complexity { textureQuality 0.1 } "
      "Texture2 { image 2 2 2 0xFFFF 0xFF00 0xFF00 0xFFFF model MODULATE }";
  return checker;
}

void expectCheckerboardShadow(const Image& image, double tolerance) {
  struct Probe {
    double x, y;
    bool lit;
  };
  for (const Probe& p :
       {Probe{0.45, 0.15, false}, Probe{-0.45, -0.15, false}, Probe{0.45, -0.15, true},
        Probe{-0.45, 0.15, true}, Probe{0.15, 0.45, false}, Probe{-0.15, 0.45, true}}) {
    const int px = int(std::floor((p.x + 1.2) * 100.0));
    const int py = int(std::floor((1.2 - p.y) * 100.0));
    const double x = -1.2 + (px + 0.5) / 100.0, y = 1.2 - (py + 0.5) / 100.0;
    const double expected = p.lit ? 255.0 / std::sqrt(1.0 + x * x + y * y) : 0.0;
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(image.pixel(px, py)[c], expected, tolerance)
          << "floor point (" << p.x << ", " << p.y << ") channel " << c;
  }
}

SoSeparator* readIv(const std::string& text) {
  init();
  SoInput input;
  input.setBuffer(text.data(), text.size());
  SoSeparator* root = SoDB::readAll(&input);
  if (root == nullptr) throw std::runtime_error("the test scene does not parse:\n" + text);
  root->ref();
  return root;
}

Image referenceIv(const std::string& text, int size, std::vector<float>* floats) {
  SoSeparator* root = readIv(text);
  const ViewSetup view = ViewSetup::prepare(root, SbViewportRegion(short(size), short(size)));
  ReferenceOptions options;
  options.width = size;
  options.height = size;
  std::optional<ReferenceResult> result = renderReference(view.root.get(), options);
  root->unref();
  if (!result) throw std::runtime_error("the reference render was cancelled");
  if (floats != nullptr) *floats = result->image.rgb;
  return result->image.toImage();
}

}  // namespace ivshadow::test
