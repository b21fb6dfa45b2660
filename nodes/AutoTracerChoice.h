#pragma once

#include "gl/GlCapabilities.h"
#include "nodes/PerContext.h"

class SoNode;
class SoState;

namespace ivshadow {

// What AUTO chooses, for a group's renderer and a peeling separator's method: the tracer where
// GL is a software rasteriser (Mesa's llvmpipe, softpipe), which shades every fragment on the
// cores the tracer would use, so that tracing the subgraph whole is the faster of the two there
// (docs/PERFORMANCE.md); GL's own path on a GPU. Decided per GL context, said once per node.
class AutoTracerChoice {
 public:
  // Whether `owner`, rendering into the context `state` renders to, traces; `field` and
  // `otherwise` name the field and the GL path for the message.
  bool traces(SoState* state, const SoNode* owner, const char* field, const char* otherwise);

 private:
  PerContext<GlCapabilities> capabilities_;
  bool said_ = false;
};

}  // namespace ivshadow
