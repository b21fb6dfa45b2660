#include "nodes/GroupTracer.h"

#include "gl/NestedRenderScope.h"
#include "gl/TracedPicturePass.h"
#include "ivshadow/DeepShadowStatistics.h"
#include "ivshadow/SoTransparentShadowGroup.h"
#include "nodes/DeepShadowSettings.h"
#include "nodes/GroupContents.h"
#include "nodes/TracerActivity.h"
#include "scene/CoinRef.h"
#include "scene/EnvironmentValues.h"
#include "scene/SceneTriangles.h"
#include "scene/ScreenBox.h"
#include "scene/WarnOnce.h"

#include <Inventor/SbViewportRegion.h>
#include <Inventor/SoPath.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/elements/SoCacheElement.h>
#include <Inventor/elements/SoGLCacheContextElement.h>
#include <Inventor/elements/SoGLLazyElement.h>
#include <Inventor/elements/SoLightElement.h>
#include <Inventor/elements/SoModelMatrixElement.h>
#include <Inventor/elements/SoProjectionMatrixElement.h>
#include <Inventor/elements/SoViewingMatrixElement.h>
#include <Inventor/elements/SoViewportRegionElement.h>
#include <Inventor/errors/SoDebugError.h>
#include <Inventor/lists/SoNodeList.h>
#include <Inventor/lists/SoPathList.h>
#include <Inventor/nodes/SoSeparator.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace ivshadow {
namespace {

// What the state above the group holds that the traced picture depends on and the group
// is not notified of: the lights in force (node, version, where) and the model matrix, then
// the lighting's material values, the light model and the environment. `lights` gets the
// first part, `shading` the second.
void stateAbove(SoState* state, std::vector<float>& lights, std::vector<float>& shading) {
  lights.clear();
  shading.clear();
  const SoNodeList& inForce = SoLightElement::getLights(state);
  for (int i = 0; i < inForce.getLength(); ++i) {
    lights.push_back(float(inForce[i]->getNodeId()));
    const SbMatrix& matrix = SoLightElement::getMatrix(state, i);
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) lights.push_back(matrix[r][c]);
  }
  const SbMatrix& model = SoModelMatrixElement::get(state);
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) shading.push_back(model[r][c]);
  for (const SbColor* colour :
       {&SoLazyElement::getAmbient(state), &SoLazyElement::getEmissive(state),
        &SoLazyElement::getSpecular(state)})
    for (int i = 0; i < 3; ++i) shading.push_back((*colour)[i]);
  shading.push_back(SoLazyElement::getShininess(state));
  shading.push_back(float(SoLazyElement::getLightModel(state)));
  const EnvironmentValues e = EnvironmentValues::of(state);
  shading.insert(shading.end(),
                 {e.ambientIntensity, e.ambientColour[0], e.ambientColour[1], e.ambientColour[2],
                  e.attenuation[0], e.attenuation[1], e.attenuation[2], float(e.fogType),
                  e.fogColour[0], e.fogColour[1], e.fogColour[2], e.fogVisibility, e.fogStart});
}

double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

}  // namespace

GroupTracer::GroupTracer(SoSeparator* owner, const char* setting)
    : owner_(owner), setting_(setting), refineSensor_(&GroupTracer::refine, this) {}
GroupTracer::~GroupTracer() = default;

void GroupTracer::refine(void* self, SoSensor*) {
  auto* tracer = static_cast<GroupTracer*>(self);
  // The notification reaches whoever redraws the scene (a viewer's scene manager); the next
  // frame finds nothing changed and traces the full picture.
  const TracerActivity::Scope touching(TracerActivity::RefineTouch);
  tracer->owner_->touch();
}

const float* GroupTracer::reducedLimit(Context& context, const std::vector<float>& depth,
                                       const std::array<int, 4>& viewport, int width, int height) {
  context.depthReduced.resize(std::size_t(width) * std::size_t(height));
  for (int y = 0; y < height; ++y) {
    const int fullY =
        std::min(viewport[3] - 1, int((float(y) + 0.5f) * float(viewport[3]) / float(height)));
    for (int x = 0; x < width; ++x) {
      const int fullX =
          std::min(viewport[2] - 1, int((float(x) + 0.5f) * float(viewport[2]) / float(width)));
      context.depthReduced[std::size_t(y) * std::size_t(width) + std::size_t(x)] =
          depth[std::size_t(fullY) * std::size_t(viewport[2]) + std::size_t(fullX)];
    }
  }
  return context.depthReduced.data();
}

void GroupTracer::updateScene(SoGLRenderAction* action, const GroupContents& contents,
                              DeepShadowStatistics& statistics) {
  SoState* state = action->getState();
  const SbMatrix& viewing = SoViewingMatrixElement::get(state);
  const SbMatrix& projection = SoProjectionMatrixElement::get(state);
  stateAbove(state, lightsNow_, shadingNow_);
  const SbVec2s size = SoViewportRegionElement::get(state).getViewportSizePixels();
  // The triangles are kept in the world: a transform above the group moves them, as does a
  // change of the material or environment above it, which the group is not notified of. A
  // camera inside the group was read with the viewport's aspect.
  const bool shapesKept =
      scene_ && castersVersion_ == contents.castersVersion() &&
      (!contents.hasCamera() || readSize_ == size) && viewVersion_ == contents.viewVersion() &&
      shadingNow_ == shadingAbove_ &&
      ((sceneViewing_ == viewing && sceneProjection_ == projection) || !scene_->viewDependent());
  if (shapesKept && mapsVersion_ == contents.mapsVersion() && sceneViewing_ == viewing &&
      lightsNow_ == lightsAbove_)
    return;
  const auto start = std::chrono::steady_clock::now();
  // A copy: the action's own path changes as it traverses; this one is applied to.
  const CoinRef<SoPath> toGroup(action->getCurPath()->copy());
  // A moved light, or a moved camera (lights before it are fixed in eye space), changes only
  // the lights: they are read again without the shapes.
  lightsAbove_.swap(lightsNow_);
  shadingAbove_.swap(shadingNow_);
  sceneProjection_ = projection;
  if (shapesKept && scene_->updateLights(toGroup.get())) {
    mapsVersion_ = contents.mapsVersion();
    sceneViewing_ = viewing;
    ++sceneVersion_;
    statistics.tracerLightsMs = millisecondsSince(start);
    return;
  }
  scene_ = SceneTracer::fromPath(toGroup.get(), size[0], size[1]);
  readSize_ = size;
  readPathLength_ = toGroup->getLength();
  ++shapesVersion_;
  bounds_ = scene_->bounds();
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
                                "%s (%s) draws %s through GL, without shadows: "
                                "lines, points and screen-aligned pixels are not traced",
                                describeNode(owner_).c_str(), setting_, shape.c_str());
}

GroupTracer::Context* GroupTracer::contextFor(SoState* state) {
  return contexts_.get(SoGLCacheContextElement::get(state), [this] {
    std::string whyNot;
    auto pass = TracedPicturePass::create(whyNot);
    if (!pass) {
      if (firstWarning(owner_, "no traced picture"))
        SoDebugError::postWarning(owner_->getTypeId().getName().getString(),
                                  "%s: %s cannot draw its picture (%s); rendering "
                                  "with GL",
                                  describeNode(owner_).c_str(), setting_, whyNot.c_str());
      return std::unique_ptr<Context>();
    }
    auto made = std::make_unique<Context>();
    made->pass = std::move(pass);
    return made;
  });
}

bool GroupTracer::render(SoGLRenderAction* action, const GroupContents& contents,
                         const TracerSettings& settings, DeepShadowStatistics& statistics) {
  SoState* state = action->getState();
  Context* context = contextFor(state);
  if (context == nullptr) return false;
  // The picture belongs to this frame's camera and depth: a render cache must not replay it.
  SoCacheElement::invalidate(state);
  try {
    updateScene(action, contents, statistics);
  } catch (const std::runtime_error& error) {
    if (firstWarning(owner_, std::string("tracer failed: ") + error.what()))
      SoDebugError::postWarning(owner_->getTypeId().getName().getString(),
                                "%s: %s failed (%s); rendering with GL",
                                describeNode(owner_).c_str(), setting_, error.what());
    scene_.reset();
    return false;
  }

  const SbViewportRegion& region = SoViewportRegionElement::get(state);
  const SbVec2s origin = region.getViewportOriginPixels();
  const SbVec2s size = region.getViewportSizePixels();
  View view;
  view.viewport = {origin[0], origin[1], size[0], size[1]};
  // A camera inside the group views its children, as GL would draw them (the one read with
  // the shapes); else the camera in force where the group is traversed.
  const bool cameraInside = contents.hasCamera() && scene_->haveCamera();
  view.viewing = cameraInside ? &scene_->viewing() : &SoViewingMatrixElement::get(state);
  view.projection = cameraInside ? &scene_->projection() : &SoProjectionMatrixElement::get(state);
  // A trace this frame may be reduced (a motion goes on): stretched, its pixels take depths
  // from beyond the region of the picture before, where the depth it was traced at is old.
  const bool mayReduce = context->tracedLastFrame && settings.movingResolution < 1.0f;
  const bool depthAsTraced = readWhatGlDrew(*context, view, mayReduce);
  // The same camera rays through the same shapes: they meet the surfaces kept.
  const bool sameView = context->shapes == shapesVersion_ && context->viewing == *view.viewing &&
                        context->projection == *view.projection &&
                        context->viewport == view.viewport &&
                        (depthAsTraced || context->depthNow == context->depthTraced);
  const bool kept = sameView && context->scene == sceneVersion_;
  // A reduced picture is refined by the first frame that finds nothing changed.
  const bool refining = kept && context->reduced;
  const bool hadPicture = context->scene != 0;
  const bool traced = !kept || refining;
  if (traced) {
    // A change right after a frame that traced for a change is part of a motion.
    const Motion motion{!kept && context->tracedLastFrame, sameView, depthAsTraced};
    if (!tracePicture(*context, view, motion, settings, statistics)) return false;
    if (refining) ++statistics.tracerRefines;
  }
  // A motion: this frame traced because something changed since a picture was drawn. The
  // first picture and a refined one are not (the next change is then traced in full).
  context->tracedLastFrame = !kept && hadPicture;
  present(action, *context, view.viewport, traced);
  return true;
}

bool GroupTracer::readWhatGlDrew(Context& context, const View& view, bool mayReduce) {
  const std::array<int, 4>& viewport = view.viewport;
  // Where the picture of this view changes nothing, what GL drew does not matter to it: the
  // region of the picture traced when this is its view (a trace of another view or of other
  // shapes reads it all). A reduced picture is stretched: read it all too.
  const bool pictureView = context.scene != 0 && context.shapes == shapesVersion_ &&
                           context.viewing == *view.viewing &&
                           context.projection == *view.projection && context.viewport == viewport &&
                           !context.reduced && !mayReduce;
  const std::array<int, 4> region =
      pictureView ? context.region : std::array<int, 4>{0, 0, viewport[2], viewport[3]};
  // As stored: while its depth is the one traced at, the depths need no reading as floats.
  context.frame.readBefore(viewport, region);
  if (context.frame.depthAsTraced()) return true;
  if (const std::string error = context.pass->readDepth(viewport, context.depthNow);
      !error.empty() && firstWarning(owner_, "depth read: " + error))
    SoDebugError::postWarning(owner_->getTypeId().getName().getString(),
                              "%s: the framebuffer's depth could not be read (%s); the traced "
                              "picture covers what GL drew before it",
                              describeNode(owner_).c_str(), error.c_str());
  return false;
}

bool GroupTracer::tracePicture(Context& context, const View& view, const Motion& motion,
                               const TracerSettings& settings, DeepShadowStatistics& statistics) {
  const auto start = std::chrono::steady_clock::now();
  const std::array<int, 4>& viewport = view.viewport;
  const std::vector<float>& depth = motion.depthAsTraced ? context.depthTraced : context.depthNow;
  const float scale = motion.moving ? settings.movingResolution : 1.0f;
  TraceOptions options;
  options.width = std::max(1, int(std::ceil(float(viewport[2]) * scale)));
  options.height = std::max(1, int(std::ceil(float(viewport[3]) * scale)));
  const bool reduced = options.width < viewport[2] || options.height < viewport[3];
  options.bounceSamples = settings.bounceSamples;
  options.depthBuffer = TracedPicturePass::drawDepthBuffer();
  options.viewportWidth = viewport[2];
  options.viewportHeight = viewport[3];
  const float* limit = reduced
                           ? reducedLimit(context, depth, viewport, options.width, options.height)
                           : depth.data();
  // The first picture keeps no surfaces: a single frame (a batch render) would only pay for
  // them (about 15 MB at 800 x 600, each page a fault); the first change traces its camera
  // rays again and keeps them for the changes after it. Nor does a frame whose view changed,
  // the first of a camera's motion included: the next frame's rays may meet other surfaces,
  // and keeping them made that first frame cost half as much again at 8 layers (23 MB at
  // 400 x 400). A change that keeps the view (a light's, after the camera stopped) keeps them.
  const bool viewChanged = !motion.sameView;
  if (viewChanged) context.surfaces.rows.clear();
  options.surfaces = context.scene != 0 && !viewChanged ? &context.surfaces : nullptr;
  options.reuseSurfaces = motion.sameView;
  scene_->trace(*view.viewing, *view.projection, limit, options, pixels_);
  const std::string error = context.pass->upload(options.width, options.height, pixels_.rgba.data(),
                                                 pixels_.depth.data());
  if (!error.empty()) {
    if (firstWarning(owner_, "traced picture upload: " + error))
      SoDebugError::postWarning(owner_->getTypeId().getName().getString(),
                                "%s: GL could not hold the traced picture (%s); rendering "
                                "with GL",
                                describeNode(owner_).c_str(), error.c_str());
    context.scene = 0;
    context.surfaces.rows.clear();
    context.frame.forget();
    return false;
  }
  context.scene = sceneVersion_;
  context.shapes = shapesVersion_;
  context.viewing = *view.viewing;
  context.projection = *view.projection;
  context.viewport = viewport;
  if (!motion.depthAsTraced) context.depthTraced.swap(context.depthNow);
  // A stretched picture's pixel spreads over 1 / scale of the viewport's, and takes the
  // bilinear mean of its neighbours': the margin holds both.
  const int spread = int(std::ceil(float(viewport[2]) / float(options.width))) +
                     int(std::ceil(float(viewport[3]) / float(options.height)));
  // The shapes GL draws after the picture are not in the box; before them the picture's depth
  // is written again (restoreDepth), wherever GL may have cleared it: the whole viewport.
  context.region = scene_->untracedPaths().empty()
                       ? screenBox(bounds_, *view.viewing, *view.projection, viewport[2],
                                   viewport[3], 2 + spread)
                       : std::array<int, 4>{0, 0, viewport[2], viewport[3]};
  context.frame.markTraced(context.region);
  context.reduced = reduced;
  if (reduced) {
    if (refineSensor_.isScheduled()) refineSensor_.unschedule();
    refineSensor_.setTimeFromNow(SbTime(kRefineDelaySeconds));
    refineSensor_.schedule();
  }
  statistics.tracerMs = millisecondsSince(start);
  statistics.raysTraced = pixels_.shadowRays;
  statistics.tracerWidth = options.width;
  statistics.tracerHeight = options.height;
  statistics.tracerReduced = reduced ? 1 : 0;
  statistics.tracerCameraRays = pixels_.cameraRays;
  ++statistics.tracerFrames;
  return true;
}

void GroupTracer::present(SoGLRenderAction* action, Context& context,
                          const std::array<int, 4>& viewport, bool traced) {
  // A frame that traced nothing puts back the framebuffer the picture left last, when what GL
  // drew before it is the same; else it composites the picture and keeps what that leaves.
  // A frame that traced keeps nothing: a single frame (a batch render) or a motion would only
  // pay for the copy.
  if (traced || !context.frame.restore()) {
    context.pass->draw(viewport, context.region);
    if (!traced) context.frame.keep();
  }
  SoState* state = action->getState();
  // GL is restored; Coin must not trust what it believes it last sent.
  SoGLLazyElement::getInstance(state)->reset(state, SoLazyElement::ALL_MASK);
  if (!scene_->untracedPaths().empty()) {
    drawingUntraced_ = &context;
    untracedViewport_ = viewport;
    untracedRegion_ = context.region;
    drawUntraced(action);
    drawingUntraced_ = nullptr;
  }
}

void GroupTracer::restoreDepth(SoGLRenderAction* action) {
  if (drawingUntraced_ == nullptr) return;
  drawingUntraced_->pass->drawDepth(untracedViewport_, untracedRegion_);
  drawingUntraced_ = nullptr;
  SoState* state = action->getState();
  SoGLLazyElement::getInstance(state)->reset(state, SoLazyElement::ALL_MASK);
}

void GroupTracer::drawUntraced(SoGLRenderAction* action) {
  SoState* state = action->getState();
  // Each shape's path below the owner, on the path this action took to the owner (another
  // viewer's root, or a graph changed above the group, has another): the camera, the lights
  // and the transforms on the way are traversed again, and every group on them renders as a
  // plain separator.
  SoPathList paths;
  for (const std::vector<int>& below : scene_->untracedPaths()) {
    SoPath* path = action->getCurPath()->copy();
    for (std::size_t i = std::size_t(readPathLength_); i < below.size(); ++i)
      path->append(below[i]);
    paths.append(path);
  }
  SoGLRenderAction nested(SoViewportRegionElement::get(state));
  nested.setCacheContext(action->getCacheContext());
  nested.setTransparencyType(action->getTransparencyType());
  {
    const NestedRenderScope scope;
    const TracerActivity::Scope drawing(TracerActivity::DrawingUntraced);
    nested.apply(paths, FALSE);
  }
  SoGLLazyElement::getInstance(state)->reset(state, SoLazyElement::ALL_MASK);
}

}  // namespace ivshadow
