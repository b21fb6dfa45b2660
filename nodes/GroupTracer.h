#pragma once

#include "nodes/PerContext.h"
#include "nodes/SceneTracer.h"

#include <Inventor/SbMatrix.h>

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

class SoGLRenderAction;
class SoSeparator;

namespace ivshadow {

class GroupContents;
class TracedPicturePass;
struct DeepShadowStatistics;

// A SoTransparentShadowGroup whose renderer is TRACER: its subgraph's triangles are traced
// on the CPU (SceneTracer: exact shadows and exact glass in one pass, from the depth GL drew
// before the group on) and the picture is handed to the framebuffer with its depth
// (TracedPicturePass). The subgraph is read again when it changes (its shapes or the
// inherited state), only its lights when they or the camera moved; the picture is traced again when
// the subgraph, the camera, the viewport or the depth drawn before it changed, else the one kept is
// drawn.
class GroupTracer {
 public:
  explicit GroupTracer(SoSeparator* owner);
  ~GroupTracer();
  GroupTracer(const GroupTracer&) = delete;
  GroupTracer& operator=(const GroupTracer&) = delete;

  // Draws the owner's subgraph traced, in the state `action` is in at the owner; false, with
  // one warning, when this context cannot draw the picture (the caller renders the group as
  // GL does).
  bool render(SoGLRenderAction* action, const GroupContents& contents,
              DeepShadowStatistics& statistics);

 private:
  struct Context {
    std::unique_ptr<TracedPicturePass> pass;
    // What the picture uploaded last was traced for.
    std::uint64_t scene = 0;
    SbMatrix viewing;
    SbMatrix projection;
    std::array<int, 4> viewport{};
    std::vector<float> depthTraced;  // the depth GL had drawn before the group
    std::vector<float> depthNow;     // read this frame
  };

  // Reads the subgraph again when it changed since the last read, or only its lights when
  // only they (or the camera) changed.
  void updateScene(SoGLRenderAction* action, const GroupContents& contents,
                   DeepShadowStatistics& statistics);

  SoSeparator* owner_;
  std::unique_ptr<SceneTracer> scene_;
  std::uint64_t sceneVersion_ = 0;  // counts the reads
  std::uint64_t castersVersion_ = ~std::uint64_t(0);
  std::uint64_t mapsVersion_ = ~std::uint64_t(0);
  std::uint64_t viewVersion_ = ~std::uint64_t(0);
  SbMatrix sceneViewing_;  // lights fixed in eye space were placed with it
  SbMatrix sceneProjection_;
  // The state above the group the subgraph was read in (stateAbove), and this frame's.
  std::vector<float> lightsAbove_, shadingAbove_, lightsNow_, shadingNow_;
  PerContext<Context> contexts_;
  TracedPixels pixels_;
};

}  // namespace ivshadow
