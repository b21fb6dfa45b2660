// GL and Embree failures forced through IVSHADOW_FAIL_GL and IVSHADOW_FAIL_EMBREE
// (gl/GlAllocationCheck.h, nodes/RayCasters.cpp): each run of `ivshadow render` must
// exit 0 with one warning naming the node, and draw the documented fallback, which the test
// renders itself without the fault: the same light without a shadow (a plain PointLight of the
// same place and intensity, which a DEEP_SHADOW_LIGHTS group lights with the same program but
// never shadows), Coin's blending instead of peeling, the map instead of the rays.
#include "image_files/ImageComparison.h"
#include "image_files/PngFile.h"
#include "tests/support/TestSupport.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace ivshadow {
namespace {

// A white floor at z = 0 and a red pane (transparency 0.5) at z = 1 under a light at z = 2.5,
// seen from above: the pane's shadow on the floor reaches 1.67 times past its edge, so a ring
// of shadow shows around the pane.
std::string groupScene(const std::string& light, const std::string& lightFields,
                       const std::string& transparency) {
  return "#Inventor V2.1 ascii\n"
         "Separator {\n"
         "  PerspectiveCamera { position 0 0 6 nearDistance 1 farDistance 20 "
         "heightAngle 0.785398 }\n"
         "  DEF Scene TransparentShadowGroup { renderer RASTER\n"
         "    castingLights DEEP_SHADOW_LIGHTS\n"
         "    transparency " +
         transparency +
         "\n"
         "    DEF Lamp " +
         light + " { location 0 0 2.5 intensity 1 " + lightFields +
         " }\n"
         "    DEF Floor Separator {\n"
         "      Material { diffuseColor 1 1 1 }\n"
         "      Coordinate3 { point [ -2 -2 0, 2 -2 0, 2 2 0, -2 2 0 ] }\n"
         "      FaceSet { numVertices 4 }\n"
         "    }\n"
         "    DEF Pane Separator {\n"
         "      Material { diffuseColor 1 0.1 0.1 transparency 0.5 }\n"
         "      Coordinate3 { point [ -0.6 -0.6 1, 0.6 -0.6 1, 0.6 0.6 1, -0.6 0.6 1 ] }\n"
         "      FaceSet { numVertices 4 }\n"
         "    }\n"
         "  }\n"
         "}\n";
}

// The same floor and pane in a standalone peeling separator (or a plain one), lit by a point
// light outside it.
std::string separatorScene(const std::string& separator) {
  return "#Inventor V2.1 ascii\n"
         "Separator {\n"
         "  PerspectiveCamera { position 0 0 6 nearDistance 1 farDistance 20 "
         "heightAngle 0.785398 }\n"
         "  PointLight { location 0 0 2.5 }\n"
         "  DEF Glass " +
         separator +
         " {\n"
         "    Material { diffuseColor 1 1 1 }\n"
         "    Coordinate3 { point [ -2 -2 0, 2 -2 0, 2 2 0, -2 2 0 ] }\n"
         "    FaceSet { numVertices 4 }\n"
         "    Material { diffuseColor 1 0.1 0.1 transparency 0.5 }\n"
         "    Coordinate3 { point [ -0.6 -0.6 1, 0.6 -0.6 1, 0.6 0.6 1, -0.6 0.6 1 ] }\n"
         "    FaceSet { numVertices 4 }\n"
         "  }\n"
         "}\n";
}

struct Rendered {
  test::ProcessResult result;
  Image image;
  nlohmann::json stats;  // --stats
};

Rendered render(const std::string& name, const std::string& scene,
                const std::vector<std::string>& environment = {}) {
  const std::string dir = test::outputDir();
  const std::string file = dir + "/" + name + ".iv", png = dir + "/" + name + ".png",
                    stats = dir + "/" + name + ".json";
  std::ofstream(file) << scene;
  Rendered rendered;
  rendered.result = test::run(
      {test::ivshadowExe(), "render", file, "-o", png, "--size", "96x96", "--stats", stats},
      environment);
  if (rendered.result.exitCode == 0) {
    rendered.image = readPng(png);
    rendered.stats = nlohmann::json::parse(std::ifstream(stats));
  }
  return rendered;
}

int maxError(const Image& a, const Image& b) {
  return ImageComparison::compare(a, b, "faulty", "expected").all.maxError;
}

// The fault made one warning, containing `warning`, and nothing else on stderr.
void expectOneWarning(const Rendered& faulty, const std::string& warning) {
  ASSERT_EQ(faulty.result.exitCode, 0) << faulty.result.err;
  EXPECT_EQ(test::lines(faulty.result.err).size(), 1u) << faulty.result.err;
  EXPECT_NE(faulty.result.err.find(warning), std::string::npos) << faulty.result.err;
}

// A light whose shadow GL cannot hold lights as if it cast none. The fallback and the
// expectation are drawn by the same shading program, the fallback with a visibility of exactly
// 1: no tolerance. That the shadow does show without the fault (by far more than a rounding
// step) is what makes the comparison able to fail.
void expectLitWithoutShadow(const std::string& fault, const std::string& method,
                            const std::string& warning) {
  // A map's size for a map (the rays read none).
  const std::string fields = "method " + method + (method == "RAYS" ? "" : " resolution 256");
  const Rendered faulty =
      render("fault_" + fault + "_" + method,
             groupScene("DeepShadowLight", fields, "COIN_BLENDING"), {"IVSHADOW_FAIL_GL=" + fault});
  expectOneWarning(faulty, warning);
  const Rendered unshadowed = render("unshadowed", groupScene("PointLight", "", "COIN_BLENDING"));
  const Rendered shadowed =
      render("shadowed_" + method, groupScene("DeepShadowLight", fields, "COIN_BLENDING"));
  ASSERT_EQ(unshadowed.result.exitCode, 0) << unshadowed.result.err;
  ASSERT_EQ(shadowed.result.exitCode, 0) << shadowed.result.err;
  ASSERT_GT(maxError(shadowed.image, unshadowed.image), 40) << "the scene shows no shadow";
  if (faulty.result.exitCode == 0) EXPECT_EQ(maxError(faulty.image, unshadowed.image), 0);
}

// The one bounce's maps that GL cannot hold: the group renders without the bounce, saying so
// once, as bounce FALSE would draw it (the wall black, which with the bounce shows red).
void expectNoBounce(const std::string& fault, const std::string& warning) {
  std::ifstream file(test::scenesDir() + "/bounce_wall.iv");
  std::stringstream text;
  text << file.rdbuf();
  // GL's bounce (the default, AUTO, traces on a software rasteriser).
  std::string scene = text.str();
  const std::string group = "DEF Room TransparentShadowGroup {";
  scene.insert(scene.find(group) + group.size(), " renderer RASTER");
  const Rendered faulty = render("bounce_" + fault, scene, {"IVSHADOW_FAIL_GL=" + fault});
  ASSERT_EQ(faulty.result.exitCode, 0) << faulty.result.err;
  const std::string& err = faulty.result.err;
  const std::size_t at = err.find(warning);
  ASSERT_NE(at, std::string::npos) << err;
  EXPECT_EQ(err.find(warning, at + 1), std::string::npos) << "said twice: " << err;
  const Rendered bounced = render("bounce", text.str());
  ASSERT_EQ(bounced.result.exitCode, 0) << bounced.result.err;
  // The wall's centre: about 40 of red with the bounce (BounceTest), none without.
  EXPECT_GT(int(bounced.image.pixel(48, 48)[0]), 20);
  EXPECT_EQ(int(faulty.image.pixel(48, 48)[0]), 0);
}

TEST(GlFault, BounceMapsThatDoNotFitRenderWithoutTheBounce) {
  expectNoBounce("texture",
                 "TransparentShadowGroup 'Room': no memory for the imperfect shadow maps "
                 "(GL_OUT_OF_MEMORY (forced by IVSHADOW_FAIL_GL)); rendering without the bounce");
}

TEST(GlFault, AnIncompleteBounceFramebufferRendersWithoutTheBounce) {
  expectNoBounce("framebuffer",
                 "TransparentShadowGroup 'Room': the imperfect shadow maps' framebuffer is "
                 "incomplete (GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT (forced by IVSHADOW_FAIL_GL)); "
                 "rendering without the bounce");
}

TEST(GlFault, MapTexturesThatNeverFitLightWithoutAShadow) {
  expectLitWithoutShadow(
      "texture", "MAP",
      "SoDeepShadowLight \"Lamp\": no deep shadow map fits in GL memory at any resolution; "
      "it lights without a shadow");
}

TEST(GlFault, AnIncompleteMapFramebufferLightsWithoutAShadow) {
  expectLitWithoutShadow("framebuffer", "MAP",
                         "SoDeepShadowLight \"Lamp\": the map's framebuffer is incomplete "
                         "(GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT (forced by IVSHADOW_FAIL_GL)); "
                         "it lights without a shadow");
}

TEST(GlFault, OpacityMapTexturesThatNeverFitLightWithoutAShadow) {
  expectLitWithoutShadow(
      "texture", "OPACITY_MAP",
      "SoDeepShadowLight \"Lamp\": no opacity map fits in GL memory at any resolution; "
      "it lights without a shadow");
}

TEST(GlFault, AnIncompleteOpacityMapFramebufferLightsWithoutAShadow) {
  expectLitWithoutShadow("framebuffer", "OPACITY_MAP",
                         "SoDeepShadowLight \"Lamp\": the opacity map's framebuffer is "
                         "incomplete (GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT (forced by "
                         "IVSHADOW_FAIL_GL)); it lights without a shadow");
}

TEST(GlFault, MapBuffersThatFailLightWithoutAShadow) {
  expectLitWithoutShadow("buffer", "MAP",
                         "SoDeepShadowLight \"Lamp\": GL could not allocate the map's flag buffer "
                         "(GL_OUT_OF_MEMORY (forced by IVSHADOW_FAIL_GL)); it lights without a "
                         "shadow");
}

// A map whose fragment lists GL cannot hold is peeled: one warning, and the same map, so the
// same picture to the bit (the two builds store the same layers, tests/gl/
// MapFragmentListsGLTest.cpp), which shows the shadow.
TEST(GlFault, MapFragmentListsThatFailArePeeledIntoTheSameShadow) {
  const std::string fields = "method MAP resolution 256";
  const Rendered faulty =
      render("fault_list_MAP", groupScene("DeepShadowLight", fields, "COIN_BLENDING"),
             {"IVSHADOW_FAIL_GL=list"});
  expectOneWarning(faulty,
                   "SoDeepShadowLight \"Lamp\": GL could not allocate the fragment lists "
                   "(GL_OUT_OF_MEMORY (forced by IVSHADOW_FAIL_GL)); its map is built by depth "
                   "peeling instead, which keeps only the nearest maxLayers surfaces of a texel "
                   "(layerOverflow TRUNCATE)");
  const Rendered listed =
      render("listed_MAP", groupScene("DeepShadowLight", fields, "COIN_BLENDING"));
  const Rendered unshadowed = render("unshadowed", groupScene("PointLight", "", "COIN_BLENDING"));
  ASSERT_EQ(listed.result.exitCode, 0) << listed.result.err;
  ASSERT_EQ(unshadowed.result.exitCode, 0) << unshadowed.result.err;
  ASSERT_GT(maxError(listed.image, unshadowed.image), 40) << "the scene shows no shadow";
  if (faulty.result.exitCode == 0) EXPECT_EQ(maxError(faulty.image, listed.image), 0);
}

TEST(GlFault, RayCaptureTargetsThatFailLightWithoutAShadow) {
  expectLitWithoutShadow("texture", "RAYS",
                         "SoDeepShadowLight \"Lamp\": GL could not allocate the ray capture "
                         "targets (GL_OUT_OF_MEMORY (forced by IVSHADOW_FAIL_GL)); it lights "
                         "without a shadow");
}

TEST(GlFault, AnIncompleteRayCaptureFramebufferLightsWithoutAShadow) {
  expectLitWithoutShadow("framebuffer", "RAYS",
                         "SoDeepShadowLight \"Lamp\": the ray capture framebuffer is incomplete "
                         "(GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT (forced by IVSHADOW_FAIL_GL)); "
                         "it lights without a shadow");
}

// A group that cannot peel blends its transparency as under COIN_BLENDING. Its light is a
// plain PointLight, which a DEEP_SHADOW_LIGHTS group never shadows: the only GL the fault
// reaches is the peeling's. Both pictures come from the same program and Coin's blending of
// the same fragments: no tolerance.
void expectGroupBlended(const std::string& fault, const std::string& warning) {
  const Rendered faulty = render("group_peel_" + fault, groupScene("PointLight", "", "PEELED"),
                                 {"IVSHADOW_FAIL_GL=" + fault});
  expectOneWarning(faulty, warning);
  const Rendered blended = render("group_blended", groupScene("PointLight", "", "COIN_BLENDING"));
  ASSERT_EQ(blended.result.exitCode, 0) << blended.result.err;
  if (faulty.result.exitCode == 0) EXPECT_EQ(maxError(faulty.image, blended.image), 0);
}

TEST(GlFault, GroupPeelTargetsThatFailAreBlendedByCoin) {
  expectGroupBlended("texture",
                     "TransparentShadowGroup 'Scene': GL could not allocate the peel targets "
                     "(GL_OUT_OF_MEMORY (forced by IVSHADOW_FAIL_GL)); transparency composited "
                     "by Coin, without depth peeling");
}

TEST(GlFault, AnIncompleteGroupPeelFramebufferIsBlendedByCoin) {
  expectGroupBlended("framebuffer",
                     "TransparentShadowGroup 'Scene': the peel framebuffer is incomplete "
                     "(GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT (forced by IVSHADOW_FAIL_GL)); "
                     "transparency composited by Coin, without depth peeling");
}

TEST(GlFault, AGroupPeelBufferThatFailsIsBlendedByCoin) {
  expectGroupBlended("buffer",
                     "TransparentShadowGroup 'Scene': transparency composited by Coin, without "
                     "depth peeling: GL could not "
                     "allocate the peeling's progress buffer (GL_OUT_OF_MEMORY (forced by "
                     "IVSHADOW_FAIL_GL))");
}

// A standalone peeling separator that cannot peel draws as a plain separator does: Coin's
// fixed-function lighting and blending, the same calls. No tolerance.
TEST(GlFault, SeparatorPeelTargetsThatFailDrawAsAPlainSeparator) {
  for (const std::string fault : {"texture", "framebuffer", "buffer"}) {
    SCOPED_TRACE(fault);
    // GL's peeling (the default, AUTO, traces on a software rasteriser).
    std::string scene = separatorScene("PeelingSeparator");
    const std::string separator = "DEF Glass PeelingSeparator {";
    scene.insert(scene.find(separator) + separator.size(), " method FRAGMENT_LISTS");
    const Rendered faulty = render("separator_peel_" + fault, scene, {"IVSHADOW_FAIL_GL=" + fault});
    expectOneWarning(faulty, "PeelingSeparator 'Glass': ");
    const Rendered plain = render("separator_plain", separatorScene("Separator"));
    ASSERT_EQ(plain.result.exitCode, 0) << plain.result.err;
    if (faulty.result.exitCode == 0) EXPECT_EQ(maxError(faulty.image, plain.image), 0);
  }
}

// GL cannot give the camera's fragment lists slots of their own in each pixel: they keep none,
// every fragment in the one linked list, and store the same fragments, so the picture is the
// same to the bit. Two more panes across the whole view put three transparent fragments in
// the pane's pixels and two elsewhere: each pixel's list is linked through the shared
// overflow and sorted by depth, and the overflow (a quarter fragment a pixel to begin with)
// grows once, where four slots of their own hold them all. Nothing is lost but speed: no
// warning.
TEST(GlFault, CameraFragmentListsWithoutSlotsListTheSamePicture) {
  std::string scene = separatorScene("PeelingSeparator");
  const std::string separator = "DEF Glass PeelingSeparator {";
  std::string panes = separator + " method FRAGMENT_LISTS\n";
  // Of different colours, so that their order shows.
  const std::pair<const char*, const char*> wide[] = {{"0.5", "0.1 0.9 0.2"},
                                                      {"1.5", "0.1 0.2 0.9"}};
  for (const auto& [z, colour] : wide)
    panes += std::string("    Material { diffuseColor ") + colour +
             " transparency 0.6 }\n    Coordinate3 { point [ -3 -3 " + z + ", 3 -3 " + z +
             ", 3 3 " + z + ", -3 3 " + z + " ] }\n    FaceSet { numVertices 4 }\n";
  scene.replace(scene.find(separator), separator.size(), panes);
  const Rendered faulty = render("slots_none", scene, {"IVSHADOW_FAIL_GL=slots"});
  const Rendered slotted = render("slots", scene);
  ASSERT_EQ(faulty.result.exitCode, 0) << faulty.result.err;
  ASSERT_EQ(slotted.result.exitCode, 0) << slotted.result.err;
  EXPECT_EQ(faulty.result.err, "");
  EXPECT_EQ(slotted.stats["list_slots"], 4);
  EXPECT_EQ(slotted.stats["list_passes"], 1);
  EXPECT_EQ(faulty.stats["list_slots"], 0);
  EXPECT_EQ(faulty.stats["list_passes"], 2);
  // Every pixel sees the two wide panes; the small one adds its own.
  EXPECT_GT(faulty.stats["list_fragments"].get<long long>(), 2LL * 96 * 96);
  EXPECT_EQ(faulty.stats["list_fragments"], slotted.stats["list_fragments"]);
  EXPECT_EQ(maxError(faulty.image, slotted.image), 0);
}

// Without an Embree device a RAYS light keeps its deep shadow map: the same picture as
// method MAP, drawn by the same code. No tolerance.
TEST(GlFault, WithoutAnEmbreeDeviceARaysLightUsesItsMap) {
  const Rendered faulty =
      render("embree_device", groupScene("DeepShadowLight", "method RAYS", "COIN_BLENDING"),
             {"IVSHADOW_FAIL_EMBREE=device"});
  expectOneWarning(faulty,
                   "light 'Lamp': cannot trace shadow rays (Embree could not create a device "
                   "(forced by IVSHADOW_FAIL_EMBREE=device)); using its deep shadow map");
  const Rendered mapped =
      render("embree_map", groupScene("DeepShadowLight", "method MAP", "COIN_BLENDING"));
  const Rendered unshadowed =
      render("embree_unshadowed", groupScene("PointLight", "", "COIN_BLENDING"));
  ASSERT_EQ(mapped.result.exitCode, 0) << mapped.result.err;
  ASSERT_EQ(unshadowed.result.exitCode, 0) << unshadowed.result.err;
  ASSERT_GT(maxError(mapped.image, unshadowed.image), 40) << "the scene shows no shadow";
  if (faulty.result.exitCode == 0) EXPECT_EQ(maxError(faulty.image, mapped.image), 0);
}

// A misspelt knob forces nothing, and says so rather than passing a test that forced nothing.
TEST(GlFault, AnUnknownWordOfTheKnobIsReported) {
  const Rendered faulty =
      render("unknown_word", groupScene("DeepShadowLight", "method MAP", "COIN_BLENDING"),
             {"IVSHADOW_FAIL_GL=textures"});
  ASSERT_EQ(faulty.result.exitCode, 0) << faulty.result.err;
  EXPECT_NE(faulty.result.err.find("IVSHADOW_FAIL_GL: 'textures' is none of texture, buffer, "
                                   "framebuffer, list, slots; ignored"),
            std::string::npos)
      << faulty.result.err;
}

// Issue 35: without a device a RAYS light falls back to its map and says so; its group's
// bounce, placed with Embree whatever the method, was then dropped without a word (the
// warning was said once per light, whatever it said).
TEST(GlFault, WithoutAnEmbreeDeviceTheDroppedBounceIsSaidToo) {
  std::string scene = groupScene("DeepShadowLight", "method RAYS", "COIN_BLENDING");
  const std::string group = "castingLights DEEP_SHADOW_LIGHTS";
  scene.replace(scene.find(group), group.size(), group + " bounce TRUE");
  const Rendered faulty = render("embree_bounce", scene, {"IVSHADOW_FAIL_EMBREE=device"});
  ASSERT_EQ(faulty.result.exitCode, 0) << faulty.result.err;
  EXPECT_NE(faulty.result.err.find("using its deep shadow map"), std::string::npos)
      << faulty.result.err;
  EXPECT_NE(faulty.result.err.find("light 'Lamp': cannot trace shadow rays (Embree could not "
                                   "create a device (forced by IVSHADOW_FAIL_EMBREE=device)); the "
                                   "group renders without its bounce"),
            std::string::npos)
      << faulty.result.err;
}

TEST(GlFault, AnUnknownValueOfTheEmbreeKnobIsReported) {
  const Rendered faulty =
      render("embree_unknown", groupScene("DeepShadowLight", "method RAYS", "COIN_BLENDING"),
             {"IVSHADOW_FAIL_EMBREE=devices"});
  ASSERT_EQ(faulty.result.exitCode, 0) << faulty.result.err;
  EXPECT_NE(faulty.result.err.find("IVSHADOW_FAIL_EMBREE: 'devices' is not device; ignored"),
            std::string::npos)
      << faulty.result.err;
  EXPECT_EQ(faulty.result.err.find("cannot trace shadow rays"), std::string::npos);
}

}  // namespace
}  // namespace ivshadow
