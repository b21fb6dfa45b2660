#pragma once

#include "gl/KeptFrame.h"
#include "nodes/PerContext.h"
#include "raytrace/SceneTracer.h"

#include <Inventor/SbBox3f.h>
#include <Inventor/SbMatrix.h>
#include <Inventor/SbVec2s.h>
#include <Inventor/sensors/SoAlarmSensor.h>

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

class SoGLRenderAction;
class SoSeparator;
class SoState;

namespace ivshadow {

class GroupContents;
class TracedPicturePass;
struct DeepShadowStatistics;

// What the owner asks of its traces.
struct TracerSettings {
  float movingResolution = 1.0f;  // the fraction of the viewport a frame of a motion traces
  int bounceSamples = 0;          // bounce rays per pixel (0: no bounce)
};

// A SoTransparentShadowGroup whose renderer is TRACER, or a SoPeelingSeparator whose method
// is: its subgraph's triangles are traced on the CPU (SceneTracer: exact shadows and exact
// glass in one pass, from the depth GL drew before the owner on) and the picture is handed to
// the framebuffer with its depth (TracedPicturePass). The subgraph is read again when it
// changes (its shapes or the inherited state), only its lights when they or the camera moved;
// the picture is traced again when the subgraph, the camera, the viewport or the depth drawn
// before it changed, else the one kept is drawn (and while what GL drew before it stays the
// same, the framebuffer that left is put back by a blit: KeptFrame). While the scene moves (a frame
// traces right after one that traced) the picture is traced at the settings' movingResolution and
// refined, in full, by the first frame that finds nothing changed; the tracer schedules that frame
// itself (kRefineDelaySeconds after the last reduced one) by touching its owner. Shapes drawn with
// lines, points or screen-aligned pixels, which have no triangles to trace, are drawn through GL
// after the picture (a second render action over their paths), depth-tested against it.
class GroupTracer {
 public:
  // `setting` names what made `owner` trace, for its messages ("renderer TRACER").
  GroupTracer(SoSeparator* owner, const char* setting);
  ~GroupTracer();
  GroupTracer(const GroupTracer&) = delete;
  GroupTracer& operator=(const GroupTracer&) = delete;

  // Draws the owner's subgraph traced, in the state `action` is in at the owner; false, with
  // one warning, when this context cannot draw the picture (the caller renders the group as
  // GL does).
  bool render(SoGLRenderAction* action, const GroupContents& contents,
              const TracerSettings& settings, DeepShadowStatistics& statistics);
  // Called by the owner when the render action that draws its untraced shapes reaches it:
  // writes the picture's depth again (once), since the nodes above the owner that this action
  // traverses again to set the state may have cleared the depth buffer (FreeCAD's saveImage
  // clears it in a callback after its background), and the shapes must be hidden by the
  // picture's surfaces.
  void restoreDepth(SoGLRenderAction* action);

 private:
  struct Context {
    std::unique_ptr<TracedPicturePass> pass;
    // What the picture uploaded last was traced for.
    std::uint64_t scene = 0;
    std::uint64_t shapes = 0;  // the read of the shapes it was traced with
    SbMatrix viewing;
    SbMatrix projection;
    std::array<int, 4> viewport{};
    std::vector<float> depthTraced;   // the depth GL had drawn before the group
    std::vector<float> depthNow;      // read this frame, when not the one traced at
    std::vector<float> depthReduced;  // depthNow at a reduced picture's pixels
    bool reduced = false;             // the picture kept was traced at movingResolution
    // The pixels the picture may change, {x0, y0, x1, y1} in the viewport: the box around the
    // triangles as its camera sees them (scene/ScreenBox.h). Elsewhere it leaves what GL drew.
    std::array<int, 4> region{};
    bool tracedLastFrame = false;  // the previous frame traced for a change (a motion)
    // The surfaces the picture's camera rays met: composited again when only the lights
    // changed.
    SurfacesMet surfaces;
    // The framebuffer the picture left, put back while nothing changes.
    KeptFrame frame;
  };

  // Where and how this frame looks at the subgraph.
  struct View {
    std::array<int, 4> viewport{};  // x, y, width, height
    const SbMatrix* viewing = nullptr;
    const SbMatrix* projection = nullptr;
  };
  // What this frame's trace follows.
  struct Motion {
    bool moving;         // a change right after a frame that traced for one
    bool sameView;       // the camera rays meet the surfaces kept
    bool depthAsTraced;  // GL drew the depth the picture was traced at
  };

  // The picture's resources in the current context; null, with one warning, when the context
  // cannot draw a traced picture.
  Context* contextFor(SoState* state);
  // Reads what GL drew before the group over `view`'s viewport (where the picture, if traced
  // for this view and not to be reduced, `mayReduce`, may change it): true when its depth is
  // the one the picture was traced at (context.depthTraced), else the depth is read into
  // context.depthNow.
  bool readWhatGlDrew(Context& context, const View& view, bool mayReduce);
  // Traces the picture for `view` and uploads it; false, with one warning, when GL cannot hold
  // it.
  bool tracePicture(Context& context, const View& view, const Motion& motion,
                    const TracerSettings& settings, DeepShadowStatistics& statistics);
  // Hands the picture to the framebuffer (the kept frame put back, or the picture composited)
  // and draws the untraced shapes after it.
  void present(SoGLRenderAction* action, Context& context, const std::array<int, 4>& viewport,
               bool traced);
  // The depth limit of a picture of `width` x `height` pixels over the viewport whose window
  // depths are `depth`: each pixel's centre's depth.
  static const float* reducedLimit(Context& context, const std::vector<float>& depth,
                                   const std::array<int, 4>& viewport, int width, int height);
  static void refine(void* self, SoSensor*);
  // Draws the shapes drawn with lines, points or screen-aligned pixels through GL, after the
  // picture, depth-tested against it.
  void drawUntraced(SoGLRenderAction* action);

  // Reads the subgraph again when it changed since the last read, or only its lights when
  // only they (or the camera) changed.
  void updateScene(SoGLRenderAction* action, const GroupContents& contents,
                   DeepShadowStatistics& statistics);

  SoSeparator* owner_;
  const char* setting_;
  // While drawUntraced runs: the picture to write the depth of again, and where.
  const Context* drawingUntraced_ = nullptr;
  std::array<int, 4> untracedViewport_{};
  std::array<int, 4> untracedRegion_{};
  std::unique_ptr<SceneTracer> scene_;
  SbBox3f bounds_;                   // scene_'s triangles, in the world
  std::uint64_t sceneVersion_ = 0;   // counts the reads
  std::uint64_t shapesVersion_ = 0;  // counts the reads of the shapes (not of lights alone)
  std::uint64_t castersVersion_ = ~std::uint64_t(0);
  std::uint64_t mapsVersion_ = ~std::uint64_t(0);
  std::uint64_t viewVersion_ = ~std::uint64_t(0);
  SbMatrix sceneViewing_;  // lights fixed in eye space were placed with it
  SbMatrix sceneProjection_;
  SbVec2s readSize_{0, 0};  // the viewport's size when the subgraph was read
  // The state above the group the subgraph was read in (stateAbove), and this frame's.
  std::vector<float> lightsAbove_, shadingAbove_, lightsNow_, shadingNow_;
  PerContext<Context> contexts_;
  TracedPixels pixels_;
  SoAlarmSensor refineSensor_;
  // The length of the path to the owner the subgraph was read through: the untraced shapes'
  // paths below it are drawn from the path of the frame's own action.
  int readPathLength_ = 0;
};

}  // namespace ivshadow
