#pragma once

#include "scene/CoinRef.h"

class SoShaderProgram;

namespace ivshadow {

// The camera-pass program of SoTransparentShadowGroup as a Coin SoShaderProgram node, so Coin
// compiles it per context, binds it through SoGLShaderProgramElement (which SoShadowStyle
// switches off for shapes that are not SHADOWED) and keeps its coin_* uniforms (light model,
// two-sided lighting, texture model) up to date.
class ShadingProgram {
 public:
  // `peelPasses`: the variant for SoPeelingSeparator's peel passes (early depth test).
  explicit ShadingProgram(bool peelPasses = false);
  SoShaderProgram* node() const { return program_.get(); }

 private:
  CoinRef<SoShaderProgram> program_;
};

}  // namespace ivshadow
