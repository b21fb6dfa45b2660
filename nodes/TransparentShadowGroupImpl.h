#pragma once

#include "gl/GlCapabilities.h"
#include "gl/GlPassTimer.h"
#include "gl/ShadingUniforms.h"
#include "ivshadow/DeepShadowStatistics.h"
#include "ivshadow/Export.h"
#include "ivshadow/PeelStatistics.h"
#include "nodes/AutoTracerChoice.h"
#include "nodes/DeepShadowSettings.h"
#include "nodes/GroupBounce.h"
#include "nodes/GroupContents.h"
#include "nodes/GroupShading.h"
#include "nodes/GroupTracer.h"
#include "nodes/IdleFields.h"
#include "nodes/MapMethod.h"
#include "nodes/MapState.h"
#include "nodes/PerContext.h"
#include "nodes/RayCasters.h"

#include <Inventor/SbMatrix.h>
#include <Inventor/SbVec3f.h>

#include <array>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

class SoLight;
class SoGLRenderAction;
class SoNotList;
class SoPath;
class SoState;
class SoSeparator;

namespace ivshadow {

class DeepShadowPass;
class ImperfectShadowMaps;
class PeelPass;
class RayMethod;

// The work behind SoTransparentShadowGroup: per GL context, keeps each deep shadow light's
// map (MapMethod) or traced shadows (RayCasters, the captures) up to date with what the
// subgraph holds (GroupContents), and renders the children with the group's shading
// (GroupShading), which a SoPeelingSeparator below uses for its layers. With `peel` the
// children's transparent surfaces are composited in exact depth order (peelSubgraph).
class TransparentShadowGroupImpl {
 public:
  // Draws the owner's children (once or, for peeling, several times).
  using ChildrenRenderer = std::function<void(SoGLRenderAction*, bool inPath)>;

  TransparentShadowGroupImpl(SoSeparator* owner, ChildrenRenderer renderChildren);
  ~TransparentShadowGroupImpl();
  TransparentShadowGroupImpl(const TransparentShadowGroupImpl&) = delete;
  TransparentShadowGroupImpl& operator=(const TransparentShadowGroupImpl&) = delete;

  // Renders the group with shadows, its transparent surfaces peeled when `peel`; returns
  // false when this context cannot (the caller then renders it as a plain separator).
  bool render(SoGLRenderAction* action, bool inPath, bool peel);
  void changed(SoNotList* list);
  const DeepShadowStatistics& statistics() const { return statistics_; }
  const PeelStatistics& peelStatistics() const { return peelStatistics_; }

 private:
  struct Context {
    std::unique_ptr<DeepShadowPass> pass;
    std::uint64_t castersVersion = 0;
    std::uint64_t mapsVersion = 0;
    std::vector<MapState> maps;  // per light slot: what this context's maps hold
    bool softwareRenderer = false;
    std::string renderer;
    std::unique_ptr<RayMethod> rays;
    std::unique_ptr<PeelPass> peel;  // made on the first peeled frame
    bool peelTried = false;          // made, or failed with a warning
    GlPassTimer buildTimer;
    GlPassTimer shadingTimer;
    std::unique_ptr<ImperfectShadowMaps> bounceMaps;  // with bounce TRUE
    std::uint64_t bounceVersion = 0;                  // GroupBounce::version() drawn
    std::uint64_t bouncePoints = 0;                   // GroupBounce::pointsVersion() uploaded
    int bounceMapSize = 0;                            // the tiles drawn, within this budget
    GlPassTimer bounceTimer;
  };

  void buildMaps(SoGLRenderAction* action, Context& context);
  // Fits and builds slot `slot`'s map (or resolves it to RAYS), filling its statistics.
  // `view` is the view of this build, computed by the first directional light that needs it.
  void buildSlot(SoGLRenderAction* action, Context& context, std::size_t slot,
                 std::uint64_t memoryBudget, std::optional<ViewCorners>& view);
  // The bookkeeping that ends every build, whole or a refit: Coin's lazy state, the timers
  // and the statistics.
  void finishBuild(SoGLRenderAction* action, Context& context,
                   std::chrono::steady_clock::time_point start);
  // What the camera can show, in the group's coordinates: the camera above the group's, or
  // the one inside it (which is traversed after the maps are built).
  ViewCorners view(SoGLRenderAction* action) const;
  // Rebuilds the maps of directional lights that no longer serve the view (mapServesView).
  void refitToView(SoGLRenderAction* action, Context& context);
  // Brings the bounce's lights (per group) and this context's maps of them up to date; true
  // when the shading is to add the bounce.
  bool updateBounce(SoGLRenderAction* action, Context& context);
  // Draws the children in the shading pass: peeled, or as Coin blends them.
  void shadeChildren(SoGLRenderAction* action, bool inPath, bool peel, Context& context);
  // Whether the group is traced in the action's context: renderer TRACER, or AUTO on a
  // software rasteriser (said once).
  bool traced(SoGLRenderAction* action);
  // Renders the group with its tracer; false when the tracer declines and GL draws it.
  bool renderTraced(SoGLRenderAction* action);
  // The action's GL context's passes and maps, made on its first frame; null (said once)
  // where GL cannot give them.
  Context* contextFor(SoGLRenderAction* action);
  // Begins the shading variant this frame's maps and bounce need; null (said once) when Coin
  // bound no program for it.
  ShadingUniforms* beginShading(SoGLRenderAction* action, Context& context, bool bounced);
  // Writes each light slot's map (or ray) parameters into the uniforms; returns how many
  // slots shadow per pixel.
  int packMaps(ShadingUniforms& uniforms, const Context& context);
  // Writes the bounce's lights and atlas into the uniforms, or none without the bounce.
  void packBounce(ShadingUniforms& uniforms, const Context& context, bool bounced);
  // Brings the per-pixel shadows (RAYS, VOLUMES) up to date, saying once why a light has none.
  void updateRays(SoGLRenderAction* action, bool inPath, Context& context,
                  ShadingUniforms& uniforms);
  // Binds the maps, rays and bounce, draws the children shaded and pops the state that render
  // pushed for the shading.
  void drawShaded(SoGLRenderAction* action, bool inPath, bool peel, Context& context, bool rays,
                  bool bounced);
  SoSeparator* owner_;
  ChildrenRenderer renderChildren_;
  GroupContents contents_;
  GroupShading shading_;
  PerContext<Context> contexts_;
  DeepShadowStatistics statistics_;
  PeelStatistics peelStatistics_;
  RayCasters rayCasters_;
  GroupBounce bounce_;
  GroupTracer tracer_;                     // renderer TRACER
  AutoTracerChoice autoTracer_;            // what renderer AUTO chooses
  IdleFields idleFields_;                  // the methods this frame's lights used
  std::uint64_t bouncePlaced_ = 0;         // the mapsVersion the bounce's lights were placed for
  std::set<const SoLight*> methodLogged_;  // lights whose AUTO choice was said
};

}  // namespace ivshadow
