#include "nodes/AutoTracerChoice.h"

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
  const bool software = gl->isSoftwareRenderer();
  if (!said_) {
    said_ = true;
    SoDebugError::postInfo(owner->getTypeId().getName().getString(), "%s: %s AUTO uses %s on %s",
                           describeNode(owner).c_str(), field, software ? "TRACER" : otherwise,
                           gl->renderer.c_str());
  }
  return software;
}

}  // namespace ivshadow
