// A SoTransparentShadowGroup composites its transparent surfaces in exact depth order by
// default (transparency PEELED), without a SoPeelingSeparator; COIN_BLENDING keeps Coin's
// order-dependent blending. Every expected colour here is computed in the test from the
// blend equations (seeds/000 eq. 2.5-2.8: C = a c + (1 - a) C_behind, over black), from the
// scene's own numbers, without the plugin's extraction or reference renderer.

#include "ivshadow/IvShadowInit.h"
#include "ivshadow/PeelStatistics.h"
#include "ivshadow/SoPeelingSeparator.h"
#include "ivshadow/SoTransparentShadowGroup.h"
#include "tests/gl/CheckedRenderer.h"
#include "tests/gl/ShadowScene.h"

#include <Inventor/SoOutput.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/actions/SoWriteAction.h>
#include <Inventor/nodes/SoSeparator.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace ivshadow::test {
namespace {

constexpr int kSize = 160;
constexpr double kViewHeight = 2.4;
constexpr double kPixel = kViewHeight / kSize;

// Layers are composited in float and written to the 8-bit framebuffer once (over black or
// over an opaque floor whose value is exact in 8 bits): one rounding, at most half a step,
// so 1/255 bounds an exact result.
constexpr double kExact = 1.0;

// The scene point (x, y) seen at the centre of pixel (px, py), row 0 at the top.
std::array<double, 2> scenePoint(int px, int py) {
  return {-kViewHeight / 2 + (px + 0.5) * kPixel, kViewHeight / 2 - (py + 0.5) * kPixel};
}

// A surface met by a pixel's ray: its height (the camera looks down -z, so larger is
// nearer), colour and opacity, in traversal order.
struct Surface {
  double z;
  std::array<double, 3> colour;
  double alpha;
};

// The exact picture: surfaces sorted near to far and composited front to back over black.
std::array<double, 3> exactComposite(std::vector<Surface> surfaces) {
  std::sort(surfaces.begin(), surfaces.end(),
            [](const Surface& a, const Surface& b) { return a.z > b.z; });
  std::array<double, 3> colour{};
  double transmittance = 1.0;
  for (const Surface& s : surfaces) {
    for (std::size_t c = 0; c < 3; ++c) colour[c] += transmittance * s.alpha * s.colour[c];
    transmittance *= 1.0 - s.alpha;
  }
  for (double& c : colour) c *= 255.0;
  return colour;
}

// Coin's BLEND: surfaces drawn at once in traversal order, each blended over what is in the
// framebuffer (glBlendFunc(SRC_ALPHA, ONE_MINUS_SRC_ALPHA)) where it passes the depth test
// (LESS), and writing its depth: a transparent surface drawn before one behind it hides it.
std::array<double, 3> coinBlend(const std::vector<Surface>& surfaces) {
  std::array<double, 3> colour{};
  double nearest = -1e30;
  for (const Surface& s : surfaces) {
    if (s.z <= nearest) continue;
    nearest = s.z;
    for (std::size_t c = 0; c < 3; ++c)
      colour[c] = s.alpha * s.colour[c] + (1 - s.alpha) * colour[c];
  }
  for (double& c : colour) c *= 255.0;
  return colour;
}

struct Rendered {
  Image image;
  PeelStatistics group;
  PeelStatistics separators;
};

Rendered render(const std::string& text) {
  init();
  std::string error;
  auto renderer = CheckedRenderer::create(kSize, kSize, error);
  if (!renderer) throw std::runtime_error(error);
  renderer->action().setTransparencyType(SoGLRenderAction::BLEND);
  SoSeparator* root = readIv(text);
  renderer->render(root);
  Rendered out{renderer->read(), {}, {}};
  SoSearchAction search;
  search.setType(SoTransparentShadowGroup::getClassTypeId());
  search.setInterest(SoSearchAction::ALL);
  search.apply(root);
  for (int i = 0; i < search.getPaths().getLength(); ++i)
    out.group.passes += static_cast<SoTransparentShadowGroup*>(search.getPaths()[i]->getTail())
                            ->getPeelStatistics()
                            .passes;
  search.setType(SoPeelingSeparator::getClassTypeId());
  search.apply(root);
  for (int i = 0; i < search.getPaths().getLength(); ++i)
    out.separators.passes +=
        static_cast<SoPeelingSeparator*>(search.getPaths()[i]->getTail())->getStatistics().passes;
  renderer.reset();
  root->unref();
  return out;
}

// The group around `content`, unlit (BASE_COLOR: a surface's colour is its diffuse colour),
// seen straight down by an orthographic camera.
std::string groupScene(const std::string& groupFields, const std::string& content) {
  std::ostringstream iv;
  iv << "#Inventor V2.1 ascii\nSeparator {\n"
     << "  OrthographicCamera { position 0 0 5 nearDistance 1 farDistance 10 height " << kViewHeight
     << " }\n"
     << "  DEF Group TransparentShadowGroup { renderer RASTER " << groupFields << "\n"
     << "    LightModel { model BASE_COLOR }\n"
     << "    ShapeHints { vertexOrdering UNKNOWN_ORDERING shapeType UNKNOWN_SHAPE_TYPE }\n"
     << content << "  }\n}\n";
  return iv.str();
}

// Two half-transparent panes crossing along x = 0: A (red) tilted, z = -x / 2, nearer the
// camera left of the crossing; B (green) flat at z = 0, nearer right of it. A is traversed
// first, so Coin's blending hides B behind A on the left.
constexpr double kPaneHalf = 0.8;
const Surface kPaneA{0.0, {1, 0, 0}, 0.5};
const Surface kPaneB{0.0, {0, 1, 0}, 0.5};

std::string crossingPanes() {
  const double h = kPaneHalf;
  std::ostringstream iv;
  iv << "    Separator { Material { diffuseColor 1 0 0 transparency 0.5 }\n"
     << "      Coordinate3 { point [ " << -h << ' ' << -h << ' ' << h / 2 << ", " << h << ' ' << -h
     << ' ' << -h / 2 << ", " << h << ' ' << h << ' ' << -h / 2 << ", " << -h << ' ' << h << ' '
     << h / 2 << " ] }\n      FaceSet { numVertices 4 } }\n"
     << "    Separator { Material { diffuseColor 0 1 0 transparency 0.5 }\n"
     << "      Coordinate3 { point [ " << -h << ' ' << -h << " 0, " << h << ' ' << -h << " 0, " << h
     << ' ' << h << " 0, " << -h << ' ' << h << " 0 ] }\n      FaceSet { numVertices 4 } }\n";
  return iv.str();
}

// The panes' picture under `composite`; pixels within two pixels of a pane's edge or of the
// crossing are not checked (rasterisation may give them to either side).
ExpectedImage panesPicture(std::array<double, 3> (*composite)(const std::vector<Surface>&)) {
  return [composite](int px, int py) {
    Expectation e;
    const auto [x, y] = scenePoint(px, py);
    const double margin = 2 * kPixel;
    const double extent = std::max(std::abs(x), std::abs(y));
    if (std::abs(extent - kPaneHalf) < margin || std::abs(x) < margin) return e;
    e.checked = true;
    if (extent > kPaneHalf) return e;  // black background
    Surface a = kPaneA, b = kPaneB;
    a.z = -x / 2;
    e.rgb = composite({a, b});
    return e;
  };
}

std::array<double, 3> exactOf(const std::vector<Surface>& s) {
  return exactComposite(s);
}

TEST(GroupPeeling, CrossingPanesAreExactOnBothSidesWithoutAPeelingSeparator) {
  const Rendered rendered = render(groupScene("", crossingPanes()));
  const std::string failure = compareWithExpectation(rendered.image, panesPicture(exactOf), kExact);
  EXPECT_TRUE(failure.empty()) << failure;
  // Both layers in one pass into the fragment lists: no peel pass.
  EXPECT_EQ(rendered.group.passes, 1);
  // The scene needs it: Coin's order is a quarter of full scale off on the left, where B is
  // hidden (green 0.25 x 255 missing).
  const Surface a{0.4, kPaneA.colour, kPaneA.alpha}, b = kPaneB;
  EXPECT_NEAR(exactComposite({a, b})[1] - coinBlend({a, b})[1], 63.75, 1e-9);
}

// A lone half-transparent red pane as an IndexedFaceSet of four coordinates, which Coin draws
// between glBegin and glEnd (below its vertex-buffer limit): Mesa hands such vertices to the
// rasteriser only at its next flush, and the opaque pass's progress flag used to be read
// before that, so the pane raised no flag, no peel pass ran and it vanished. Exact: alpha 0.5
// of red over black, 127.5; black around it.
const char* const kIndexedPane =
    "    Material { diffuseColor 1 0 0 transparency 0.5 }\n"
    "    Coordinate3 { point [ -0.8 -0.8 0, 0.8 -0.8 0, -0.8 0.8 0, 0.8 0.8 0 ] }\n"
    "    IndexedFaceSet { coordIndex [ 0, 1, 3, -1, 0, 3, 2, -1 ] }\n";

ExpectedImage indexedPanePicture() {
  return [](int px, int py) {
    Expectation e;
    const auto [x, y] = scenePoint(px, py);
    const double extent = std::max(std::abs(x), std::abs(y));
    if (std::abs(extent - 0.8) < 2 * kPixel) return e;  // the pane's edge
    e.checked = true;
    if (extent < 0.8) e.rgb = {127.5, 0.0, 0.0};
    return e;
  };
}

TEST(GroupPeeling, ASmallIndexedFaceSetDrawnImmediatelyIsPeeledToo) {
  const Rendered grouped = render(groupScene("", kIndexedPane));
  EXPECT_GE(grouped.group.passes, 1);
  std::string failure = compareWithExpectation(grouped.image, indexedPanePicture(), kExact);
  EXPECT_TRUE(failure.empty()) << failure;
  // And in a SoPeelingSeparator outside any group.
  const Rendered separated = render(
      groupScene("isActive FALSE",
                 std::string("PeelingSeparator { method FRAGMENT_LISTS\n") + kIndexedPane + "}\n"));
  EXPECT_GE(separated.separators.passes, 1);
  failure = compareWithExpectation(separated.image, indexedPanePicture(), kExact);
  EXPECT_TRUE(failure.empty()) << failure;
}

TEST(GroupPeeling, CrossingPanesUnderCoinBlendingKeepCoinsOrder) {
  const Rendered rendered = render(groupScene("transparency COIN_BLENDING", crossingPanes()));
  const std::string failure =
      compareWithExpectation(rendered.image, panesPicture(coinBlend), kExact);
  EXPECT_TRUE(failure.empty()) << failure;
  EXPECT_EQ(rendered.group.passes, 0);
}

TEST(GroupPeeling, ATransparentShapeThatIsNotShadowedIsBlendedAsByCoin) {
  // SoShadowStyle switches the group's program off for pane A: Coin draws it in the opaque
  // pass, blended over what is there and writing its depth, as under its BLEND. B, behind A
  // on the left, is then hidden there; on the right it is peeled and composited over A. Both
  // sides give Coin's order, and A is not drawn opaque.
  std::string panes = crossingPanes();
  panes.replace(panes.find("Material"), 0, "ShadowStyle { style NO_SHADOWING } ");
  const Rendered rendered = render(groupScene("", panes));
  const std::string failure =
      compareWithExpectation(rendered.image, panesPicture(coinBlend), kExact);
  EXPECT_TRUE(failure.empty()) << failure;
}

// A closed glass box, each face its own colour (opacity 0.5), turned so that the camera sees
// different pairs of faces, over an opaque grey floor (0.4: 102 in 8 bits, exactly).
constexpr double kBoxHalf = 0.4;
constexpr double kBoxCentreZ = 0.8;
constexpr double kFloorGrey = 0.4;
constexpr double kFloorHalf = 1.1;
const std::array<std::array<double, 3>, 6> kFaceColours = {
    {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {0, 1, 1}, {1, 0, 1}}};

// The box's rotation (about x by 0.5, then about y by 0.4) as rows of a matrix.
std::array<std::array<double, 3>, 3> boxRotation() {
  const double ax = 0.5, ay = 0.4;
  const std::array<std::array<double, 3>, 3> rx = {
      {{1, 0, 0}, {0, std::cos(ax), -std::sin(ax)}, {0, std::sin(ax), std::cos(ax)}}};
  const std::array<std::array<double, 3>, 3> ry = {
      {{std::cos(ay), 0, std::sin(ay)}, {0, 1, 0}, {-std::sin(ay), 0, std::cos(ay)}}};
  std::array<std::array<double, 3>, 3> r{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) r[i][j] += ry[i][k] * rx[k][j];
  return r;
}

// Face f (traversal order): axis f / 2, side + for even f: +x, -x, +y, -y, +z, -z.
std::string glassBoxOverFloor() {
  const auto r = boxRotation();
  std::ostringstream iv;
  iv << "    Separator { Material { diffuseColor " << kFloorGrey << ' ' << kFloorGrey << ' '
     << kFloorGrey << " }\n      Coordinate3 { point [ " << -kFloorHalf << ' ' << -kFloorHalf
     << " 0, " << kFloorHalf << ' ' << -kFloorHalf << " 0, " << kFloorHalf << ' ' << kFloorHalf
     << " 0, " << -kFloorHalf << ' ' << kFloorHalf << " 0 ] }\n"
     << "      FaceSet { numVertices 4 } }\n";
  // Each face its own shape with its own material, drawn in face order.
  static const int kCorners[6][4] = {{1, 3, 7, 5}, {0, 4, 6, 2}, {2, 6, 7, 3},
                                     {0, 1, 5, 4}, {4, 5, 7, 6}, {0, 2, 3, 1}};
  for (int f = 0; f < 6; ++f) {
    const auto& c = kFaceColours[std::size_t(f)];
    iv << "    Separator { Material { diffuseColor " << c[0] << ' ' << c[1] << ' ' << c[2]
       << " transparency 0.5 }\n      Coordinate3 { point [ ";
    for (int k = 0; k < 4; ++k) {
      // Corners by bits (x 1, y 2, z 4).
      const int corner = kCorners[f][k];
      const std::array<double, 3> v = {corner & 1 ? kBoxHalf : -kBoxHalf,
                                       corner & 2 ? kBoxHalf : -kBoxHalf,
                                       corner & 4 ? kBoxHalf : -kBoxHalf};
      for (int i = 0; i < 3; ++i)
        iv << r[i][0] * v[0] + r[i][1] * v[1] + r[i][2] * v[2] + (i == 2 ? kBoxCentreZ : 0.0)
           << ' ';
      iv << ", ";
    }
    iv << "] }\n      FaceSet { numVertices 4 } }\n";
  }
  return iv.str();
}

// The surfaces the ray through (x, y) meets, in traversal order (floor, then the faces the
// box's slabs give), or false when it passes within `margin` of a box edge.
bool boxSurfaces(double x, double y, double margin, std::vector<Surface>& surfaces) {
  surfaces.clear();
  if (std::max(std::abs(x), std::abs(y)) < kFloorHalf)
    surfaces.push_back({0.0, {kFloorGrey, kFloorGrey, kFloorGrey}, 1.0});
  const auto r = boxRotation();
  // The ray (x, y, z) - t (0, 0, 1) in box coordinates: R^T (p - centre), direction R^T (0,0,-1).
  const std::array<double, 3> p = {x, y, 10.0 - kBoxCentreZ};
  std::array<double, 3> o{}, d{};
  for (int i = 0; i < 3; ++i) {
    o[i] = r[0][i] * p[0] + r[1][i] * p[1] + r[2][i] * p[2];
    d[i] = -r[2][i];
  }
  double entry = -1e30, exit = 1e30;
  int entryFace = -1, exitFace = -1;
  for (int i = 0; i < 3; ++i) {
    const double t1 = (-kBoxHalf - o[i]) / d[i], t2 = (kBoxHalf - o[i]) / d[i];
    const double near = std::min(t1, t2), far = std::max(t1, t2);
    // Entering through the face whose side the ray starts on.
    const int nearFace = 2 * i + (t1 < t2 ? 1 : 0), farFace = 2 * i + (t1 < t2 ? 0 : 1);
    if (near > entry) entry = near, entryFace = nearFace;
    if (far < exit) exit = far, exitFace = farFace;
  }
  if (entry > exit) return true;  // misses the box
  for (double t : {entry, exit})
    for (int i = 0; i < 3; ++i) {
      const double c = o[i] + t * d[i];
      // On the face itself the coordinate is +-half; the other two must keep off the edges.
      if (std::abs(std::abs(c) - kBoxHalf) > 1e-9 && std::abs(c) > kBoxHalf - margin) return false;
    }
  if (exit - entry < margin) return false;  // grazing a corner or an edge
  // The box's faces in traversal order (face index), the height along the ray 10 - t.
  for (int f = 0; f < 6; ++f) {
    if (f == entryFace) surfaces.push_back({10.0 - entry, kFaceColours[std::size_t(f)], 0.5});
    if (f == exitFace) surfaces.push_back({10.0 - exit, kFaceColours[std::size_t(f)], 0.5});
  }
  return true;
}

ExpectedImage boxPicture(std::array<double, 3> (*composite)(const std::vector<Surface>&)) {
  return [composite](int px, int py) {
    Expectation e;
    const auto [x, y] = scenePoint(px, py);
    const double margin = 2 * kPixel;
    if (std::abs(std::max(std::abs(x), std::abs(y)) - kFloorHalf) < margin) return e;
    std::vector<Surface> surfaces;
    if (!boxSurfaces(x, y, margin, surfaces)) return e;
    e.checked = true;
    e.rgb = composite(surfaces);
    return e;
  };
}

TEST(GroupPeeling, ClosedGlassBoxOverAFloorIsExact) {
  const Rendered rendered = render(groupScene("", glassBoxOverFloor()));
  const std::string failure = compareWithExpectation(rendered.image, boxPicture(exactOf), kExact);
  EXPECT_TRUE(failure.empty()) << failure;
  EXPECT_EQ(rendered.group.passes, 1) << "two glass layers, one pass into the fragment lists";
}

TEST(GroupPeeling, ClosedGlassBoxUnderCoinBlendingKeepsCoinsOrder) {
  const Rendered rendered = render(groupScene("transparency COIN_BLENDING", glassBoxOverFloor()));
  const std::string failure = compareWithExpectation(rendered.image, boxPicture(coinBlend), kExact);
  EXPECT_TRUE(failure.empty()) << failure;
  // And there, Coin's order is visibly wrong: where a front face is drawn before the back
  // face behind it, the back face (a full channel of colour) is lost and the floor (0.4)
  // shows through instead, 0.25 (1 - 0.4) 255 = 38.25 off.
  double worst = 0.0;
  std::vector<Surface> surfaces;
  for (int py = 0; py < kSize; ++py)
    for (int px = 0; px < kSize; ++px) {
      const auto [x, y] = scenePoint(px, py);
      if (!boxSurfaces(x, y, 0.0, surfaces)) continue;
      const auto exact = exactComposite(surfaces), coin = coinBlend(surfaces);
      for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(exact[c] - coin[c]));
    }
  EXPECT_GT(worst, 38.0);
}

TEST(GroupPeeling, APeelingSeparatorInsideAPeelingGroupPeelsOnce) {
  const std::string inside =
      "    PeelingSeparator { method FRONT_TO_BACK\n" + crossingPanes() + "    }\n";
  // Peeling group: the group peels every pixel once, the separator draws its children as part
  // of that peeling.
  const Rendered peeled = render(groupScene("", inside));
  std::string failure = compareWithExpectation(peeled.image, panesPicture(exactOf), kExact);
  EXPECT_TRUE(failure.empty()) << failure;
  EXPECT_EQ(peeled.group.passes, 1);  // the fragment lists' one pass
  EXPECT_EQ(peeled.separators.passes, 0);
  // Blending group: the separator peels as before (front to back: the range pass, then one
  // pass per layer).
  const Rendered blended = render(groupScene("transparency COIN_BLENDING", inside));
  failure = compareWithExpectation(blended.image, panesPicture(exactOf), kExact);
  EXPECT_TRUE(failure.empty()) << failure;
  EXPECT_EQ(blended.group.passes, 0);
  EXPECT_EQ(blended.separators.passes, 3);
}

TEST(GroupPeeling, AGroupInsideAPeelingGroupIsPeeledWithIt) {
  // The inner group draws its children as part of the outer group's peeling (its own
  // programs would write into the peel targets): exact, with the outer group's one pass.
  const Rendered rendered = render(groupScene(
      "", "    TransparentShadowGroup { renderer RASTER\n" + crossingPanes() + "    }\n"));
  const std::string failure = compareWithExpectation(rendered.image, panesPicture(exactOf), kExact);
  EXPECT_TRUE(failure.empty()) << failure;
  EXPECT_EQ(rendered.group.passes, 1) << "summed over both groups: only the outer one lists";
}

TEST(GroupPeeling, AnOpaqueSceneCostsNoPeelPass) {
  const std::string floor =
      "    Material { diffuseColor 0.4 0.4 0.4 }\n"
      "    Coordinate3 { point [ -1 -1 0, 1 -1 0, 1 1 0, -1 1 0 ] }\n"
      "    FaceSet { numVertices 4 }\n";
  const Rendered peeled = render(groupScene("", floor));
  const Rendered blended = render(groupScene("transparency COIN_BLENDING", floor));
  EXPECT_EQ(peeled.group.passes, 0) << "the opaque pass saw no transparent fragment";
  // The one traversal draws what Coin's blending draws.
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      for (int c = 0; c < 3; ++c)
        ASSERT_EQ(peeled.image.pixel(x, y)[c], blended.image.pixel(x, y)[c]);
  EXPECT_EQ(peeled.image.pixel(kSize / 2, kSize / 2)[0], 102);
}

// ShadowScene's red glass (opacity 0.4) over its green glass (opacity 0.8) over the floor,
// lit by the group's deep shadow light, without a peeling separator: the red glass is
// traversed first, so Coin's blending would hide the green one. Opacities are exact in 8 bits.
void expectShadowedGlassesPeeled(const std::string& method) {
  ShadowScene scene;
  scene.method = method;
  scene.filters = {Filter{0.3, 0.5, {1, 0, 0}, 0.6, ""}, Filter{0.4, 0.25, {0, 1, 0}, 0.2, ""}};
  const Image image = renderIv(scene.text(), ShadowScene::kSize);
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
      // The shading is per pixel in float; the floor is written in 8 bits before the layers
      // are composited over it (half a step, times the layers' transmittance 0.12) and the
      // result rounded once more: 1/255.
      kExact);
  EXPECT_TRUE(failure.empty()) << method << ": " << failure;
}

TEST(GroupPeeling, PeeledLayersShowTheMapsShadows) {
  expectShadowedGlassesPeeled("MAP");
}

TEST(GroupPeeling, PeeledLayersShowTheTracedShadows) {
  expectShadowedGlassesPeeled("RAYS");
}

TEST(GroupPeeling, TheTransparencyFieldIsWrittenWhenNotTheDefault) {
  init();
  SoSeparator* root = readIv(groupScene("transparency COIN_BLENDING", ""));
  SoSearchAction search;
  search.setType(SoTransparentShadowGroup::getClassTypeId());
  search.apply(root);
  ASSERT_NE(search.getPath(), nullptr);
  auto* group = static_cast<SoTransparentShadowGroup*>(search.getPath()->getTail());
  EXPECT_EQ(group->transparency.getValue(), int(SoTransparentShadowGroup::COIN_BLENDING));
  auto written = [&] {
    SoOutput out;
    out.setBuffer(malloc(1024), 1024, realloc);
    SoWriteAction write(&out);
    write.apply(group);
    void* buffer = nullptr;
    size_t size = 0;
    out.getBuffer(buffer, size);
    const std::string text(static_cast<const char*>(buffer), size);
    free(buffer);
    return text;
  };
  EXPECT_NE(written().find("transparency COIN_BLENDING"), std::string::npos) << written();
  group->transparency.setValue(SoTransparentShadowGroup::PEELED);
  group->transparency.setDefault(TRUE);
  // (The "fields [ ... ]" line Coin writes for an extension node names the field, not its
  // value.)
  EXPECT_EQ(written().find("transparency PEELED"), std::string::npos)
      << "the default is not written: " << written();
  EXPECT_EQ(written().find("transparency COIN_BLENDING"), std::string::npos) << written();
  auto* fresh = new SoTransparentShadowGroup;
  fresh->ref();
  EXPECT_EQ(fresh->transparency.getValue(), int(SoTransparentShadowGroup::PEELED));
  fresh->unref();
  root->unref();
}

}  // namespace
}  // namespace ivshadow::test
