#include "nodes/GroupTracer.h"

#include "callbacks/TracedPicturePass.h"
#include "ivshadow/DeepShadowStatistics.h"
#include "ivshadow/SoTransparentShadowGroup.h"
#include "nodes/GroupContents.h"
#include "scene/CoinRef.h"
#include "scene/SceneTriangles.h"
#include "scene/WarnOnce.h"

#include <Inventor/SbViewportRegion.h>
#include <Inventor/SoPath.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/elements/SoCacheElement.h>
#include <Inventor/elements/SoGLCacheContextElement.h>
#include <Inventor/elements/SoGLLazyElement.h>
#include <Inventor/elements/SoProjectionMatrixElement.h>
#include <Inventor/elements/SoViewingMatrixElement.h>
#include <Inventor/elements/SoViewportRegionElement.h>
#include <Inventor/errors/SoDebugError.h>
#include <Inventor/nodes/SoSeparator.h>

#include <chrono>
#include <stdexcept>

namespace ivshadow {
namespace {

double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

}  // namespace

GroupTracer::GroupTracer(SoSeparator* owner) : owner_(owner) {}
GroupTracer::~GroupTracer() = default;

void GroupTracer::updateScene(SoGLRenderAction* action, const GroupContents& contents,
                              DeepShadowStatistics& statistics) {
  SoState* state = action->getState();
  const SbMatrix& viewing = SoViewingMatrixElement::get(state);
  const bool shapesKept = scene_ && castersVersion_ == contents.castersVersion() &&
                          viewVersion_ == contents.viewVersion() &&
                          (sceneViewing_ == viewing || !scene_->viewDependent());
  if (shapesKept && mapsVersion_ == contents.mapsVersion() && sceneViewing_ == viewing) return;
  const auto start = std::chrono::steady_clock::now();
  const SbVec2s size = SoViewportRegionElement::get(state).getViewportSizePixels();
  // A copy: the action's own path changes as it traverses; this one is applied to.
  const CoinRef<SoPath> toGroup(action->getCurPath()->copy());
  // A moved light, or a moved camera (lights before it are fixed in eye space), changes only
  // the lights: they are read again without the shapes.
  if (shapesKept && scene_->updateLights(toGroup.get())) {
    mapsVersion_ = contents.mapsVersion();
    sceneViewing_ = viewing;
    ++sceneVersion_;
    statistics.tracerLightsMs = millisecondsSince(start);
    return;
  }
  scene_ = SceneTracer::fromPath(toGroup.get(), size[0], size[1]);
  castersVersion_ = contents.castersVersion();
  mapsVersion_ = contents.mapsVersion();
  viewVersion_ = contents.viewVersion();
  sceneViewing_ = viewing;
  ++sceneVersion_;
  statistics.tracerSceneMs = millisecondsSince(start);
  ++statistics.tracerScenes;
  for (const std::string& shape : scene_->untracedShapes())
    if (firstWarning(owner_, "not traced: " + shape))
      SoDebugError::postWarning(owner_->getTypeId().getName().getString(),
                                "%s (renderer TRACER) does not draw %s, which is drawn with "
                                "lines, points or screen-aligned pixels",
                                describeNode(owner_).c_str(), shape.c_str());
}

bool GroupTracer::render(SoGLRenderAction* action, const GroupContents& contents,
                         DeepShadowStatistics& statistics) {
  SoState* state = action->getState();
  Context* context = contexts_.get(SoGLCacheContextElement::get(state), [this] {
    std::string whyNot;
    auto pass = TracedPicturePass::create(whyNot);
    if (!pass) {
      if (firstWarning(owner_, "no traced picture"))
        SoDebugError::postWarning(owner_->getTypeId().getName().getString(),
                                  "%s: renderer TRACER cannot draw its picture (%s); rendering "
                                  "with GL",
                                  describeNode(owner_).c_str(), whyNot.c_str());
      return std::unique_ptr<Context>();
    }
    auto made = std::make_unique<Context>();
    made->pass = std::move(pass);
    return made;
  });
  if (context == nullptr) return false;
  // The picture belongs to this frame's camera and depth: a render cache must not replay it.
  SoCacheElement::invalidate(state);
  try {
    updateScene(action, contents, statistics);
  } catch (const std::runtime_error& error) {
    if (firstWarning(owner_, std::string("tracer failed: ") + error.what()))
      SoDebugError::postWarning(owner_->getTypeId().getName().getString(),
                                "%s: renderer TRACER failed (%s); rendering with GL",
                                describeNode(owner_).c_str(), error.what());
    scene_.reset();
    return false;
  }

  const SbViewportRegion& region = SoViewportRegionElement::get(state);
  const SbVec2s origin = region.getViewportOriginPixels();
  const SbVec2s size = region.getViewportSizePixels();
  const std::array<int, 4> viewport{origin[0], origin[1], size[0], size[1]};
  const SbMatrix& viewing = SoViewingMatrixElement::get(state);
  const SbMatrix& projection = SoProjectionMatrixElement::get(state);
  context->pass->readDepth(viewport, context->depthNow);
  const bool kept = context->scene == sceneVersion_ && context->viewing == viewing &&
                    context->projection == projection && context->viewport == viewport &&
                    context->depthNow == context->depthTraced;
  if (!kept) {
    const auto start = std::chrono::steady_clock::now();
    TraceOptions options;
    options.width = viewport[2];
    options.height = viewport[3];
    const auto& group = *static_cast<const SoTransparentShadowGroup*>(owner_);
    options.bounceSamples = group.bounce.getValue() ? group.bounceLights.getValue() : 0;
    scene_->trace(viewing, projection, context->depthNow.data(), options, pixels_);
    const std::string error =
        context->pass->upload(viewport, pixels_.rgba.data(), pixels_.depth.data());
    if (!error.empty()) {
      if (firstWarning(owner_, "traced picture upload: " + error))
        SoDebugError::postWarning(owner_->getTypeId().getName().getString(),
                                  "%s: GL could not hold the traced picture (%s); rendering "
                                  "with GL",
                                  describeNode(owner_).c_str(), error.c_str());
      context->scene = 0;
      return false;
    }
    context->scene = sceneVersion_;
    context->viewing = viewing;
    context->projection = projection;
    context->viewport = viewport;
    context->depthTraced.swap(context->depthNow);
    statistics.tracerMs = millisecondsSince(start);
    statistics.raysTraced = pixels_.shadowRays;
    ++statistics.tracerFrames;
  }
  context->pass->draw(viewport);
  // GL is restored; Coin must not trust what it believes it last sent.
  SoGLLazyElement::getInstance(state)->reset(state, SoLazyElement::ALL_MASK);
  return true;
}

}  // namespace ivshadow
