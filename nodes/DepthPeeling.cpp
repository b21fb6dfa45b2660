#include "nodes/DepthPeeling.h"

#include "gl/FragmentListPass.h"
#include "gl/GlStateScope.h"
#include "gl/PeelPass.h"
#include "gl/ShaderConstants.h"
#include "ivshadow/DeepShadowStatistics.h"
#include "ivshadow/PeelStatistics.h"
#include "ivshadow/SoPeelingSeparator.h"
#include "nodes/GroupShading.h"
#include "nodes/ShadowGroupElement.h"
#include "nodes/SuspendedRenderCaches.h"
#include "nodes/TransparencyOverride.h"
#include "scene/WarnOnce.h"

#include <Inventor/SbViewportRegion.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/elements/SoCacheElement.h>
#include <Inventor/elements/SoDepthBufferElement.h>
#include <Inventor/elements/SoGLLazyElement.h>
#include <Inventor/elements/SoPolygonOffsetElement.h>
#include <Inventor/elements/SoShapeStyleElement.h>
#include <Inventor/elements/SoViewportRegionElement.h>
#include <Inventor/errors/SoDebugError.h>
#include <Inventor/nodes/SoNode.h>

#include <algorithm>
#include <chrono>
#include <string>

namespace ivshadow {
namespace {

// The state every pass after the opaque one draws in (pushed by the caller): every shape with
// the plugin's program, against the opaque pass's depth.
void setPeelPassState(SoState* state) {
  // Drawn at once with blending on, which the peel passes turn into MAX blending.
  overrideTransparencyType(state, SoGLRenderAction::BLEND);
  ShadowGroupElement::setPeeling(state, true);
  // Every shape must draw with a peel variant: a shape drawn by Coin's fixed function would
  // write its colour into the depth range and accumulation targets. SoShadowStyle switches
  // the program off (for shapes it keeps from being SHADOWED) only while the shadows flag
  // is up, so it is lowered for the peel passes; such shapes were drawn by Coin in the
  // opaque pass, and only their transparent surfaces are peeled, with the group's shading.
  SoShapeStyleElement::setShadowsRendering(state, FALSE);
  // Against the opaque pass's depth: only what lies in front of it is peeled, and the
  // early depth test of the peel program skips the rest before shading.
  SoDepthBufferElement::set(state, TRUE, FALSE, SoDepthBufferElement::LESS, SbVec2f(0.0f, 1.0f));
  // A shape drawn in the opaque pass by Coin's fixed function (one SoShadowStyle keeps from
  // being SHADOWED) comes out a few ulps nearer when the program draws it again, and would
  // be peeled over itself. The peel passes push every surface back by about kSameLayer
  // (16 steps of the 32-bit float depth near 0.5), so a surface's own opaque depth hides
  // it; every peel pass moves a surface alike, so layers still compare as before.
  SoPolygonOffsetElement::set(state, nullptr, 0.0f, 16.0f, SoPolygonOffsetElement::FILLED, TRUE);
}

// Says once per node and reason why a view is peeled instead of listed.
void warnListsNotUsed(const SoNode* owner, const std::string& reason, const std::string& why) {
  if (!firstWarning(owner, "fragment lists: " + reason)) return;
  const char* node =
      owner != nullptr ? owner->getTypeId().getName().getString() : "SoPeelingSeparator";
  SoDebugError::postWarning(node, "fragment lists not used, peeling instead: %s", why.c_str());
}

// The transparent surfaces into fragment lists and resolved over the opaque picture: true,
// with the passes counted, or false (with one warning) when the lists cannot hold the view
// and nothing was composited.
bool drawFragmentLists(SoGLRenderAction* action, PeelPass& pass, GroupShading& shading,
                       const PeelOptions& options,
                       const std::function<void(SoGLRenderAction*)>& draw,
                       PeelStatistics& statistics) {
  std::string whyNot;
  FragmentListPass* lists = pass.fragmentLists(whyNot);
  if (lists == nullptr) {
    warnListsNotUsed(options.owner, "unavailable", whyNot);
    return false;
  }
  SoState* state = action->getState();
  const SbViewportRegion& region = SoViewportRegionElement::get(state);
  const SbVec2s origin = region.getViewportOriginPixels();
  const SbVec2s size = region.getViewportSizePixels();
  // When the list pass's state pops, Coin's depth element sends the depth function it believes
  // in force (LEQUAL unless a node set one), which need not be GL's: FreeCAD draws with GL_LESS
  // set directly, and its nodes after the group draw a highlight before the whole shape again,
  // which LEQUAL let over it. GL's depth state is put back as the pass found it, as a RAYS
  // capture does (the peel passes' targets, PeelPass::end, put it back likewise).
  const GlStateScope depth(GlStateScope::kDepth);
  state->push();
  setPeelPassState(state);
  FragmentListPass::Outcome outcome = FragmentListPass::Outcome::TooLarge;
  bool unbuilt = false;
  int passes = 0;
  // A second pass only when the first found the buffer too small (it is now large enough).
  for (int attempt = 0; attempt < 2; ++attempt) {
    // A variant that did not build: Coin has said why, and the view is peeled.
    if (shading.bind(action, ShadingVariant::FragmentList) == nullptr) {
      unbuilt = true;
      break;
    }
    if (!lists->begin(origin[0], origin[1], size[0], size[1])) break;
    draw(action);
    outcome = lists->finish();
    ++passes;
    if (outcome != FragmentListPass::Outcome::Grow) break;
  }
  state->pop();
  statistics.listPasses = passes;
  statistics.listFragments = 0;
  if (outcome == FragmentListPass::Outcome::Stored) {
    lists->resolve();
    statistics.listFragments = (long long)lists->fragments();
    statistics.listSlots = lists->slots();
    statistics.passes = passes;
    return true;
  }
  if (outcome == FragmentListPass::Outcome::Crowded)
    warnListsNotUsed(options.owner, "crowded",
                     "a pixel holds more than " + std::to_string(kMaxFragmentsPerPixel) +
                         " transparent surfaces");
  else if (!unbuilt)
    warnListsNotUsed(options.owner, "storage", lists->tooLargeReason());
  return false;
}

}  // namespace

std::string peelSubgraph(SoGLRenderAction* action, PeelPass& pass, GroupShading& shading,
                         const PeelOptions& options,
                         const std::function<void(SoGLRenderAction*)>& draw,
                         PeelStatistics& statistics) {
  SoState* state = action->getState();
  {
    // Before the opaque pass: a failure found after it would leave the transparent surfaces
    // undrawn, or drawn twice.
    const SbViewportRegion& region = SoViewportRegionElement::get(state);
    const SbVec2s origin = region.getViewportOriginPixels();
    const SbVec2s size = region.getViewportSizePixels();
    const std::string failure = pass.prepare(origin[0], origin[1], size[0], size[1]);
    if (!failure.empty()) {
      statistics.passes = 0;
      statistics.peelMs = statistics.gpuPeelMs = 0.0;
      return failure;
    }
  }
  // Each pass sets its own uniforms and targets; no cache above may replay one of them.
  SoCacheElement::invalidate(state);
  // Nor may a cache below: one recorded in an earlier frame, replayed between the passes,
  // drew its shapes apart from the depths the passes compare (a layer of peeled_glasses.iv
  // was never peeled, and dual peeling ran all 64 passes from the second frame on).
  const SuspendedRenderCaches noCaches;

  state->push();
  // The opaque pass discards transparent fragments; drawn at once, none is delayed. Blending
  // is on for the shapes Coin finds transparent: those the program draws are discarded
  // anyway, and a transparent shape that SoShadowStyle keeps from being SHADOWED (drawn by
  // Coin without the program) is blended as under Coin's BLEND rather than drawn opaque.
  overrideTransparencyType(state, SoGLRenderAction::BLEND);
  // A peeling separator or group below draws its children plainly: they are peeled here.
  ShadowGroupElement::setPeeling(state, true);
  const bool opaqueBound = shading.bind(action, ShadingVariant::OpaqueOnly) != nullptr;
  // The opaque pass notes whether it discarded a transparent fragment: without one there is
  // nothing to peel, and the view costs what Coin's own drawing costs.
  if (opaqueBound) pass.beginOpaque();
  draw(action);
  const bool transparentSeen = opaqueBound && pass.endOpaque();
  state->pop();
  // Without the opaque variant (Coin has said why) the plain pass drew everything.
  if (!opaqueBound) return {};

  const auto start = std::chrono::steady_clock::now();
  const int cap = options.maxPasses > 0
                      ? std::min(options.maxPasses, SoPeelingSeparator::kMaxPasses)
                      : SoPeelingSeparator::kMaxPasses;
  int passes = 0;
  statistics.listPasses = 0;
  statistics.listFragments = 0;
  statistics.listSlots = 0;
  const bool listed = (transparentSeen || !options.earlyTermination) && options.fragmentLists &&
                      drawFragmentLists(action, pass, shading, options, draw, statistics);
  if (listed) {
    passes = statistics.passes;
  } else if (transparentSeen || !options.earlyTermination) {
    const SbViewportRegion& region = SoViewportRegionElement::get(state);
    const SbVec2s origin = region.getViewportOriginPixels();
    const SbVec2s size = region.getViewportSizePixels();
    pass.begin(origin[0], origin[1], size[0], size[1]);
    state->push();
    setPeelPassState(state);
    for (;;) {
      const ShadingLocations* peelProgram =
          shading.bind(action, passes == 0    ? ShadingVariant::PeelInit
                               : options.dual ? ShadingVariant::PeelDual
                                              : ShadingVariant::PeelFrontToBack);
      // A peel variant did not build (Coin has said why): the passes done so far stand.
      if (peelProgram == nullptr) break;
      pass.startPass(passes);
      pass.setPeelUniforms(*peelProgram);
      draw(action);
      const bool deeper = pass.finishPass(passes, options.dual);
      ++passes;
      if (passes >= cap || (options.earlyTermination && !deeper)) break;
    }
    // The pop first: its depth element sends Coin's depth function, and the targets' scope
    // that end() closes then puts back GL's own (FreeCAD's GL_LESS, see drawFragmentLists).
    state->pop();
    pass.end(passes);
  }
  // The passes drew with blending, buffers and targets Coin did not choose; the scopes
  // restored GL, and Coin must not trust what it believes it last sent.
  SoGLLazyElement::getInstance(state)->reset(state, SoLazyElement::ALL_MASK);

  statistics.passes = passes;
  // The lists' passes are not timed on the GPU.
  statistics.gpuPeelMs = !listed && passTiming() && passes > 0 ? pass.gpuMs() : 0.0;
  statistics.peelMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  ++statistics.frames;
  return {};
}

}  // namespace ivshadow
