// What the passes give GPU tools. Timers: their results are waited for only while someone
// reads the timings, so a map build, which is always timed, does not stall the CPU on its
// timer otherwise, and its figure still comes, from the latest build GL has finished. Debug
// groups and labels: each pass's commands grouped and its objects named for a GPU debugger.
#include "gl/GlHandles.h"
#include "ivshadow/DeepShadowStatistics.h"
#include "ivshadow/SoDeepShadowLight.h"
#include "tests/gl/GlCallCounter.h"
#include "tests/gl/GlContextTest.h"
#include "tests/gl/ShadowScene.h"

#include <Inventor/nodes/SoSeparator.h>
#include <epoxy/gl.h>

#include <algorithm>
#include <string>
#include <vector>

namespace ivshadow::test {
namespace {

// Pass timing on while it lives, as `ivshadow render --stats` and the viewer turn it on.
struct PassTimingOn {
  PassTimingOn() { setPassTiming(true); }
  ~PassTimingOn() { setPassTiming(false); }
};

class PassInstrumentsGLTest : public GlContextTest {
 protected:
  void SetUp() override {
    GlContextTest::SetUp();
    ShadowScene scene;  // a map (RASTER, method MAP) of red glass over the floor
    scene.filters = {kRedGlass};
    root_ = readIv(scene.text());
    lamp_ = static_cast<SoDeepShadowLight*>(SoNode::getByName("Lamp"));
    ASSERT_NE(lamp_, nullptr);
    renderer().render(root_);  // links the programs and builds the map once
  }
  void TearDown() override {
    if (root_ != nullptr) root_->unref();
    GlContextTest::TearDown();
  }
  // A frame in which the map is built again: the light moved.
  DeepShadowStatistics rebuild() {
    const SbVec3f place = lamp_->location.getValue();
    lamp_->location = place + SbVec3f(0.01f, 0.0f, 0.0f);
    renderer().render(root_);
    return collectDeepShadowStatistics(root_);
  }

  SoSeparator* root_ = nullptr;
  SoDeepShadowLight* lamp_ = nullptr;
};

bool holds(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

std::string listed(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += "\n  " + name;
  return text;
}

int groupDepth() {
  GLint depth = 0;
  glGetIntegerv(GL_DEBUG_GROUP_STACK_DEPTH, &depth);
  return depth;
}

TEST_F(PassInstrumentsGLTest, WithoutPassTimingARebuildWaitsForNoTimer) {
  ASSERT_FALSE(passTiming());
  GlCallCounter counter;
  const int before = collectDeepShadowStatistics(root_).rebuilds;
  const DeepShadowStatistics stats = rebuild();
  EXPECT_EQ(stats.rebuilds, before + 1) << "the counted frame built no map";
  EXPECT_EQ(counter.resultWaits(), 0);
}

// The counter sees the waits it is to find: with the timings asked for, the build's timer
// (and the shading's) are read as soon as they stop, before the GPU has reached them.
TEST_F(PassInstrumentsGLTest, WithPassTimingARebuildWaitsForItsTimer) {
  const PassTimingOn timing;
  GlCallCounter counter;
  const DeepShadowStatistics stats = rebuild();
  EXPECT_GT(counter.resultWaits(), 0);
  EXPECT_GT(stats.gpuBuildMs, 0.0);
}

// Unwaited, a build's figure is the latest GL had finished: the frame before's, whose
// commands the headless renderer waited for at its end.
TEST_F(PassInstrumentsGLTest, WithoutPassTimingTheBuildTimeComesFromTheBuildBefore) {
  rebuild();
  EXPECT_GT(rebuild().gpuBuildMs, 0.0);
}

// A frame of the group (PEELED, the default) that builds its map: the build, the opaque pass
// and the transparent surfaces' pass (fragment lists, or depth peeling where they cannot be
// had) each show as a group, and every group is closed again (the stack holds only GL's own
// default group after the frame; a pop too many would be GL_STACK_UNDERFLOW, which the
// renderer's error check reports).
TEST_F(PassInstrumentsGLTest, EveryPassOfAFrameIsADebugGroup) {
  GlCallCounter counter;
  rebuild();
  const std::vector<std::string>& groups = counter.debugGroups();
  EXPECT_TRUE(holds(groups, "ivshadow deep shadow map build, light 0")) << listed(groups);
  EXPECT_TRUE(holds(groups, "ivshadow opaque pass (peeling's first)")) << listed(groups);
  EXPECT_TRUE(holds(groups, "ivshadow fragment list pass") ||
              holds(groups, "ivshadow depth peeling"))
      << listed(groups);
  EXPECT_EQ(groupDepth(), 1);
}

TEST_F(PassInstrumentsGLTest, ATracedLightsCaptureIsADebugGroup) {
  lamp_->set("method RAYS");
  GlCallCounter counter;
  rebuild();
  const std::vector<std::string>& groups = counter.debugGroups();
  EXPECT_TRUE(holds(groups, "ivshadow ray capture")) << listed(groups);
  EXPECT_TRUE(holds(groups, "ivshadow ray capture layer 0")) << listed(groups);
  EXPECT_EQ(groupDepth(), 1);
}

TEST_F(PassInstrumentsGLTest, ObjectsAreLabelledAndGroupsNest) {
  GlTexture texture = createTexture(GL_TEXTURE_2D);
  labelGlObject(GL_TEXTURE, texture.get(), "test texture");
  char label[64] = {};
  GLsizei length = 0;
  glGetObjectLabel(GL_TEXTURE, texture.get(), sizeof(label), &length, label);
  EXPECT_EQ(std::string(label, std::size_t(length)), "ivshadow test texture");
  {
    const GlDebugGroup outer("outer");
    const GlDebugGroup inner("inner");
    EXPECT_EQ(groupDepth(), 3);
  }
  EXPECT_EQ(groupDepth(), 1);
}

}  // namespace
}  // namespace ivshadow::test
