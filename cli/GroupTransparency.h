#pragma once

#include <Inventor/actions/SoGLRenderAction.h>

#include <string>

class SoNode;

namespace ivshadow {

// The transparency type a render action should use for `root` when the user asked for
// `requested`, and the one warning to give when that is not `requested`.
//
// SORTED_LAYERS_BLEND cannot work inside a SoTransparentShadowGroup or SoPeelingSeparator:
// Coin renders the whole scene once per layer and peels each layer with its own fragment
// program, but the nodes shade their shapes with their own GLSL program, which takes the
// fragment program's place. Every pass then draws the same nearest surface, Coin stacks that
// layer on itself and nothing behind the glass survives: the glass turns opaque.
struct GroupTransparency {
  SoGLRenderAction::TransparencyType type;
  std::string warning;  // empty when `requested` is used as asked

  static GroupTransparency choose(SoNode* root, SoGLRenderAction::TransparencyType requested);
};

}  // namespace ivshadow
