#pragma once

#include "gl/GlPassTimer.h"
#include "scene/ShadowTypes.h"

#include <Inventor/SbBox3f.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

class SoGLRenderAction;
class SoState;

namespace ivshadow {

class GroupContents;
class GroupShading;
class RayCasters;
class RayShadowPass;
class ShadowVolumePass;
class ShadowVolumes;
struct DeepShadowStatistics;
struct MapState;

// The screen-space methods of one group in one GL context, RAYS and VOLUMES: captures the
// surfaces the camera sees of the group's children (the capture variants of the group's
// shading), traces one shadow ray per surface and RAYS light through the group's casters
// (RayCasters, on the process's one Embree device), draws each VOLUMES light's shadow volumes
// against the same surfaces (ShadowVolumes, ShadowVolumePass) and hands the visibility to the
// shading pass (RayShadowPass). A frame whose
// view, lights and casters are unchanged reuses the last trace; one where only lights changed
// reuses the captured surfaces and traces them again.
class RayMethod {
 public:
  // Draws the group's children, as the group does.
  using ChildrenRenderer = std::function<void(SoGLRenderAction*, bool inPath)>;

  // `textureUnit`: the first unit of the shading pass's ray textures (DeepShadowPass).
  explicit RayMethod(int textureUnit);
  ~RayMethod();
  RayMethod(const RayMethod&) = delete;
  RayMethod& operator=(const RayMethod&) = delete;

  // Captures (unless the view and what is drawn are unchanged) and traces again unless
  // nothing the last trace depends on has changed; records times and counts in `statistics`.
  // Empty, or what GL said when the capture targets or the traced shadows' textures could not
  // be allocated: then no shadow is traced or bound (the RAYS lights light without one) until
  // a change asks for a new trace.
  std::string update(SoGLRenderAction* action, const GroupContents& contents, GroupShading& shading,
                     const RayCasters& casters, const std::vector<MapState>& maps,
                     const ChildrenRenderer& renderChildren, bool inPath,
                     DeepShadowStatistics& statistics);
  // The traced visibility as the shading pass binds it.
  RayShadowPass& pass() { return *pass_; }
  // Whether VOLUMES lights can be drawn in this context (the pass is made on first asking);
  // else why not, and the caller gives them another method.
  bool volumesAvailable(std::string& whyNot);
  // After update(): empty, or why the last frame's VOLUMES lights got no shadow (GL could not
  // allocate what the volumes need); the other lights are not affected.
  const std::string& volumeFailure() const { return volumeFailure_; }

 private:
  // What the captured surfaces depend on: the view and what the children draw. The casters'
  // version moves with every change below the group but a light's or a camera's, and with
  // the state the group inherits; a camera inside the group moves the view version. Lights
  // change nothing a capture holds (positions, normals, depths).
  struct CaptureKey {
    std::uint64_t castersVersion = 0;
    std::uint64_t viewVersion = 0;
    std::array<int, 4> viewport{};
    std::array<float, 48> matrices{};  // viewing, projection, model
    bool operator==(const CaptureKey& o) const {
      return castersVersion == o.castersVersion && viewVersion == o.viewVersion &&
             viewport == o.viewport && matrices == o.matrices;
    }
  };
  // What a trace depends on: the captured surfaces and the lights and casters (the maps'
  // version). An equal key reuses the last trace.
  struct TraceKey {
    CaptureKey capture;
    std::uint64_t mapsVersion = 0;
    bool operator==(const TraceKey& o) const {
      return capture == o.capture && mapsVersion == o.mapsVersion;
    }
  };

  // Draws the children into the capture targets and reads their surface layers back into
  // surfaces_ (capturedLayers_ of them). Empty, or why the targets could not be made (then
  // no layer is captured).
  std::string capture(SoGLRenderAction* action, const GroupContents& contents,
                      GroupShading& shading, const ChildrenRenderer& renderChildren, bool inPath,
                      DeepShadowStatistics& statistics);

  // Draws the VOLUMES lights' volumes into the visibility upload() sized, with the view the
  // group's shading found (a camera inside the group included); sets volumeFailure_.
  void drawVolumes(SoState* state, const GroupShading& shading, const GroupContents& contents,
                   const std::vector<MapState>& maps, DeepShadowStatistics& statistics);

  std::unique_ptr<RayShadowPass> pass_;
  int textureUnit_ = 0;
  // The casters' volumes per colour model (ShadowColourModel), and the casters' version they
  // were made of.
  struct Volumes {
    std::uint64_t version = 0;
    std::unique_ptr<ShadowVolumes> volumes;
  };
  std::array<Volumes, 3> volumes_;
  std::unique_ptr<ShadowVolumePass> volumePass_;
  std::string volumePassFailure_;  // set once the pass could not be made in this context
  std::string volumeFailure_;
  std::size_t warnedApproximated_ = 0;  // the count of triangles last warned about
  std::vector<VolumeVertex> faces_;
  GlPassTimer captureTimer_;
  // The last capture and the last trace's visibility, kept so that a trace of the same view
  // needs no capture and so that their memory is reused.
  std::vector<SurfaceLayer> surfaces_;
  std::size_t capturedLayers_ = 0;
  SbBox3f receivers_;  // the captured surfaces' bounds, which the shadow volumes must reach
  std::vector<std::uint16_t> visibility_;
  TraceKey traced_;
  bool traceValid_ = false;
};

}  // namespace ivshadow
