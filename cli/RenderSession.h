#pragma once

#include "cli/KeptScene.h"
#include "cli/RenderCommand.h"
#include "headless/OffscreenRenderer.h"

#include <Inventor/actions/SoGLRenderAction.h>

#include <memory>
#include <optional>
#include <vector>

class SoNode;

namespace ivshadow {

struct ImageSize;

// `ivshadow render`, one scene after another in one process: the headless renderer (its EGL
// context, framebuffer, render action and Coin's GL caches) is made by the first render and
// kept while the size stays, so that later renders pay neither for the context nor for what
// the driver compiled in it. Each render writes, says and returns exactly what `ivshadow
// render` with the same options would (a variants worker, cli/VariantsWorker.h, renders a
// sweep's variants through one).
//
// The scene of a render that traced its group and nothing else is kept for the next render
// of the same file at the same size (cli/KeptScene.h): that render puts back the fields the
// last one assigned, applies its own and draws, so that the group's tracer re-reads only what
// changed (a light's fields: the lights alone, and from the second such change on it shades
// the surfaces its camera rays met rather than tracing them again).
class RenderSession {
 public:
  // As runRender: 0 on success, 2 on bad input, 3 when no GL context can be made, 1 on any
  // other failure; messages on stderr, "wrote ..." on stdout.
  int render(const RenderOptions& options);

  // The next render reads its scene afresh: the caller saw the last render say a warning.
  // What a scene's nodes say once, as they read or build what they keep (a shape the tracer
  // leaves out, a defective shape), would not be said again by a render that finds it kept,
  // where a render process of its own says it every time.
  void forgetScene() { kept_.reset(); }

 private:
  // The render itself; `keep` says whether the scene may serve the next render.
  int renderScene(const RenderOptions& options, bool& keep);
  // Makes kept_ the scene this render draws: the kept one with its assigned fields put back
  // where it serves, else the file read afresh; says its warnings and applies `assignments`.
  // Whether the kept scene served.
  bool prepareScene(const RenderOptions& options, const std::vector<FieldAssignment>& assignments,
                    const std::optional<KeptScene::FileState>& file);
  // The renderer of `size`, made again when the size changed, with the memory `root` needs
  // checked before it is made and again for its GL; nullptr when no GL context can be made.
  OffscreenRenderer* rendererFor(const ImageSize& size, SoNode* root);

  std::unique_ptr<OffscreenRenderer> renderer_;
  SoGLRenderAction::TransparencyType defaultTransparency_ = SoGLRenderAction::BLEND;
  // After the renderer: the scene's nodes free what they hold in its GL context first.
  std::unique_ptr<KeptScene> kept_;
};

}  // namespace ivshadow
