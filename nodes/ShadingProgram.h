#pragma once

#include "callbacks/TexGenModes.h"
#include "callbacks/UniformLocations.h"
#include "nodes/PerContext.h"
#include "scene/CoinRef.h"

#include <array>

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
  FragmentList,        // fragment_list.frag: fragment lists' one pass (FragmentListPass)
};
inline constexpr int kShadingVariants = 8;

// The variants as Coin SoShaderProgram nodes, so Coin compiles each per context (when first
// used), binds it through SoGLShaderProgramElement (which SoShadowStyle switches off for
// shapes that are not SHADOWED) and keeps its coin_* uniforms (light model, two-sided
// lighting, texture model) up to date. The locations of the other uniforms are read once per
// program and context.
class ShadingProgram {
 public:
  // Out of line: the nodes' type is complete only in the .cpp.
  ShadingProgram();
  ~ShadingProgram();
  ShadingProgram(const ShadingProgram&) = delete;
  ShadingProgram& operator=(const ShadingProgram&) = delete;

  // Binds `variant` in the action's current state (the caller pushes and pops it) and returns
  // its program and uniform locations, or null when it did not build (Coin has said why).
  const UniformLocations* bind(SoGLRenderAction* action, ShadingVariant variant);
  // The variant GL has current in the state's context, or null when the current program is
  // none of them (a SoShadowStyle switched shading off, or a program of someone else's).
  const UniformLocations* current(SoState* state);
  // Sets uTexGen on every variant linked in the state's context (no binding needed), each
  // only when it holds other modes; a variant linked anew starts from 0.
  void sendTexGen(SoState* state, const TexGenModes& modes);
  // Whether a variant in the state's context holds modes other than 0.
  bool anyTexGen(SoState* state);

 private:
  SoShaderProgram* node(ShadingVariant variant);

  std::array<CoinRef<SoShaderProgram>, kShadingVariants> nodes_;
  struct Linked {
    std::array<UniformLocations, kShadingVariants> locations;
    std::array<TexGenModes, kShadingVariants> texGen{};  // uTexGen as last sent
  };
  Linked& linked(SoState* state);

  PerContext<Linked> linked_;
};

}  // namespace ivshadow
