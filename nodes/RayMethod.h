#pragma once

#include "callbacks/GlPassTimer.h"
#include "scene/ShadowTypes.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

class SoGLRenderAction;

namespace ivshadow {

class GroupContents;
class GroupShading;
class RayCasters;
class RayShadowPass;
struct DeepShadowStatistics;
struct MapState;

// The RAYS method of one group in one GL context: captures the surfaces the camera sees of
// the group's children (the capture variants of the group's shading), traces one shadow ray
// per surface and RAYS light through the group's casters (RayCasters, on the process's one
// Embree device) and hands the visibility to the shading pass (RayShadowPass). A frame whose
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

  std::unique_ptr<RayShadowPass> pass_;
  GlPassTimer captureTimer_;
  // The last capture and the last trace's visibility, kept so that a trace of the same view
  // needs no capture and so that their memory is reused.
  std::vector<SurfaceLayer> surfaces_;
  std::size_t capturedLayers_ = 0;
  std::vector<std::uint16_t> visibility_;
  TraceKey traced_;
  bool traceValid_ = false;
};

}  // namespace ivshadow
