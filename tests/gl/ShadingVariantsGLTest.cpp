// The shading is compiled with only the parts a frame needs (nodes/ShadingProgram.h,
// ShadingFeatures, says why). A probe inside the group reads, while the group's program is
// bound, which parts' uniforms that program has: a uniform GL reports active is one the
// compiled code reads.
#include "image_files/ImageComparison.h"
#include "tests/gl/GlContextTest.h"
#include "tests/gl/ShadowScene.h"

#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/nodes/SoCallback.h>
#include <Inventor/nodes/SoSeparator.h>
#include <epoxy/gl.h>

#include <functional>
#include <set>
#include <string>
#include <tuple>

namespace ivshadow::test {
namespace {

// The parts each marker uniform belongs to (gl/glsl/lighting.glsl).
struct Parts {
  bool maps = false;  // uMapDepth: deep shadow map lookups
  bool rays = false;  // uRayDepth: traced visibility
  bool fog = false;   // uFogType: fog
  bool operator<(const Parts& o) const {
    return std::tie(maps, rays, fog) < std::tie(o.maps, o.rays, o.fog);
  }
  bool operator==(const Parts& o) const {
    return std::tie(maps, rays, fog) == std::tie(o.maps, o.rays, o.fog);
  }
};

void probe(void* data, SoAction* action) {
  if (!action->isOfType(SoGLRenderAction::getClassTypeId())) return;
  GLint program = 0;
  glGetIntegerv(GL_CURRENT_PROGRAM, &program);
  const GLuint name = GLuint(program);
  // The RAYS captures draw with programs that light nothing: not the shading.
  if (name == 0 || glGetUniformLocation(name, "uLightCount") < 0) return;
  static_cast<std::set<Parts>*>(data)->insert(Parts{glGetUniformLocation(name, "uMapDepth") >= 0,
                                                    glGetUniformLocation(name, "uRayDepth") >= 0,
                                                    glGetUniformLocation(name, "uFogType") >= 0});
}

class ShadingVariantsGLTest : public GlContextTest {
 protected:
  // The parts of every program bound where the probe stands (after the filters, in the
  // group), over two frames (the first builds, the second reuses); `edit` changes the text.
  std::set<Parts> partsOf(const ShadowScene& scene,
                          const std::function<void(std::string&)>& edit = {}) {
    ShadowScene probed = scene;
    probed.groupNodes += " DEF Probe Callback {}";
    std::string text = probed.text();
    if (edit) edit(text);
    SoSeparator* root = readIv(text);
    std::set<Parts> seen;
    static_cast<SoCallback*>(SoNode::getByName("Probe"))->setCallback(probe, &seen);
    for (int frame = 0; frame < 2; ++frame) renderer().render(root);
    picture_ = renderer().read();
    root->unref();
    return seen;
  }
  Image picture_;
};

ShadowScene glassScene(const std::string& method) {
  ShadowScene scene;
  scene.filters = {kRedGlass};
  scene.method = method;
  return scene;
}

TEST_F(ShadingVariantsGLTest, AMapLightCompilesTheMapLookupAlone) {
  EXPECT_EQ(partsOf(glassScene("MAP")), (std::set<Parts>{{true, false, false}}));
}

TEST_F(ShadingVariantsGLTest, ATracedLightCompilesTheTracedLookupAlone) {
  EXPECT_EQ(partsOf(glassScene("RAYS")), (std::set<Parts>{{false, true, false}}));
}

TEST_F(ShadingVariantsGLTest, FogAboveTheGroupCompilesFogIn) {
  ShadowScene scene = glassScene("MAP");
  scene.aboveGroup = "Environment { fogType HAZE fogVisibility 20 }";
  EXPECT_EQ(partsOf(scene), (std::set<Parts>{{true, false, true}}));
}

// Two lights, one with each method: both lookups are compiled into one program, and each
// light gets its own shadow: the picture is the one two map lights at the same places give,
// within one 8-bit step (the map and the rays each agree with the analytic picture to that on
// this filter: DeepShadow's and RayShadow's analytic catalogues). The second light stands
// 0.05 aside, beyond the shading's 1e-3 match of a GL light to its slot, so that it is found
// as itself and not as the first.
TEST_F(ShadingVariantsGLTest, AMapAndATracedLightShareOneProgramWithBothLookups) {
  ShadowScene scene = glassScene("MAP");
  scene.lightCount = 2;
  const std::string second = "DEF Lamp1 DeepShadowLight { location 0 0 1 intensity 0.5 method MAP";
  const auto aside = [&second](const std::string& method) {
    return [&second, method](std::string& text) {
      ASSERT_NE(text.find(second), std::string::npos);
      text.replace(text.find(second), second.size(),
                   "DEF Lamp1 DeepShadowLight { location 0.05 0 1 intensity 0.5 method " + method);
    };
  };
  EXPECT_EQ(partsOf(scene, aside("MAP")), (std::set<Parts>{{true, false, false}}));
  const Image twoMaps = picture_;
  EXPECT_EQ(partsOf(scene, aside("RAYS")), (std::set<Parts>{{true, true, false}}));
  EXPECT_LE(ImageComparison::compare(picture_, twoMaps, "mixed", "maps").all.maxError, 1);
  // The comparison above can tell the lights apart: with the second light at the first's
  // place, the picture differs from twoMaps in the 5-pixel strip where only one of the two
  // shadows falls. There half the light (intensity 0.5) passes the red glass or not, tens of
  // steps of green and blue; 10 is far above the one step the two methods may differ by.
  partsOf(scene);
  EXPECT_GT(ImageComparison::compare(picture_, twoMaps, "together", "aside").all.maxError, 10);
}

}  // namespace
}  // namespace ivshadow::test
