#pragma once

#include "gl/ShadingLocations.h"
#include "gl/TexGenModes.h"
#include "ivshadow/Export.h"
#include "nodes/PerContext.h"
#include "scene/CoinRef.h"

#include <map>
#include <string>

class SoGLRenderAction;
class SoState;
class SoShaderProgram;

namespace ivshadow {

// The programs that shade the shapes of SoTransparentShadowGroup and SoPeelingSeparator, each
// chosen when it is compiled (a #define per variant) rather than by a uniform at run time.
enum class ShadingVariant : int {
  Shade,               // shading.frag: the camera pass
  OpaqueOnly,          // shading.frag, IVSHADOW_OPAQUE_ONLY: peeling's opaque pass
  PeelInit,            // peel.frag, IVSHADOW_PEEL_INIT: the first peel pass
  PeelFrontToBack,     // peel.frag: one layer per pass
  PeelDual,            // peel.frag, IVSHADOW_PEEL_DUAL: two layers per pass
  CaptureOpaque,       // capture.frag, IVSHADOW_CAPTURE_OPAQUE: RAYS lights' opaque capture
  CaptureTransparent,  // capture.frag: their transparent captures
  FragmentList,        // fragment_list.frag: fragment lists' one pass (FragmentListPass), the last
};

// The parts of the lighting code a frame needs, each compiled into the variants only where
// some light or the state needs it: llvmpipe runs both sides of every branch for every
// fragment, so code a branch skips still costs its full price (docs/PERFORMANCE.md, "Shader
// variants"). A flag off leaves its code out; a flag on where nothing needs it costs time,
// never correctness.
struct ShadingFeatures {
  bool maps = false;      // some light looks its visibility up in a map of either kind:
  bool deep = false;      // ... a deep shadow map (method MAP)
  bool opacity = false;   // ... an opacity map (method OPACITY_MAP)
  bool rays = false;      // some light's visibility was traced per pixel (method RAYS)
  bool nearest = false;   // some map is read at the nearest texel (filter NONE)
  bool filtered = false;  // some map is filtered over a texel square (PCF; 1 wide: bilinear)
  bool fog = false;       // the state has fog (SoEnvironment fogType other than NONE)
  bool bounce = false;    // the group's light bounces once (SoTransparentShadowGroup::bounce)

  // A distinct number per combination, 0 for none, below kKeys.
  static constexpr int kKeys = 256;
  int key() const {
    return int(maps) | int(rays) << 1 | int(nearest) << 2 | int(filtered) << 3 | int(fog) << 4 |
           int(deep) << 5 | int(opacity) << 6 | int(bounce) << 7;
  }
  // The #defines that compile the parts in (gl/glsl/lighting.glsl).
  std::string defines() const;
};

// The variants as Coin SoShaderProgram nodes, so Coin compiles each per context (when first
// used), binds it through SoGLShaderProgramElement (which SoShadowStyle switches off for
// shapes that are not SHADOWED) and keeps its coin_* uniforms (light model, two-sided
// lighting, texture model) up to date. The locations of the other uniforms are read once per
// program and context (ShadingLocations).
class ShadingProgram {
 public:
  // Out of line: the nodes' type is complete only in the .cpp.
  ShadingProgram();
  ~ShadingProgram();
  ShadingProgram(const ShadingProgram&) = delete;
  ShadingProgram& operator=(const ShadingProgram&) = delete;

  // Binds `variant`, compiled with `features`, in the action's current state (the caller
  // pushes and pops it) and returns its program and uniform locations, or null when it did not
  // build (Coin has said why). Variants that light nothing ignore `features`.
  const ShadingLocations* bind(SoGLRenderAction* action, ShadingVariant variant,
                               const ShadingFeatures& features);
  // The variant GL has current in the state's context, or null when the current program is
  // none of them (a SoShadowStyle switched shading off, or a program of someone else's).
  const ShadingLocations* current(SoState* state);
  // Sets uTexGen on every variant linked in the state's context (no binding needed), each
  // only when it holds other modes; a variant linked anew starts from 0.
  void sendTexGen(SoState* state, const TexGenModes& modes);
  // Whether a variant in the state's context holds modes other than 0.
  bool anyTexGen(SoState* state);
  // The text of every variant's shaders, which declares each uniform ShadingLocations names.
  IVSHADOW_INTERNAL static std::string declarations();

 private:
  // A variant with its features, as one number.
  static int keyOf(ShadingVariant variant, const ShadingFeatures& features);
  SoShaderProgram* node(ShadingVariant variant, const ShadingFeatures& features);

  std::map<int, CoinRef<SoShaderProgram>> nodes_;  // by keyOf, made when first bound
  struct Linked {
    std::map<int, ShadingLocations> locations;  // by keyOf
    std::map<int, TexGenModes> texGen;          // uTexGen as last sent
  };
  Linked& linked(SoState* state);

  PerContext<Linked> linked_;
};

}  // namespace ivshadow
