#include "nodes/PeelingSeparatorImpl.h"

#include "callbacks/PeelPass.h"
#include "callbacks/ShadingUniforms.h"
#include "ivshadow/DeepShadowStatistics.h"
#include "ivshadow/SoPeelingSeparator.h"
#include "nodes/ShadowGroupElement.h"
#include "nodes/TransparencyOverride.h"

#include <Inventor/SbViewportRegion.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/elements/SoCacheElement.h>
#include <Inventor/elements/SoDepthBufferElement.h>
#include <Inventor/elements/SoGLCacheContextElement.h>
#include <Inventor/elements/SoGLLazyElement.h>
#include <Inventor/elements/SoShapeStyleElement.h>
#include <Inventor/elements/SoViewportRegionElement.h>
#include <Inventor/errors/SoDebugError.h>

#include <algorithm>
#include <chrono>

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
  // A group capturing surfaces for its RAYS lights wants every layer drawn with its program.
  SoState* state = action->getState();
  if (ShadowGroupElement::capturing(state)) {
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
  peel(action, inPath, shading_);
  shading_.end();
  SoShapeStyleElement::setShadowsRendering(state, FALSE);
  state->pop();
}

void PeelingSeparatorImpl::peel(SoGLRenderAction* action, bool inPath, GroupShading& shading) {
  SoState* state = action->getState();
  PeelPass* pass = passFor(state);
  // No program current: a SoShadowStyle above switched shading off for these shapes.
  if (pass == nullptr || currentProgram() == 0) {
    renderPlainly(action, inPath);
    return;
  }
  // Each pass sets its own uniforms and targets; no cache above may replay one of them.
  SoCacheElement::invalidate(state);

  state->push();
  // The opaque pass discards transparent fragments; drawn at once, none is delayed.
  overrideTransparencyType(state, SoGLRenderAction::NONE);
  const bool opaqueBound = shading.bind(action, ShadingVariant::OpaqueOnly) != nullptr;
  renderPlainly(action, inPath);
  state->pop();
  // Without the opaque variant (Coin has said why) the plain pass drew everything.
  if (!opaqueBound) return;

  const auto start = std::chrono::steady_clock::now();
  const SbViewportRegion& region = SoViewportRegionElement::get(state);
  const SbVec2s origin = region.getViewportOriginPixels();
  const SbVec2s size = region.getViewportSizePixels();
  const bool dual = owner_->method.getValue() == SoPeelingSeparator::DUAL;
  const int requested = owner_->maxPasses.getValue();
  const int cap = requested > 0 ? std::min(requested, SoPeelingSeparator::kMaxPasses)
                                : SoPeelingSeparator::kMaxPasses;
  const bool stopEarly = owner_->earlyTermination.getValue();

  pass->begin(origin[0], origin[1], size[0], size[1]);
  state->push();
  // Drawn at once with blending on, which the peel passes turn into MAX blending.
  overrideTransparencyType(state, SoGLRenderAction::BLEND);
  // Against the opaque pass's depth: only what lies in front of it is peeled, and the
  // early depth test of the peel program skips the rest before shading.
  SoDepthBufferElement::set(state, TRUE, FALSE, SoDepthBufferElement::LESS, SbVec2f(0.0f, 1.0f));
  int passes = 0;
  for (;;) {
    const UniformLocations* peelProgram =
        shading.bind(action, passes == 0 ? ShadingVariant::PeelInit
                             : dual      ? ShadingVariant::PeelDual
                                         : ShadingVariant::PeelFrontToBack);
    // A peel variant did not build (Coin has said why): the passes done so far stand.
    if (peelProgram == nullptr) break;
    pass->startPass(passes);
    pass->setPeelUniforms(*peelProgram);
    renderPlainly(action, inPath);
    const bool deeper = pass->finishPass(passes, dual);
    ++passes;
    if (passes >= cap || (stopEarly && !deeper)) break;
  }
  state->pop();
  pass->end(passes);
  // The passes drew with blending and targets Coin did not choose; the scope restored GL,
  // and Coin must not trust what it believes it last sent.
  SoGLLazyElement::getInstance(state)->reset(state, SoLazyElement::ALL_MASK);

  statistics_.passes = passes;
  if (passTiming()) statistics_.gpuPeelMs = pass->gpuMs();
  statistics_.peelMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  ++statistics_.frames;
}

}  // namespace ivshadow
