#include "nodes/AutoTracerChoice.h"

#include "gl/TracedPicturePass.h"
#include "scene/SceneTriangles.h"

#include <Inventor/elements/SoGLCacheContextElement.h>
#include <Inventor/errors/SoDebugError.h>
#include <Inventor/nodes/SoNode.h>

namespace ivshadow {

bool AutoTracerChoice::traces(SoState* state, const SoNode* owner, const char* field,
                              const char* otherwise) {
  const GlCapabilities* gl = capabilities_.get(SoGLCacheContextElement::get(state), [] {
    return std::make_unique<GlCapabilities>(GlCapabilities::queryCurrent());
  });
  // A context too old to draw the traced picture (GL 3.3 on llvmpipe) takes GL's path, which
  // says what it lacks in turn: tracing there would only fall back to it with one more warning.
  std::string whyNot;
  const bool traces = gl->isSoftwareRenderer() && TracedPicturePass::supported(whyNot);
  if (!said_) {
    said_ = true;
    SoDebugError::postInfo(owner->getTypeId().getName().getString(), "%s: %s AUTO uses %s on %s%s",
                           describeNode(owner).c_str(), field, traces ? "TRACER" : otherwise,
                           gl->renderer.c_str(),
                           whyNot.empty() ? "" : (" (" + whyNot + ")").c_str());
  }
  return traces;
}

}  // namespace ivshadow
