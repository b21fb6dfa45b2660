#pragma once

#include "cli/RenderCommand.h"
#include "headless/OffscreenRenderer.h"

#include <Inventor/actions/SoGLRenderAction.h>

#include <memory>

namespace ivshadow {

// `ivshadow render`, one scene after another in one process: the headless renderer (its EGL
// context, framebuffer, render action and Coin's GL caches) is made by the first render and
// kept while the size stays, so that later renders pay neither for the context nor for what
// the driver compiled in it. Each render reads its scene afresh and writes, says and returns
// exactly what `ivshadow render` with the same options would (a variants worker,
// cli/VariantsWorker.h, renders a sweep's variants through one).
class RenderSession {
 public:
  // As runRender: 0 on success, 2 on bad input, 3 when no GL context can be made, 1 on any
  // other failure; messages on stderr, "wrote ..." on stdout.
  int render(const RenderOptions& options);

 private:
  std::unique_ptr<OffscreenRenderer> renderer_;
  SoGLRenderAction::TransparencyType defaultTransparency_ = SoGLRenderAction::BLEND;
};

}  // namespace ivshadow
