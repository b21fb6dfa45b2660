#pragma once

#include "callbacks/GlPassTimer.h"
#include "scene/ShadowTypes.h"

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
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
// view, lights and casters are unchanged reuses the last trace.
class RayMethod {
 public:
  // Draws the group's children, as the group does.
  using ChildrenRenderer = std::function<void(SoGLRenderAction*, bool inPath)>;

  // `textureUnit`: the first unit of the shading pass's ray textures (DeepShadowPass).
  explicit RayMethod(int textureUnit);
  ~RayMethod();
  RayMethod(const RayMethod&) = delete;
  RayMethod& operator=(const RayMethod&) = delete;

  // Captures and traces again unless nothing the last trace depends on has changed; records
  // times and counts in `statistics`.
  void update(SoGLRenderAction* action, const GroupContents& contents, GroupShading& shading,
              const RayCasters& casters, const std::vector<MapState>& maps,
              const ChildrenRenderer& renderChildren, bool inPath,
              DeepShadowStatistics& statistics);
  // The traced visibility as the shading pass binds it.
  RayShadowPass& pass() { return *pass_; }

 private:
  // What a trace depends on: an equal key reuses the last trace.
  struct TraceKey {
    std::uint64_t mapsVersion = 0;
    std::uint64_t viewVersion = 0;
    std::array<int, 4> viewport{};
    std::array<float, 48> matrices{};  // viewing, projection, model
    bool operator==(const TraceKey& o) const {
      return mapsVersion == o.mapsVersion && viewVersion == o.viewVersion &&
             viewport == o.viewport && matrices == o.matrices;
    }
  };

  std::unique_ptr<RayShadowPass> pass_;
  GlPassTimer captureTimer_;
  // The last trace's captures and visibility, kept so that their memory is reused.
  std::vector<SurfaceLayer> surfaces_;
  std::vector<std::uint16_t> visibility_;
  TraceKey traced_;
  bool traceValid_ = false;
};

}  // namespace ivshadow
