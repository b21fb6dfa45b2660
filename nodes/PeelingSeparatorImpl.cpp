#include "nodes/PeelingSeparatorImpl.h"

#include "nodes/TracerActivity.h"

#include "gl/PeelPass.h"
#include "gl/ShadingUniforms.h"
#include "ivshadow/SoPeelingSeparator.h"
#include "ivshadow/SoTransparentShadowGroup.h"
#include "nodes/DepthPeeling.h"
#include "nodes/IdleFields.h"
#include "nodes/NodesOfType.h"
#include "nodes/ShadowGroupElement.h"
#include "scene/SceneTriangles.h"
#include "scene/WarnOnce.h"

#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/elements/SoCacheElement.h>
#include <Inventor/elements/SoGLCacheContextElement.h>
#include <Inventor/elements/SoLightElement.h>
#include <Inventor/elements/SoShapeStyleElement.h>
#include <Inventor/errors/SoDebugError.h>

#include <algorithm>
#include <chrono>

namespace ivshadow {

PeelingSeparatorImpl::PeelingSeparatorImpl(SoPeelingSeparator* owner)
    : owner_(owner),
      contents_(owner, false),
      shading_(contents_),
      tracer_(owner, "method TRACER") {}

PeelingSeparatorImpl::~PeelingSeparatorImpl() {
  forgetWarnings(owner_);
}

void PeelingSeparatorImpl::renderPlainly(SoGLRenderAction* action, bool inPath) {
  if (inPath)
    owner_->SoSeparator::GLRenderInPath(action);
  else
    owner_->SoSeparator::GLRenderBelowPath(action);
}

bool PeelingSeparatorImpl::traced(SoState* state) {
  const int method = owner_->method.getValue();
  if (method != SoPeelingSeparator::AUTO_METHOD) return method == SoPeelingSeparator::TRACER;
  return autoTracer_.traces(state, owner_, "method", "FRAGMENT_LISTS");
}

PeelPass* PeelingSeparatorImpl::passFor(SoState* state) {
  return passes_.get(SoGLCacheContextElement::get(state), [this] {
    std::string whyNot;
    auto made = PeelPass::create(whyNot);
    if (!made && firstWarning(owner_, "rendering without depth peeling: " + whyNot))
      SoDebugError::postWarning("SoPeelingSeparator", "%s: rendering without depth peeling: %s",
                                describeNode(owner_).c_str(), whyNot.c_str());
    return made;
  });
}

void PeelingSeparatorImpl::sayFieldsIdle(const char* why, bool methodActs) {
  auto& separator = *static_cast<SoPeelingSeparator*>(owner_);
  if (!methodActs) IdleFields::sayIfSet(separator, "method", why);
  for (const char* field : {"maxPasses", "earlyTermination"})
    IdleFields::sayIfSet(separator, field, why);
}

void PeelingSeparatorImpl::render(SoGLRenderAction* action, bool inPath) {
  SoState* state = action->getState();
  // A group capturing surfaces for its RAYS lights wants every layer drawn with its program;
  // a peeling above (a peeling group's, or another separator's) peels these children with
  // the rest, each pixel once.
  if (ShadowGroupElement::capturing(state) || ShadowGroupElement::peeling(state) ||
      TracerActivity::active(TracerActivity::DrawingUntraced)) {
    // The peeling above reports the passes; during a capture the last frame's stand.
    if (ShadowGroupElement::peeling(state)) {
      statistics_.passes = 0;
      statistics_.peelMs = statistics_.gpuPeelMs = 0.0;
      sayFieldsIdle("the peeling above peels its children with the rest, each pixel once", false);
    }
    tracer_.restoreDepth(action);
    renderPlainly(action, inPath);
    return;
  }
  // Inside a deep shadow group its program, uniforms and maps are already in place; without
  // peel targets the children are blended by Coin with them, as under the group's
  // COIN_BLENDING.
  if (GroupShading* group = ShadowGroupElement::activeGroup(state)) {
    sayFieldsIdle("inside a shadow group it lists its fragments in one pass, shaded by the group",
                  false);
    if (!peel(action, inPath, *group)) renderPlainly(action, inPath);
    return;
  }
  if (traced(state)) {
    contents_.update(action);
    const auto start = std::chrono::steady_clock::now();
    // Traced, a motion's frames are traced in full: the separator has no field to reduce them.
    // The groups below are traced whole, with their shadows and bounce (peeled by GL, a group
    // inside the separator draws as a plain separator): those with bounce TRUE that a switch
    // does not hide bounce with the most rays per point any of them asks for.
    if (bounceVersion_ != contents_.castersVersion()) {
      bounceVersion_ = contents_.castersVersion();
      bounceSamples_ = 0;
      forEachPathTo(owner_, SoTransparentShadowGroup::getClassTypeId(), false,
                    [this](SoPath& path) {
                      const auto& g = *static_cast<SoTransparentShadowGroup*>(path.getTail());
                      if (g.isActive.getValue() && g.bounce.getValue())
                        bounceSamples_ = std::max(bounceSamples_, g.bounceLights.getValue());
                    });
    }
    TracerSettings settings;
    settings.bounceSamples = bounceSamples_;
    if (tracer_.render(action, contents_, settings, tracerStatistics_)) {
      sayFieldsIdle("it traces its children", true);
      const int frames = statistics_.frames;
      statistics_ = PeelStatistics{};
      statistics_.frames = frames;
      statistics_.peelMs =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
              .count();
      statistics_.tracedFrames = tracerStatistics_.tracerFrames;
      return;
    }
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
  // No deep shadow light of its own: the shading looks nothing up.
  if (shading_.begin(action, pass->textureUnits(), ShadingFeatures{}) == nullptr) {
    state->pop();
    renderPlainly(action, inPath);
    return;
  }
  shading_.apply();
  SoShapeStyleElement::setShadowsRendering(state, TRUE);
  ShadowGroupElement::setShading(state, &shading_);
  const bool peeled = peel(action, inPath, shading_);
  shading_.end();
  SoShapeStyleElement::setShadowsRendering(state, FALSE);
  state->pop();
  // Without peel targets: drawn as without a peel pass at all, a plain separator's children.
  if (!peeled) renderPlainly(action, inPath);
}

bool PeelingSeparatorImpl::peel(SoGLRenderAction* action, bool inPath, GroupShading& shading) {
  PeelPass* pass = passFor(action->getState());
  // No program current: a SoShadowStyle above switched shading off for these shapes.
  if (pass == nullptr || currentProgram() == 0) {
    renderPlainly(action, inPath);
    return true;
  }
  PeelOptions options;
  const int method = owner_->method.getValue();
  options.dual = method != SoPeelingSeparator::FRONT_TO_BACK;
  // TRACER and AUTO peel (where they do not trace: inside a group, on a GPU, or when the
  // tracer cannot draw) with the lists.
  options.fragmentLists = method == SoPeelingSeparator::FRAGMENT_LISTS ||
                          method == SoPeelingSeparator::TRACER ||
                          method == SoPeelingSeparator::AUTO_METHOD;
  options.owner = owner_;
  options.maxPasses = owner_->maxPasses.getValue();
  if (options.maxPasses < 0) {
    if (firstWarning(owner_, "negative maxPasses"))
      SoDebugError::postWarning("SoPeelingSeparator",
                                "%s: field maxPasses %d is negative; using 0 (until no layer is "
                                "left, at most %d)",
                                describeNode(owner_).c_str(), options.maxPasses,
                                SoPeelingSeparator::kMaxPasses);
    options.maxPasses = 0;
  }
  options.earlyTermination = owner_->earlyTermination.getValue();
  // Every pass starts with the GL lights past those in force here black, as the first did: a
  // light below sets its GL light only where it is traversed, and the pass before left its
  // values there, lighting shapes traversed before it.
  const int lightsHere = SoLightElement::getLights(action->getState()).getLength();
  const std::string failure = peelSubgraph(
      action, *pass, shading, options,
      [this, inPath, lightsHere](SoGLRenderAction* drawing) {
        darkenLights(lightsHere);
        renderPlainly(drawing, inPath);
      },
      statistics_);
  if (failure.empty()) return true;
  if (firstWarning(owner_, "no peel targets: " + failure))
    SoDebugError::postWarning("SoPeelingSeparator",
                              "%s: %s; its transparency is blended by Coin, without depth peeling",
                              describeNode(owner_).c_str(), failure.c_str());
  return false;
}

}  // namespace ivshadow
