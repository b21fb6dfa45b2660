#include "gl/GlCapabilities.h"
#include "ivshadow/IvShadowInit.h"
#include "ivshadow/PeelStatistics.h"
#include "ivshadow/SoPeelingSeparator.h"
#include "scene_input/CoinMessageCapture.h"
#include "tests/gl/CheckedRenderer.h"
#include "tests/gl/PeelReference.h"
#include "tests/gl/ShadowScene.h"

#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/SoPath.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoMaterial.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoTexture2.h>
#include <Inventor/nodes/SoTranslation.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <sstream>

namespace ivshadow::test {
namespace {

constexpr int kSize = 160;
constexpr double kViewHeight = 2.4;

// A surface given as explicit triangles (so Coin draws exactly the triangles SoCallbackAction
// reports) from a (u, v) -> point parametrisation over an n x m grid.
std::string triangleMesh(int n, int m,
                         const std::function<std::array<double, 3>(double, double)>& at) {
  std::ostringstream iv;
  iv << "Coordinate3 { point [\n";
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i <= n; ++i) {
      const auto p = at(double(i) / n, double(j) / m);
      iv << p[0] << ' ' << p[1] << ' ' << p[2] << ",\n";
    }
  iv << "] }\nIndexedFaceSet { coordIndex [\n";
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      iv << a << ',' << b << ',' << d << ",-1," << a << ',' << d << ',' << c << ",-1,\n";
    }
  iv << "] }\n";
  return iv.str();
}

std::string sceneText(const std::string& peelFields, const std::string& content) {
  std::ostringstream iv;
  iv << "#Inventor V2.1 ascii\nSeparator {\n"
     << "  OrthographicCamera { position 0 0 5 nearDistance 1 farDistance 10 height " << kViewHeight
     << " }\n"
     << "  LightModel { model BASE_COLOR }\n"
     << "  ShapeHints { vertexOrdering UNKNOWN_ORDERING shapeType UNKNOWN_SHAPE_TYPE }\n"
     << "  DEF Peel PeelingSeparator { " << peelFields << "\n"
     << "    BaseColor { rgb 0.5 0.5 0.5 }\n"
     << "    Coordinate3 { point [ -1 -1 -1, 1 -1 -1, 1 1 -1, -1 1 -1 ] }\n"
     << "    FaceSet { numVertices 4 }\n"
     << content << "  }\n}\n";
  return iv.str();
}

// Three coloured planes through the origin, tilted different ways so that each cuts the
// others, a glass sphere through two of them, a quad whose alpha varies per vertex and an
// alpha-textured sheet.
std::string planesAndSphere() {
  const double pi = std::acos(-1.0);
  std::ostringstream iv;
  struct Plane {
    const char* colour;
    double transparency, tiltX, tiltY;
  };
  for (const Plane& p : {Plane{"1 0 0", 0.5, 0.6, 0.0}, Plane{"0 1 0", 0.6, 0.0, 0.7},
                         Plane{"0 0 1", 0.4, -0.5, -0.4}}) {
    iv << "Separator { Material { diffuseColor " << p.colour << " transparency " << p.transparency
       << " }\n"
       << triangleMesh(1, 1,
                       [&](double u, double v) -> std::array<double, 3> {
                         const double x = -0.8 + 1.6 * u, y = -0.8 + 1.6 * v;
                         return {x, y, x * std::tan(p.tiltY) + y * std::tan(p.tiltX)};
                       })
       << "}\n";
  }
  iv << "Separator { Material { diffuseColor 1 1 0 transparency 0.5 }\n"
     << triangleMesh(24, 12,
                     [&](double u, double v) -> std::array<double, 3> {
                       const double phi = 2 * pi * u, theta = pi * v, r = 0.45;
                       return {0.3 + r * std::sin(theta) * std::cos(phi),
                               0.2 + r * std::sin(theta) * std::sin(phi), r * std::cos(theta)};
                     })
     << "}\n"
     << "Separator { MaterialBinding { value PER_VERTEX_INDEXED }\n"
     << "  PackedColor { orderedRGBA [ 0xFF00FF20, 0xFF00FFE0, 0x00FFFF90, 0xFFFFFF60 ] }\n"
     << "  Coordinate3 { point [ -0.9 -0.9 0.3, -0.2 -0.9 -0.2, -0.2 -0.2 0.3, -0.9 -0.2 -0.2 ] }\n"
     << "  IndexedFaceSet { coordIndex [ 0, 1, 2, -1, 0, 2, 3, -1 ] }\n}\n"
     // An alpha-textured sheet (2 x 2 texels: opaque, clear, half, quarter) cutting the others.
     << "Separator { Complexity { textureQuality 0.1 }\n"
     << "  Texture2 { image 2 2 4 0xFF8000FF 0x00FF0000 0x2080FF80 0xFFFFFF40 }\n"
     << "  Material { diffuseColor 1 1 1 }\n"
     << "  Coordinate3 { point [ 0.1 -0.9 -0.4, 0.9 -0.9 0.4, 0.9 -0.1 0.4, 0.1 -0.1 -0.4 ] }\n"
     << "  TextureCoordinate2 { point [ 0 0, 1 0, 1 1, 0 1 ] }\n"
     << "  IndexedFaceSet { coordIndex [ 0, 1, 2, -1, 0, 2, 3, -1 ]"
     << " textureCoordIndex [ 0, 1, 2, -1, 0, 2, 3, -1 ] }\n}\n";
  return iv.str();
}

// A torus tipped towards the camera: it overlaps itself, up to four surfaces deep.
std::string tippedTorus() {
  const double pi = std::acos(-1.0);
  std::ostringstream iv;
  iv << "Separator { Material { diffuseColor 0 0.8 0.9 transparency 0.6 }\n"
     << triangleMesh(48, 16,
                     [&](double u, double v) -> std::array<double, 3> {
                       const double a = 2 * pi * u, b = 2 * pi * v, big = 0.6, small = 0.22;
                       const double x = (big + small * std::cos(b)) * std::cos(a);
                       const double y = (big + small * std::cos(b)) * std::sin(a);
                       const double z = small * std::sin(b);
                       const double tilt = 1.1;  // about x
                       return {x, y * std::cos(tilt) - z * std::sin(tilt),
                               y * std::sin(tilt) + z * std::cos(tilt)};
                     })
     << "}\n";
  return iv.str();
}

struct Rendered {
  Image image;
  PeelStatistics stats;
};

Rendered render(const std::string& text,
                SoGLRenderAction::TransparencyType type = SoGLRenderAction::BLEND) {
  init();
  std::string error;
  auto renderer = CheckedRenderer::create(kSize, kSize, error);
  if (!renderer) throw std::runtime_error(error);
  renderer->action().setTransparencyType(type);
  SoSeparator* root = readIv(text);
  renderer->render(root);
  Rendered out{renderer->read(), collectPeelStatistics(root)};
  renderer.reset();
  root->unref();
  return out;
}

PeelReference reference(const std::string& text) {
  SoSeparator* root = readIv(text);
  PeelReference result(root, kViewHeight, kSize);
  root->unref();
  return result;
}

// The largest channel difference between `actual` and the reference over the pixels the
// reference checks; writes actual/expected/diff PNGs to outputDir() when above `tolerance`.
// Sets `checked` to the number of pixels compared.
double compareWithReference(const Image& actual, const PeelReference& reference,
                            PeelReference::Keep keep, double tolerance, int& checked) {
  std::vector<std::optional<std::array<double, 3>>> expected;
  for (int y = 0; y < actual.height(); ++y)
    for (int x = 0; x < actual.width(); ++x) expected.push_back(reference.pixel(x, y, keep));
  checked = 0;
  double worst = 0.0;
  for (const auto& e : expected) checked += e ? 1 : 0;
  const std::string failure = compareWithExpectation(
      actual,
      [&](int x, int y) {
        Expectation result;
        const auto& e = expected[std::size_t(y * actual.width() + x)];
        if (!e) return result;
        result.checked = true;
        result.rgb = *e;
        for (int k = 0; k < 3; ++k)
          worst = std::max(worst, std::abs(actual.pixel(x, y)[k] - (*e)[std::size_t(k)]));
        return result;
      },
      tolerance);
  (void)failure;
  return worst;
}

// Layers are composited in float and rounded once; the framebuffer's 8 bits and the blend
// onto it add one rounding more: 2/255 bounds it (the bound).
constexpr double kTolerance = 2.0;

void expectMatchesReference(const std::string& content, const std::string& peelFields,
                            PeelReference::Keep keep = {}) {
  const std::string text = sceneText(peelFields, content);
  const Rendered rendered = render(text);
  int checked = 0;
  const double worst =
      compareWithReference(rendered.image, reference(text), keep, kTolerance, checked);
  EXPECT_LE(worst, kTolerance) << "images in " << outputDir();
  EXPECT_GT(checked, kSize * kSize * 9 / 10) << "most pixels must be checked";
}

TEST(Peeling, InterpenetratingPlanesAndSphereDual) {
  expectMatchesReference(planesAndSphere(), "method DUAL");
}

TEST(Peeling, InterpenetratingPlanesAndSphereFrontToBack) {
  expectMatchesReference(planesAndSphere(), "method FRONT_TO_BACK");
}

TEST(Peeling, SelfOverlappingTorus) {
  const std::string text = sceneText("", tippedTorus());
  EXPECT_GE(reference(text).depthComplexity(), 4) << "the torus must overlap itself";
  expectMatchesReference(tippedTorus(), "method DUAL");
  expectMatchesReference(tippedTorus(), "method FRONT_TO_BACK");
}

TEST(Peeling, FragmentListsMatchTheReferenceInOnePass) {
  for (const std::string& content : {planesAndSphere(), tippedTorus()}) {
    expectMatchesReference(content, "method FRAGMENT_LISTS");
    const Rendered listed = render(sceneText("method FRAGMENT_LISTS", content));
    // One pass into the lists, or two when the first found the overflow (a quarter fragment a
    // pixel beyond its four own slots, to begin with) too small; no peel pass.
    EXPECT_GE(listed.stats.listPasses, 1);
    EXPECT_LE(listed.stats.listPasses, 2);
    EXPECT_EQ(listed.stats.passes, listed.stats.listPasses);
    EXPECT_GT(listed.stats.listFragments, 0);
  }
}

// Six full-view transparent sheets: 6 fragments a pixel, four in the pixel's own slots and two
// in the overflow, eight times the overflow's first size. The first frame stores what fits,
// finds the overflow short, grows it and draws again; the next frame needs one pass. Both
// pictures are the reference's.
TEST(Peeling, FragmentListsGrowOnceForABusierView) {
  std::ostringstream sheets;
  for (int i = 0; i < 6; ++i)
    sheets << "Separator { Material { diffuseColor " << (i % 2) << " " << (i % 3 == 0 ? 1 : 0)
           << " 0.5 transparency 0.7 }\n"
           << "Coordinate3 { point [ -2 -2 " << (-0.8 + 0.3 * i) << ", 2 -2 " << (-0.8 + 0.3 * i)
           << ", 2 2 " << (-0.8 + 0.3 * i) << ", -2 2 " << (-0.8 + 0.3 * i) << " ] }\n"
           << "FaceSet { numVertices 4 } }\n";
  const std::string text = sceneText("method FRAGMENT_LISTS", sheets.str());
  init();
  std::string error;
  auto renderer = CheckedRenderer::create(kSize, kSize, error);
  ASSERT_TRUE(renderer) << error;
  SoSeparator* root = readIv(text);
  renderer->render(root);
  const PeelStatistics first = collectPeelStatistics(root);
  const Image firstImage = renderer->read();
  renderer->render(root);
  const PeelStatistics second = collectPeelStatistics(root);
  const Image secondImage = renderer->read();
  renderer.reset();
  root->unref();
  EXPECT_EQ(first.listPasses, 2);
  EXPECT_EQ(first.listFragments, 6LL * kSize * kSize);
  EXPECT_EQ(second.listPasses, 1);
  const PeelReference exact = reference(text);
  int checked = 0;
  EXPECT_LE(compareWithReference(firstImage, exact, {}, 1.0, checked), 1.0);
  EXPECT_LE(compareWithReference(secondImage, exact, {}, 1.0, checked), 1.0);
  EXPECT_GT(checked, kSize * kSize / 2);
}

// More transparent surfaces in a pixel than a list holds (kMaxFragmentsPerPixel, 32): the
// view is peeled instead, with one warning, and the picture is still exact.
TEST(Peeling, FragmentListsFallBackToPeelingForACrowdedPixel) {
  std::ostringstream sheets;
  for (int i = 0; i < 40; ++i)
    sheets << "Separator { Material { diffuseColor 0.2 0.6 0.4 transparency 0.8 }\n"
           << "Coordinate3 { point [ -0.5 -0.5 " << (-0.9 + 0.04 * i) << ", 0.5 -0.5 "
           << (-0.9 + 0.04 * i) << ", 0.5 0.5 " << (-0.9 + 0.04 * i) << ", -0.5 0.5 "
           << (-0.9 + 0.04 * i) << " ] }\n"
           << "FaceSet { numVertices 4 } }\n";
  const std::string text = sceneText("method FRAGMENT_LISTS", sheets.str());
  init();  // before the capture: Coin's handlers are set up by the first init
  CoinMessageCapture messages;
  const Rendered rendered = render(text);
  int warnings = 0;
  for (const CoinMessageCapture::Message& m : messages.messages())
    warnings += m.text.find(
                    "fragment lists not used, peeling instead: a pixel holds more "
                    "than 32 transparent surfaces") != std::string::npos;
  EXPECT_EQ(warnings, 1);
  // The lists' pass, then dual peeling: 40 layers in 21 passes after the depth range.
  EXPECT_EQ(rendered.stats.listPasses, 1);
  EXPECT_GT(rendered.stats.passes, 20);
  int checked = 0;
  EXPECT_LE(compareWithReference(rendered.image, reference(text), {}, 1.0, checked), 1.0);
}

// method TRACER: Embree traces the children on the CPU; the picture is the exact composite,
// the per-vertex alpha and the alpha texture included, without a peel pass.
TEST(Peeling, TracedMatchesTheReference) {
  for (const std::string& content : {planesAndSphere(), tippedTorus()}) {
    expectMatchesReference(content, "method TRACER");
    const Rendered traced = render(sceneText("method TRACER", content));
    EXPECT_EQ(traced.stats.passes, 0);
    EXPECT_EQ(traced.stats.listPasses, 0);
    EXPECT_EQ(traced.stats.tracedFrames, 1);
  }
}

// A traced separator's still frame draws the picture it kept. A child changed (the separator
// is notified), a transform above it moved or a texture set above it (it is not notified of
// either: the state above is compared) is traced again, and is the changed scene's exact
// picture.
TEST(Peeling, TracedPictureIsKeptUntilTheSceneChanges) {
  std::string text = sceneText("method TRACER", tippedTorus());
  text.replace(text.find("  DEF Peel PeelingSeparator"), 0,
               "  DEF Shift Translation { translation 0 0 0 }\n  DEF Above Texture2 { }\n");
  init();
  std::string error;
  auto renderer = CheckedRenderer::create(kSize, kSize, error);
  ASSERT_TRUE(renderer) << error;
  SoSeparator* root = readIv(text);
  const auto expectExact = [&](const std::string& scene, const char* when) {
    renderer->render(root);
    int checked = 0;
    EXPECT_LE(compareWithReference(renderer->read(), reference(scene), {}, kTolerance, checked),
              kTolerance)
        << when << "; images in " << outputDir();
    EXPECT_GT(checked, kSize * kSize * 9 / 10) << when;
  };
  expectExact(text, "first frame");
  expectExact(text, "still frame");
  EXPECT_EQ(collectPeelStatistics(root).tracedFrames, 1) << "the still frame traced";

  SoSearchAction search;
  search.setType(SoMaterial::getClassTypeId());
  search.apply(root);
  ASSERT_NE(search.getPath(), nullptr);
  static_cast<SoMaterial*>(search.getPath()->getTail())->diffuseColor.setValue(1.0f, 0.3f, 0.0f);
  std::string recoloured = text;
  recoloured.replace(recoloured.find("diffuseColor 0 0.8 0.9"),
                     std::string("diffuseColor 0 0.8 0.9").size(), "diffuseColor 1 0.3 0");
  expectExact(recoloured, "a child changed");
  EXPECT_EQ(collectPeelStatistics(root).tracedFrames, 2);

  static_cast<SoTranslation*>(SoNode::getByName("Shift"))->translation.setValue(0.3f, -0.2f, 0.0f);
  std::string shifted = recoloured;
  shifted.replace(shifted.find("translation 0 0 0"), std::string("translation 0 0 0").size(),
                  "translation 0.3 -0.2 0");
  expectExact(shifted, "a transform above moved");
  EXPECT_EQ(collectPeelStatistics(root).tracedFrames, 3);

  // A texture above the separator textures its children (Coin's MODULATE): the state they
  // inherit changed, which the separator is not notified of.
  const std::string texel = "image 1 1 4 0x4080FFC0";
  static_cast<SoTexture2*>(SoNode::getByName("Above"))
      ->image.setValue(SbVec2s(1, 1), 4,
                       reinterpret_cast<const unsigned char*>("\x40\x80\xff\xc0"));
  std::string textured = shifted;
  textured.replace(textured.find("DEF Above Texture2 { }"),
                   std::string("DEF Above Texture2 { }").size(),
                   "DEF Above Texture2 { " + texel + " }");
  expectExact(textured, "a texture above set");
  EXPECT_EQ(collectPeelStatistics(root).tracedFrames, 4);
  renderer.reset();
  root->unref();
}

// A coarse lit sphere in a half-transparent box, in a separator under a directional light:
// traced (method TRACER) it is lit per pixel, as the separator's own shading program lights it
// (FRAGMENT_LISTS), not per vertex as Coin's fixed-function GL would. The two pictures agree
// within 2 steps: the program's float lighting against the tracer's, each rounded to 8 bits
// once, the lists' colours kept in 16 bits (measured: 1). Lit per vertex, 16 % of the pixels
// differed by more than 3 steps, up to 65.
TEST(Peeling, TracedShapesAreLitAsTheSeparatorsProgramLightsThem) {
  const auto text = [](const char* method) {
    return std::string(
               "#Inventor V2.1 ascii\nSeparator {\n"
               "  OrthographicCamera { position 0 0 5 nearDistance 1 farDistance 10 "
               "height 2.4 }\n"
               "  DirectionalLight { direction -0.4 -0.5 -1 }\n"
               "  PeelingSeparator { method ") +
           method +
           "\n"
           "    Complexity { value 0.1 }\n"
           "    Material { diffuseColor 0.9 0.6 0.2 specularColor 0.6 0.6 0.6 shininess 0.2 }\n"
           "    Sphere { radius 0.7 }\n"
           "    Material { diffuseColor 0.2 0.5 1 transparency 0.5 }\n"
           "    Cube { width 1.6 height 1.6 depth 1.6 }\n"
           "  }\n}\n";
  };
  const Image traced = render(text("TRACER")).image;
  const Image listed = render(text("FRAGMENT_LISTS")).image;
  double worst = 0.0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      for (int c = 0; c < 3; ++c)
        worst = std::max(worst, double(std::abs(traced.pixel(x, y)[c] - listed.pixel(x, y)[c])));
  EXPECT_LE(worst, 2.0);
}

// method AUTO traces on a software rasteriser (these machines: llvmpipe) and lists the
// fragments on a GPU, says which once, and is exact either way.
TEST(Peeling, AutoTracesOnASoftwareRasteriserAndSaysSo) {
  const std::string text = sceneText("method AUTO", planesAndSphere());
  init();
  CoinMessageCapture messages;
  std::string error;
  auto renderer = CheckedRenderer::create(kSize, kSize, error);
  ASSERT_TRUE(renderer) << error;
  const bool software = GlCapabilities::queryCurrent().isSoftwareRenderer();
  SoSeparator* root = readIv(text);
  renderer->render(root);
  renderer->render(root);
  const PeelStatistics stats = collectPeelStatistics(root);
  int checked = 0;
  EXPECT_LE(compareWithReference(renderer->read(), reference(text), {}, kTolerance, checked),
            kTolerance);
  renderer.reset();
  root->unref();
  int said = 0;
  for (const CoinMessageCapture::Message& m : messages.messages())
    said += m.text.find(software ? "method AUTO uses TRACER" : "method AUTO uses FRAGMENT_LISTS") !=
            std::string::npos;
  EXPECT_EQ(said, 1);
  EXPECT_EQ(stats.tracedFrames, software ? 1 : 0);
  EXPECT_EQ(stats.listPasses > 0, !software);
}

TEST(Peeling, TheScenesNeedOrderIndependentTransparency) {
  // Coin's own blending in traversal order gets these scenes visibly wrong, so matching the
  // reference above says something.
  for (const std::string& content : {planesAndSphere(), tippedTorus()}) {
    std::string text = sceneText("", content);
    text.replace(text.find("PeelingSeparator"), std::string("PeelingSeparator").size(),
                 "Separator");
    const Rendered plain = render(text);
    int checked = 0;
    const double worst = compareWithReference(plain.image, reference(text), {}, 255.0, checked);
    EXPECT_GT(worst, 40.0);
  }
}

TEST(Peeling, CoinsTransparencyTypeIsOverridden) {
  const std::string text = sceneText("", planesAndSphere());
  const Image blend = render(text).image;
  for (auto type : {SoGLRenderAction::DELAYED_BLEND, SoGLRenderAction::SORTED_OBJECT_BLEND,
                    SoGLRenderAction::SCREEN_DOOR, SoGLRenderAction::NONE}) {
    const Image other = render(text, type).image;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x)
        for (int c = 0; c < 3; ++c)
          ASSERT_EQ(blend.pixel(x, y)[c], other.pixel(x, y)[c]) << "type " << int(type);
  }
}

TEST(Peeling, DualAndFrontToBackAgree) {
  const Rendered dual = render(sceneText("method DUAL", planesAndSphere()));
  const Rendered frontToBack = render(sceneText("method FRONT_TO_BACK", planesAndSphere()));
  int worst = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      for (int c = 0; c < 3; ++c)
        worst =
            std::max(worst, std::abs(dual.image.pixel(x, y)[c] - frontToBack.image.pixel(x, y)[c]));
  EXPECT_LE(worst, 1) << "both composite the same layers in float";
  // DUAL peels two layers a pass: fewer passes for the same picture.
  EXPECT_LT(dual.stats.passes, frontToBack.stats.passes);
}

TEST(Peeling, CappedFrontToBackDropsTheDeepestLayers) {
  // Two passes: the depth range, then the nearest layer only.
  expectMatchesReference(tippedTorus(), "method FRONT_TO_BACK maxPasses 2",
                         PeelReference::Keep{1, 0});
  // Three: the two nearest.
  expectMatchesReference(tippedTorus(), "method FRONT_TO_BACK maxPasses 3",
                         PeelReference::Keep{2, 0});
}

TEST(Peeling, CappedDualKeepsTheNearestAndFarthestLayers) {
  // Two passes: the depth range, then the nearest and the farthest layer.
  expectMatchesReference(tippedTorus(), "method DUAL maxPasses 2", PeelReference::Keep{1, 1});
}

TEST(Peeling, AViewWithoutTransparencyCostsNoPeelPass) {
  const Rendered rendered = render(sceneText("", ""));
  // The opaque pass met no transparent fragment: not even the depth-range pass runs.
  EXPECT_EQ(rendered.stats.passes, 0);
  // And the opaque floor is drawn as usual.
  EXPECT_NEAR(rendered.image.pixel(kSize / 2, kSize / 2)[0], 128.0, 1.0);
}

TEST(Peeling, EarlyTerminationOffRunsEveryPass) {
  const Rendered rendered = render(sceneText("method DUAL earlyTermination FALSE maxPasses 5", ""));
  EXPECT_EQ(rendered.stats.passes, 5);
}

// Issue 35: a negative maxPasses (from a file or --set PS.maxPasses=-1) was taken as 0
// silently, where other out-of-range fields warn: it still means 0, said once.
TEST(Peeling, ANegativeMaxPassesIsTakenAsZeroWithOneWarning) {
  init();  // before the capture: Coin's handlers are set up by the first init
  CoinMessageCapture messages;
  const std::string text = sceneText("method DUAL earlyTermination FALSE maxPasses -1", "");
  const Rendered rendered = render(text);
  int warnings = 0;
  for (const CoinMessageCapture::Message& m : messages.messages())
    warnings += m.text.find("PeelingSeparator 'Peel': field maxPasses -1 is negative; using 0") !=
                std::string::npos;
  EXPECT_EQ(warnings, 1);
  EXPECT_EQ(rendered.stats.passes, SoPeelingSeparator::kMaxPasses);
}

// Seen from above: a red glass (opacity 0.4) over a green glass (opacity 0.8) over the floor,
// all under the group's deep shadow light, in a separator with `peelFields`, in a group with
// `groupFields`. Opacities are exact in 8 bits.
void expectPeeledInsideAShadowGroup(const std::string& peelFields,
                                    const std::string& groupFields = "") {
  ShadowScene scene;
  scene.filters = {Filter{0.3, 0.5, {1, 0, 0}, 0.6, ""}, Filter{0.4, 0.25, {0, 1, 0}, 0.2, ""}};
  scene.peelFilters = true;
  scene.groupFields = groupFields;
  std::string text = scene.text();
  text.replace(text.find("PeelingSeparator {"), std::string("PeelingSeparator {").size(),
               "PeelingSeparator { " + peelFields);
  SoNode* root = nullptr;
  const Image image = renderIv(text, ShadowScene::kSize, &root);
  const PeelStatistics stats = collectPeelStatistics(root);
  root->unref();
  // Inside a group the layers are peeled with its shading (its renderer TRACER would trace
  // them): by the group's own peeling, or, where the group leaves transparency to Coin, by the
  // separator, TRACER and AUTO with the lists.
  EXPECT_EQ(stats.tracedFrames, 0) << peelFields;
  if (peelFields.find("FRONT_TO_BACK") == std::string::npos &&
      peelFields.find("DUAL") == std::string::npos)
    EXPECT_GE(stats.listPasses, 1) << peelFields;
  const auto red = transmittance(scene.filters[0], ColourModel::Saturate);
  const auto green = transmittance(scene.filters[1], ColourModel::Saturate);
  const std::string failure = compareWithExpectation(
      image,
      [&](int px, int py) {
        Expectation e;
        const double x = -1.2 + (px + 0.5) / 100.0, y = 1.2 - (py + 0.5) / 100.0;
        if (std::max(std::abs(x), std::abs(y)) > 0.28) return e;  // where all three overlap
        const double r2 = x * x + y * y;
        // Lambert from the light at (0, 0, 1) on each horizontal surface at height h.
        auto lambert = [&](double h) { return (1 - h) / std::sqrt((1 - h) * (1 - h) + r2); };
        e.checked = true;
        for (std::size_t c = 0; c < 3; ++c) {
          const double redLit = scene.filters[0].diffuse[c] * lambert(0.5);
          const double greenLit = scene.filters[1].diffuse[c] * lambert(0.25) * red[c];
          const double floorLit = lambert(0.0) * red[c] * green[c];
          e.rgb[c] = 255.0 * (0.4 * redLit + 0.6 * (0.8 * greenLit + 0.2 * floorLit));
        }
        return e;
      },
      kTolerance);
  EXPECT_TRUE(failure.empty()) << peelFields << ": " << failure;
}

TEST(Peeling, PeeledLayersInsideAShadowGroupShowItsShadows) {
  expectPeeledInsideAShadowGroup("");
  expectPeeledInsideAShadowGroup("method DUAL");
  expectPeeledInsideAShadowGroup("method TRACER");
  expectPeeledInsideAShadowGroup("method AUTO");
  for (const char* method : {"method FRAGMENT_LISTS", "method TRACER", "method AUTO"})
    expectPeeledInsideAShadowGroup(method, "transparency COIN_BLENDING");
}

}  // namespace
}  // namespace ivshadow::test
