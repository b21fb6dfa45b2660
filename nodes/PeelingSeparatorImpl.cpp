#include "nodes/PeelingSeparatorImpl.h"

#include "callbacks/PeelPass.h"
#include "callbacks/ShadingUniforms.h"
#include "ivshadow/SoPeelingSeparator.h"
#include "nodes/DepthPeeling.h"
#include "nodes/ShadowGroupElement.h"

#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/elements/SoCacheElement.h>
#include <Inventor/elements/SoGLCacheContextElement.h>
#include <Inventor/elements/SoShapeStyleElement.h>
#include <Inventor/errors/SoDebugError.h>

namespace ivshadow {

PeelingSeparatorImpl::PeelingSeparatorImpl(SoPeelingSeparator* owner)
    : owner_(owner), contents_(owner, false), shading_(contents_) {}

PeelingSeparatorImpl::~PeelingSeparatorImpl() = default;

void PeelingSeparatorImpl::renderPlainly(SoGLRenderAction* action, bool inPath) {
  if (inPath)
    owner_->SoSeparator::GLRenderInPath(action);
  else
    owner_->SoSeparator::GLRenderBelowPath(action);
}

PeelPass* PeelingSeparatorImpl::passFor(SoState* state) {
  return passes_.get(SoGLCacheContextElement::get(state), [] {
    std::string whyNot;
    auto made = PeelPass::create(whyNot);
    if (!made) {
      static bool warned = false;
      if (!warned) {
        warned = true;
        SoDebugError::postWarning("SoPeelingSeparator", "rendering without depth peeling: %s",
                                  whyNot.c_str());
      }
    }
    return made;
  });
}

void PeelingSeparatorImpl::render(SoGLRenderAction* action, bool inPath) {
  SoState* state = action->getState();
  // A group capturing surfaces for its RAYS lights wants every layer drawn with its program;
  // a peeling above (a peeling group's, or another separator's) peels these children with
  // the rest, each pixel once.
  if (ShadowGroupElement::capturing(state) || ShadowGroupElement::peeling(state)) {
    // The peeling above reports the passes; during a capture the last frame's stand.
    if (ShadowGroupElement::peeling(state)) {
      statistics_.passes = 0;
      statistics_.peelMs = statistics_.gpuPeelMs = 0.0;
    }
    renderPlainly(action, inPath);
    return;
  }
  // Inside a deep shadow group its program, uniforms and maps are already in place.
  if (GroupShading* group = ShadowGroupElement::activeGroup(state)) {
    peel(action, inPath, *group);
    return;
  }
  PeelPass* pass = passFor(state);
  if (pass == nullptr) {
    renderPlainly(action, inPath);
    return;
  }
  // The uniforms and the program belong to this frame; a render cache above the separator
  // must not replay them.
  SoCacheElement::invalidate(state);
  contents_.update(action);
  state->push();
  if (shading_.begin(action, pass->textureUnits()) == nullptr) {
    state->pop();
    renderPlainly(action, inPath);
    return;
  }
  shading_.apply();
  SoShapeStyleElement::setShadowsRendering(state, TRUE);
  ShadowGroupElement::setShading(state, &shading_);
  peel(action, inPath, shading_);
  shading_.end();
  SoShapeStyleElement::setShadowsRendering(state, FALSE);
  state->pop();
}

void PeelingSeparatorImpl::peel(SoGLRenderAction* action, bool inPath, GroupShading& shading) {
  PeelPass* pass = passFor(action->getState());
  // No program current: a SoShadowStyle above switched shading off for these shapes.
  if (pass == nullptr || currentProgram() == 0) {
    renderPlainly(action, inPath);
    return;
  }
  PeelOptions options;
  const int method = owner_->method.getValue();
  options.dual = method != SoPeelingSeparator::FRONT_TO_BACK;
  options.fragmentLists = method == SoPeelingSeparator::FRAGMENT_LISTS;
  options.owner = owner_;
  options.maxPasses = owner_->maxPasses.getValue();
  options.earlyTermination = owner_->earlyTermination.getValue();
  peelSubgraph(
      action, *pass, shading, options,
      [this, inPath](SoGLRenderAction* drawing) { renderPlainly(drawing, inPath); }, statistics_);
}

}  // namespace ivshadow
