#pragma once

#include "callbacks/GlPassTimer.h"
#include "callbacks/ShadingUniforms.h"
#include "ivshadow/DeepShadowStatistics.h"
#include "ivshadow/Export.h"
#include "nodes/DeepShadowSettings.h"
#include "nodes/PerContext.h"
#include "nodes/ShadingProgram.h"
#include "raytrace/CasterScene.h"
#include "raytrace/EmbreeHandles.h"
#include "raytrace/ScreenShadowTracer.h"
#include "scene/CoinRef.h"
#include "scene/SceneTriangles.h"

#include <Inventor/SbMatrix.h>
#include <Inventor/SbVec3f.h>

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <set>
#include <string>
#include <vector>

class SoDeepShadowLight;
class SoGLRenderAction;
class SoNotList;
class SoPath;
class SoState;
class SoSeparator;

namespace ivshadow {

class DeepShadowPass;
class RayShadowPass;

// The work behind SoTransparentShadowGroup: finds the deep shadow lights, keeps the casters
// and the maps up to date per GL context, and renders the children with the shading program.
// SoPeelingSeparator uses it too, without shadows, for the shading of its layers.
class TransparentShadowGroupImpl {
 public:
  // Draws the owner's children (once or, for peeling, several times).
  using ChildrenRenderer = std::function<void(SoGLRenderAction*, bool inPath)>;

  // `deepShadows` false: deep shadow lights are plain point lights here.
  TransparentShadowGroupImpl(SoSeparator* owner, bool deepShadows, ChildrenRenderer renderChildren);
  ~TransparentShadowGroupImpl();
  TransparentShadowGroupImpl(const TransparentShadowGroupImpl&) = delete;
  TransparentShadowGroupImpl& operator=(const TransparentShadowGroupImpl&) = delete;

  // Renders the group with shadows; returns false when this context cannot (the caller then
  // renders it as a plain separator).
  bool render(SoGLRenderAction* action, bool inPath);
  void changed(SoNotList* list);
  const DeepShadowStatistics& statistics() const { return statistics_; }
  // The innermost group with deep shadows rendering its children right now on this thread,
  // or null: a peeling separator inside one shades its layers with that group's shading.
  IVSHADOW_INTERNAL static TransparentShadowGroupImpl* activeGroup();
  // True while a group draws its children into the capture targets of RAYS lights: a
  // peeling separator then draws its children plainly, with the group's capture program.
  IVSHADOW_INTERNAL static bool capturing();

  // While the children render: binds the peel-pass variant of the shading program (through
  // Coin, in the action's current state) with the same uniforms, and returns its GL name
  // (0 when it failed to build).
  unsigned int bindPeelProgram(SoGLRenderAction* action);

 private:
  struct Light {
    CoinRef<SoPath> path;  // from the group to the light
    SoDeepShadowLight* light = nullptr;
  };
  struct MapState {
    SbVec3f position;
    DeepShadowSettings settings;
    bool coloured = false;
    float nearRadius = 0.0f;
    float farRadius = 0.0f;
    std::array<int, 6> faceFirst{};
    std::array<int, 6> faceLayers{};
    bool rays = false;  // method RAYS: no map, traced per pixel
    ShadowColourModel model = ShadowColourModel::Monochrome;
  };
  // What a trace of RAYS lights depends on: an equal key reuses the last trace.
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
  struct Context {
    std::unique_ptr<DeepShadowPass> pass;
    std::uint64_t castersVersion = 0;
    std::uint64_t mapsVersion = 0;
    std::vector<MapState> maps;  // per light slot: what this context's maps hold
    bool softwareRenderer = false;
    std::string renderer;
    std::unique_ptr<RayShadowPass> rays;
    GlPassTimer buildTimer;
    GlPassTimer shadingTimer;
    GlPassTimer captureTimer;
    // The last trace's captures and visibility, kept so that their memory is reused.
    std::vector<SurfaceLayer> surfaces;
    std::vector<std::uint16_t> visibility;
    TraceKey traced;
    bool traceValid = false;
  };

  void findLights();
  SbMatrix localToEye(SoState* state) const;
  int fogType(SoState* state) const;
  void buildMaps(SoGLRenderAction* action, Context& context);
  // The Embree scene of the casters, built when they changed; false (with one warning naming
  // `light`) when Embree cannot hold it, and the light then uses its map.
  bool rayCastersReady(const SoDeepShadowLight& light);
  void traceRays(SoGLRenderAction* action, Context& context, unsigned int program, bool inPath);
  SoSeparator* owner_;
  bool deepShadows_;
  ChildrenRenderer renderChildren_;
  ShadingProgram program_;
  ShadingProgram peelProgram_{true};
  PerContext<Context> contexts_;
  // Valid while the children render.
  ShadingUniforms uniforms_;
  const DeepShadowPass* renderingPass_ = nullptr;
  bool lightsValid_ = false;
  std::vector<Light> lights_;
  CoinRef<SoPath> cameraPath_;       // the last camera inside the group, if any
  CoinRef<SoPath> environmentPath_;  // the last SoEnvironment inside the group, if any
  int subgraphLightsOn_ = 0;
  bool castersValid_ = false;
  SceneTriangles casters_;
  std::uint64_t castersVersion_ = 0;
  std::uint64_t mapsVersion_ = 1;
  std::uint64_t viewVersion_ = 0;  // a camera inside the group changed
  DeepShadowStatistics statistics_;
  EmbreeMemory embreeMemory_;
  EmbreeDevice embreeDevice_;
  std::unique_ptr<CasterScene> rayCasters_;
  std::uint64_t rayCastersVersion_ = 0;
  std::string embreeError_;  // set once Embree failed: RAYS lights fall back to maps
  std::set<const SoDeepShadowLight*> methodLogged_;  // lights whose AUTO choice was said
  std::set<const SoDeepShadowLight*> embreeWarned_;  // lights told they keep their map
};

}  // namespace ivshadow
