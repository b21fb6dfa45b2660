#include "nodes/TransparentShadowGroupImpl.h"

#include "nodes/DeepShadowSettings.h"
#include "nodes/DepthPrecision.h"
#include "nodes/TracerActivity.h"

#include "gl/DeepShadowPass.h"
#include "gl/GlCapabilities.h"
#include "gl/GlStateScope.h"
#include "gl/ImperfectShadowMaps.h"
#include "gl/PeelPass.h"
#include "gl/RayShadowPass.h"
#include "gl/ShadingUniforms.h"
#include "ivshadow/SoTransparentShadowGroup.h"
#include "nodes/DepthPeeling.h"
#include "nodes/MapMethod.h"
#include "nodes/RayMethod.h"
#include "nodes/ShadowGroupElement.h"
#include "nodes/TransparencyOverride.h"
#include "raytrace/CastingLight.h"
#include "scene/SceneTriangles.h"
#include "scene/WarnOnce.h"

#include <Inventor/SoPath.h>
#include <Inventor/actions/SoCallbackAction.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/actions/SoGetMatrixAction.h>
#include <Inventor/annex/FXViz/elements/SoShadowStyleElement.h>
#include <Inventor/annex/FXViz/nodes/SoShadowSpotLight.h>
#include <Inventor/elements/SoCacheElement.h>
#include <Inventor/elements/SoDepthBufferElement.h>
#include <Inventor/elements/SoGLCacheContextElement.h>
#include <Inventor/elements/SoGLLazyElement.h>
#include <Inventor/elements/SoGLShaderProgramElement.h>
#include <Inventor/elements/SoModelMatrixElement.h>
#include <Inventor/elements/SoProjectionMatrixElement.h>
#include <Inventor/elements/SoShapeStyleElement.h>
#include <Inventor/elements/SoViewVolumeElement.h>
#include <Inventor/elements/SoViewingMatrixElement.h>
#include <Inventor/elements/SoViewportRegionElement.h>
#include <Inventor/errors/SoDebugError.h>
#include <Inventor/nodes/SoCamera.h>
#include <Inventor/nodes/SoSeparator.h>

#include <algorithm>
#include <chrono>
#include <set>

namespace ivshadow {
namespace {

std::string lightName(const SoLight& light) {
  const std::string name = light.getName().getString();
  return name.empty() ? std::string("(unnamed)") : "'" + name + "'";
}

// Once per light: GL could not give what its shadow needs, and it lights without one.
void warnNoShadow(const SoLight& light, const std::string& failure) {
  if (!firstWarning(&light, "no shadow: " + failure)) return;
  const std::string name = light.getName().getString();
  const std::string type = std::string("So") + light.getTypeId().getName().getString();
  const std::string label = name.empty() ? type : type + " \"" + name + "\"";
  SoDebugError::postWarning(type.c_str(), "%s: %s; it lights without a shadow", label.c_str(),
                            failure.c_str());
}

// What the shading must compile in for the first `count` slots, the ones it is given.
ShadingFeatures featuresOf(const std::vector<MapState>& maps, std::size_t count) {
  ShadingFeatures features;
  for (std::size_t slot = 0; slot < std::min(count, maps.size()); ++slot) {
    const MapState& map = maps[slot];
    if (shadowsPerPixel(map.method)) {
      features.rays = true;
      continue;
    }
    features.maps = true;
    (map.method == ShadowMethod::OpacityMap ? features.opacity : features.deep) = true;
    (map.settings.filterWidth > 0 ? features.filtered : features.nearest) = true;
  }
  return features;
}

}  // namespace

TransparentShadowGroupImpl::TransparentShadowGroupImpl(SoSeparator* owner,
                                                       ChildrenRenderer renderChildren)
    : owner_(owner),
      // Every pass over the children (a RAYS capture, a peel, the shading) starts with the GL
      // lights past those on at the group black, as the frame's first did: a light below the
      // group sets its GL light only where it is traversed, and the pass before left its
      // values there, lighting shapes traversed before it (brighter than Coin and the tracer).
      renderChildren_(
          [this, draw = std::move(renderChildren)](SoGLRenderAction* action, bool inPath) {
            darkenLights(shading_.outsideLights());
            draw(action, inPath);
          }),
      contents_(owner, true),
      shading_(contents_),
      tracer_(owner, "renderer TRACER") {}

TransparentShadowGroupImpl::~TransparentShadowGroupImpl() {
  forgetWarnings(owner_);
}

void TransparentShadowGroupImpl::changed(SoNotList* list) {
  // A traced group asking for its refined frame (this one or one inside) changes nothing the
  // group holds.
  if (TracerActivity::active(TracerActivity::RefineTouch)) return;
  contents_.changed(list);
}

void TransparentShadowGroupImpl::buildSlot(SoGLRenderAction* action, Context& context,
                                           std::size_t slot, std::uint64_t memoryBudget,
                                           std::optional<ViewCorners>& view) {
  DeepShadowPass& pass = *context.pass;
  const GroupContents::Light& entry = contents_.lights()[slot];
  const SceneTriangles& casters = contents_.casters();
  auto& group = *static_cast<SoTransparentShadowGroup*>(owner_);
  MapState& map = context.maps[slot];
  map = MapState{};
  map.settings = castingSettings(*entry.light, group, pass.maxTextureSize());
  SoGetMatrixAction matrixAction(action->getViewportRegion());
  if (const CoinRef<SoPath> path = contents_.lightPath(entry)) matrixAction.apply(path.get());
  CastingLight where;
  castingLight(*entry.light, group, matrixAction.getMatrix(), where);
  map.kind = where.kind;
  map.position = where.position;
  map.axis = where.axis;
  map.cutOffAngle = where.cutOffAngle;
  // Coin's SoShadowSpotLight bounds its shadow map by nearDistance and farDistance (-1:
  // fitted): the map's range, the same meaning.
  if (entry.light->isOfType(SoShadowSpotLight::getClassTypeId())) {
    const auto& spot = static_cast<const SoShadowSpotLight&>(*entry.light);
    map.settings.nearRadius = spot.nearDistance.getValue();
    map.settings.farRadius = spot.farDistance.getValue();
    if (!(map.settings.nearRadius < map.settings.farRadius) && map.settings.farRadius > 0.0f)
      map.settings.nearRadius = map.settings.farRadius = -1.0f;
  }
  // Only a directional map is fitted to the view; with a camera inside the group, computing it
  // is a traversal of the camera's path.
  if (map.kind == LightKind::Directional && !view) view = this->view(action);
  fitMapFrame(map, casters.bounds, view.value_or(ViewCorners{}));
  ShadowMethod method = map.settings.method;
  if (method == ShadowMethod::Auto) {
    method = context.softwareRenderer ? ShadowMethod::Rays : ShadowMethod::Map;
    if (methodLogged_.insert(entry.light).second)
      SoDebugError::postInfo(entry.deep ? "SoDeepShadowLight" : "SoTransparentShadowGroup",
                             "light %s: method AUTO uses %s on %s", lightName(*entry.light).c_str(),
                             shadowMethodName(method), context.renderer.c_str());
  }
  SbVec3f castersAxis;
  float castersAngle = 0.0f;
  if ((method == ShadowMethod::Map || method == ShadowMethod::OpacityMap) &&
      castersCone(map, casters.bounds, castersAxis, castersAngle) &&
      castersAngle < kMinMapConeAngle) {
    if (firstWarning(entry.light, "too far for a map"))
      SoDebugError::postWarning(entry.deep ? "SoDeepShadowLight" : "SoTransparentShadowGroup",
                                "light %s: its casters fill %g radians seen from it, too little "
                                "for a map to tell their depths apart in floats; it traces "
                                "shadow rays instead",
                                lightName(*entry.light).c_str(), double(castersAngle));
    method = ShadowMethod::Rays;
  }
  if (method == ShadowMethod::Volumes) {
    if (!context.rays) context.rays = std::make_unique<RayMethod>(context.pass->rayUnit(0));
    std::string whyNot;
    if (!context.rays->volumesAvailable(whyNot)) {
      // The exact answer by the other exact method; RAYS itself falls back to the map.
      if (firstWarning(entry.light, "volumes: " + whyNot))
        SoDebugError::postWarning(entry.deep ? "SoDeepShadowLight" : "SoTransparentShadowGroup",
                                  "light %s: method VOLUMES cannot be drawn here (%s); it traces "
                                  "shadow rays instead",
                                  lightName(*entry.light).c_str(), whyNot.c_str());
      method = ShadowMethod::Rays;
    }
  }
  if (method == ShadowMethod::Rays &&
      !rayCasters_.ready(casters, contents_.castersVersion(), entry.light, lightName(*entry.light),
                         "using its deep shadow map", statistics_))
    method = ShadowMethod::Map;
  // VOLUMES shares the capture and the shading lookup of RAYS; only what fills the
  // visibility differs (RayMethod).
  idleFields_.used(*entry.light, group, method);
  map.method = method;
  if (method == ShadowMethod::OpacityMap) fitSlices(map, casters.transparentBounds);
  map.model = castingColourModel(*entry.light, group, casters.hasColouredTransparent);
  map.coloured = map.model != ShadowColourModel::Monochrome;
  DeepShadowLightStatistics& light = statistics_.lights[slot];
  light = DeepShadowLightStatistics{};
  light.name = entry.light->getName().getString();
  light.coloured = map.coloured;
  light.method = method;
  if (shadowsPerPixel(method)) {
    // A map kept from when the light had one (it may be hundreds of megabytes) goes.
    pass.dropSlot(int(slot));
    return;
  }
  // The casters go to GL memory for a map only: a group whose lights all trace keeps them in
  // Embree alone.
  if (context.castersVersion != contents_.castersVersion()) {
    pass.uploadCasters(casters);
    context.castersVersion = contents_.castersVersion();
  }
  buildSlotMap(pass, int(slot), map, light, *entry.light, memoryBudget);
}

void TransparentShadowGroupImpl::buildMaps(SoGLRenderAction* action, Context& context) {
  const auto start = std::chrono::steady_clock::now();
  context.buildTimer.start();
  const std::size_t lights = contents_.lights().size();
  context.maps.assign(lights, MapState{});
  statistics_.lights.assign(lights, DeepShadowLightStatistics{});
  const std::uint64_t memoryBudget = mapMemoryBudget(context.softwareRenderer);
  std::optional<ViewCorners> view;
  for (std::size_t slot = 0; slot < lights; ++slot)
    buildSlot(action, context, slot, memoryBudget, view);
  idleFields_.say();
  context.pass->keepSlots(int(lights));
  finishBuild(action, context, start);
  statistics_.casterTriangles = int(contents_.casters().triangleCount());
  context.mapsVersion = contents_.mapsVersion();
}

void TransparentShadowGroupImpl::finishBuild(SoGLRenderAction* action, Context& context,
                                             std::chrono::steady_clock::time_point start) {
  // The build restored every GL state it changed; the lazy element is told anyway, since the
  // restored values are what GL holds and Coin must not skip sending its own.
  SoGLLazyElement::getInstance(action->getState())
      ->reset(action->getState(), SoLazyElement::ALL_MASK);
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  statistics_.lastBuildMs = ms;
  context.buildTimer.stop();
  statistics_.gpuBuildMs = context.buildTimer.elapsedMs();
  statistics_.totalBuildMs += ms;
  ++statistics_.rebuilds;
}

ViewCorners TransparentShadowGroupImpl::view(SoGLRenderAction* action) const {
  SoState* state = action->getState();
  const CoinRef<SoPath> cameraPath = contents_.cameraPath();
  if (!cameraPath)
    return viewCorners(SoViewVolumeElement::get(state), SoModelMatrixElement::get(state));
  // The camera's view volume in the coordinates of its path's head, the group.
  SbViewVolume volume = SoViewVolumeElement::get(state);
  SoCallbackAction camera(action->getViewportRegion());
  camera.addPostCallback(
      SoCamera::getClassTypeId(),
      [](void* data, SoCallbackAction* a, const SoNode*) {
        *static_cast<SbViewVolume*>(data) = a->getViewVolume();
        return SoCallbackAction::CONTINUE;
      },
      &volume);
  camera.apply(cameraPath.get());
  return viewCorners(volume, SbMatrix::identity());
}

void TransparentShadowGroupImpl::refitToView(SoGLRenderAction* action, Context& context) {
  const auto start = std::chrono::steady_clock::now();
  std::optional<ViewCorners> view;
  bool rebuilt = false;
  for (std::size_t slot = 0; slot < context.maps.size(); ++slot) {
    const MapState& map = context.maps[slot];
    if (shadowsPerPixel(map.method) || map.kind != LightKind::Directional) continue;
    if (!view) view = this->view(action);
    if (mapServesView(map, contents_.casters().bounds, *view)) continue;
    if (!rebuilt) context.buildTimer.start();
    buildSlot(action, context, slot, mapMemoryBudget(context.softwareRenderer), view);
    rebuilt = true;
  }
  if (rebuilt) {
    idleFields_.say();
    finishBuild(action, context, start);
  }
}

bool TransparentShadowGroupImpl::updateBounce(SoGLRenderAction* action, Context& context) {
  auto& group = *static_cast<SoTransparentShadowGroup*>(owner_);
  BounceSettings settings = resolveBounce(group);
  if (!settings.on || contents_.lights().empty()) {
    bounce_.clear();
    bouncePlaced_ = 0;
    context.bounceMaps.reset();
    context.bounceVersion = context.bouncePoints = 0;
    context.bounceMapSize = 0;
    statistics_.bounceLights = statistics_.bounceSamples = 0;
    statistics_.bounceBytes = 0;
    statistics_.bouncePlaceMs = statistics_.bounceMapMs = 0.0;
    return false;
  }
  // The atlas within this context's map budget: smaller tiles, said once. The lights do not
  // depend on it; each context draws its own maps.
  const std::uint64_t budget = mapMemoryBudget(context.softwareRenderer);
  const int asked = settings.mapSize;
  while (settings.mapSize > kMinBounceMapSize &&
         ImperfectShadowMaps::bytesFor(settings.lights, settings.mapSize) > budget)
    settings.mapSize /= 2;
  if (settings.mapSize != asked && firstWarning(owner_, "bounce budget"))
    SoDebugError::postWarning(owner_->getTypeId().getName().getString(),
                              "%s: bounceLights %d with maps of %d texels exceed the map memory "
                              "budget; using %d texels",
                              describeNode(owner_).c_str(), settings.lights, asked,
                              settings.mapSize);
  if (bouncePlaced_ != contents_.mapsVersion()) {
    bouncePlaced_ = contents_.mapsVersion();
    // The lights are placed with Embree whatever the lights' methods.
    const SoLight* first = contents_.lights().front().light;
    if (rayCasters_.ready(contents_.casters(), contents_.castersVersion(), first, lightName(*first),
                          "the group renders without its bounce", statistics_))
      bounce_.place(settings, contents_, context.maps, *rayCasters_.scene(),
                    contents_.castersVersion(), action->getState(), statistics_);
    else
      bounce_.clear();
  }
  if (context.bounceVersion != bounce_.version() || context.bounceMapSize != settings.mapSize) {
    context.bounceVersion = bounce_.version();
    context.bounceMapSize = settings.mapSize;
    if (!context.bounceMaps) context.bounceMaps = std::make_unique<ImperfectShadowMaps>();
    BounceMapRequest request;
    request.lights = &bounce_.packed();
    request.lightCount = int(bounce_.lights().lights.size());
    request.points = &bounce_.points();
    request.pointsChanged = context.bouncePoints != bounce_.pointsVersion();
    context.bouncePoints = bounce_.pointsVersion();
    request.mapSize = settings.mapSize;
    request.lift = bounce_.lift();
    context.bounceTimer.start();
    const std::string failure = context.bounceMaps->build(request);
    context.bounceTimer.stop();
    SoGLLazyElement::getInstance(action->getState())
        ->reset(action->getState(), SoLazyElement::ALL_MASK);
    statistics_.bounceMapMs = context.bounceTimer.elapsedMs();
    statistics_.bounceBytes = context.bounceMaps->bytes();
    if (!failure.empty() && firstWarning(owner_, "no bounce: " + failure))
      SoDebugError::postWarning(owner_->getTypeId().getName().getString(),
                                "%s: %s; rendering without the bounce",
                                describeNode(owner_).c_str(), failure.c_str());
  }
  return context.bounceMaps && context.bounceMaps->built();
}

void TransparentShadowGroupImpl::shadeChildren(SoGLRenderAction* action, bool inPath, bool peel,
                                               Context& context) {
  if (peel && !context.peelTried) {
    context.peelTried = true;
    std::string whyNot;
    context.peel = PeelPass::create(whyNot);
    if (!context.peel && firstWarning(owner_, "no peel pass: " + whyNot))
      SoDebugError::postWarning(owner_->getTypeId().getName().getString(),
                                "%s: transparency composited by Coin, without depth peeling: %s",
                                describeNode(owner_).c_str(), whyNot.c_str());
  }
  if (!peel || !context.peel) {
    peelStatistics_.passes = 0;
    peelStatistics_.peelMs = 0.0;
    peelStatistics_.gpuPeelMs = 0.0;
    renderChildren_(action, inPath);
    return;
  }
  // Fragment lists: every transparent fragment shaded once, in one pass, where peeling pays a
  // pass (and a traversal) per two layers; dual peeling where the lists cannot hold the view
  // (docs/PEELING.md, "Inside a group").
  PeelOptions options;
  options.dual = true;
  options.fragmentLists = true;
  options.owner = owner_;
  const std::string failure = peelSubgraph(
      action, *context.peel, shading_, options,
      [this, inPath](SoGLRenderAction* drawing) { renderChildren_(drawing, inPath); },
      peelStatistics_);
  if (failure.empty()) return;
  // As under transparency COIN_BLENDING: the shading and shadows stay, Coin blends.
  if (firstWarning(owner_, "no peel targets: " + failure))
    SoDebugError::postWarning(owner_->getTypeId().getName().getString(),
                              "%s: %s; transparency composited by Coin, without depth peeling",
                              describeNode(owner_).c_str(), failure.c_str());
  renderChildren_(action, inPath);
}

bool TransparentShadowGroupImpl::traced(SoGLRenderAction* action) {
  const int renderer = static_cast<SoTransparentShadowGroup*>(owner_)->renderer.getValue();
  if (renderer != SoTransparentShadowGroup::AUTO_RENDERER)
    return renderer == SoTransparentShadowGroup::TRACER;
  return autoTracer_.traces(action->getState(), owner_, "renderer", "RASTER");
}

bool TransparentShadowGroupImpl::renderTraced(SoGLRenderAction* action) {
  auto& group = *static_cast<SoTransparentShadowGroup*>(owner_);
  contents_.update(action);
  TracerSettings settings;
  settings.movingResolution = resolveMovingResolution(group);
  settings.bounceSamples = group.bounce.getValue() ? group.bounceLights.getValue() : 0;
  if (!tracer_.render(action, contents_, settings, statistics_)) return false;
  const std::string why =
      describeNode(owner_) + " traces its children (renderer " +
      (group.renderer.getValue() == SoTransparentShadowGroup::TRACER ? "TRACER)"
                                                                     : "AUTO uses TRACER here)");
  for (const GroupContents::Light& light : contents_.lights())
    IdleFields::traced(*light.light, group, why);
  return true;
}

TransparentShadowGroupImpl::Context* TransparentShadowGroupImpl::contextFor(
    SoGLRenderAction* action) {
  return contexts_.get(SoGLCacheContextElement::get(action->getState()), [this] {
    std::string whyNot;
    auto pass = DeepShadowPass::create(whyNot);
    if (!pass) {
      // One warning per node class, naming the class the user put in the scene.
      const std::string node = owner_->getTypeId().getName().getString();
      if (firstWarning(nullptr, "rendering without deep shadows: " + node))
        SoDebugError::postWarning(node.c_str(), "rendering without deep shadows: %s",
                                  whyNot.c_str());
      return std::unique_ptr<Context>();
    }
    auto context = std::make_unique<Context>();
    context->pass = std::move(pass);
    const GlCapabilities capabilities = GlCapabilities::queryCurrent();
    context->softwareRenderer = capabilities.isSoftwareRenderer();
    context->renderer = capabilities.renderer;
    return context;
  });
}

ShadingUniforms* TransparentShadowGroupImpl::beginShading(SoGLRenderAction* action,
                                                          Context& context, bool bounced) {
  ShadingFeatures features = featuresOf(context.maps, contents_.lights().size());
  features.bounce = bounced;
  ShadingUniforms* uniforms = shading_.begin(action, context.pass->textureUnits(), features);
  // Coin bound no program for the shading variant. When it failed to compile or link Coin
  // has said why; when it declined to draw it at all it says nothing, and the group would
  // render as a plain separator without a word (seen with two contexts on two threads).
  if (uniforms == nullptr && firstWarning(owner_, "no shading program"))
    SoDebugError::postWarning(owner_->getTypeId().getName().getString(),
                              "%s: Coin bound no shading program in this context; rendering "
                              "without deep shadows",
                              describeNode(owner_).c_str());
  return uniforms;
}

int TransparentShadowGroupImpl::packMaps(ShadingUniforms& uniforms, const Context& context) {
  const SbMatrix& toEye = shading_.localToEye();
  uniforms.mapCount = int(std::min(contents_.lights().size(), context.maps.size()));
  int rayCount = 0;
  for (std::size_t slot = 0; slot < std::size_t(uniforms.mapCount); ++slot) {
    const MapState& map = context.maps[slot];
    const bool directional = map.kind == LightKind::Directional;
    SbVec3f eye;
    if (directional) {
      toEye.multDirMatrix(map.position, eye);
      eye.normalize();
    } else {
      toEye.multVecMatrix(map.position, eye);
    }
    for (int i = 0; i < 3; ++i) {
      uniforms.mapLight[slot * 3 + std::size_t(i)] = map.position[i];
      uniforms.mapLightEye[slot * 3 + std::size_t(i)] = eye[i];
    }
    uniforms.mapParams[slot * 4 + 0] = float(map.settings.resolution);
    uniforms.mapParams[slot * 4 + 1] = directional ? 1.0f : 0.0f;
    for (std::size_t face = 0; face < 6; ++face) {
      uniforms.mapFaceFirst[slot * 6 + face] = map.faceFirst[face];
      uniforms.mapFaceLayers[slot * 6 + face] = map.faceLayers[face];
    }
    uniforms.mapSlices[slot * 3 + 0] = map.sliceNear;
    uniforms.mapSlices[slot * 3 + 1] = map.sliceFar;
    // A map that failed to build holds no layer and casts no shadow, as a deep one.
    uniforms.mapSlices[slot * 3 + 2] =
        map.method == ShadowMethod::OpacityMap ? float(map.faceLayers[0]) : 0.0f;
    uniforms.mapParams[slot * 4 + 2] = map.settings.bias;
    uniforms.mapParams[slot * 4 + 3] = float(map.settings.filterWidth);
    uniforms.mapColoured[slot] = map.coloured ? 1 : 0;
    uniforms.mapProjection[slot] = int(map.frame.projection);
    for (int i = 0; i < 16; ++i)
      uniforms.mapLookup[slot * 16 + std::size_t(i)] = (&map.frame.lookup[0][0])[i];
    uniforms.mapTexelScale[slot * 2 + 0] = map.frame.texelScale.x;
    uniforms.mapTexelScale[slot * 2 + 1] = map.frame.texelScale.y;
    if (shadowsPerPixel(map.method)) uniforms.mapRay[slot] = rayCount++;
  }
  return rayCount;
}

void TransparentShadowGroupImpl::packBounce(ShadingUniforms& uniforms, const Context& context,
                                            bool bounced) {
  if (!bounced) {
    uniforms.bounceCount = 0;
    return;
  }
  uniforms.bounceCount = int(bounce_.lights().lights.size());
  uniforms.bounceTiles = context.bounceMaps->tiles();
  uniforms.bounceMapSize = context.bounceMapSize;
  uniforms.bounceLift = bounce_.lift();
  // Normals go to the group's coordinates by the transpose of the group-to-eye matrix's
  // inverse's inverse: its own transpose (SbMatrix rows are GL's columns).
  const SbMatrix& toEye = shading_.localToEye();
  for (int row = 0; row < 3; ++row)
    for (int column = 0; column < 3; ++column)
      uniforms.eyeToLocalNormal[column * 3 + row] = toEye[row][column];
}

void TransparentShadowGroupImpl::updateRays(SoGLRenderAction* action, bool inPath, Context& context,
                                            ShadingUniforms& uniforms) {
  if (!context.rays) context.rays = std::make_unique<RayMethod>(context.pass->rayUnit(0));
  const std::string failure = context.rays->update(
      action, contents_, shading_, rayCasters_, context.maps, renderChildren_, inPath, statistics_);
  if (!failure.empty())
    for (std::size_t slot = 0; slot < std::size_t(uniforms.mapCount); ++slot)
      if (shadowsPerPixel(context.maps[slot].method))
        warnNoShadow(*contents_.lights()[slot].light, failure);
  const std::string& volumes = context.rays->volumeFailure();
  if (failure.empty() && !volumes.empty())
    for (std::size_t slot = 0; slot < std::size_t(uniforms.mapCount); ++slot)
      if (context.maps[slot].method == ShadowMethod::Volumes)
        warnNoShadow(*contents_.lights()[slot].light, volumes);
  uniforms.rayLayers = context.rays->pass().layers();
}

void TransparentShadowGroupImpl::drawShaded(SoGLRenderAction* action, bool inPath, bool peel,
                                            Context& context, bool rays, bool bounced) {
  SoState* state = action->getState();
  const std::unique_ptr<GlStateScope> bound = context.pass->bindMaps(int(context.maps.size()));
  const std::unique_ptr<GlStateScope> traced =
      rays ? context.rays->pass().bind() : std::unique_ptr<GlStateScope>();
  const std::unique_ptr<GlStateScope> bouncing =
      bounced ? context.bounceMaps->bind(context.pass->textureUnits())
              : std::unique_ptr<GlStateScope>();
  SoShapeStyleElement::setShadowsRendering(state, TRUE);
  // A peeling separator below shades its layers with this group's program and maps.
  ShadowGroupElement::setActiveGroup(state, &shading_);
  // A shadow style above the group that does not receive: its shapes are drawn as a
  // SoShadowStyle inside would draw them (shading off), until a style below turns it on.
  if (!(SoShadowStyleElement::get(state) & SoShadowStyleElement::SHADOWED))
    SoGLShaderProgramElement::enable(state, FALSE);
  const bool timed = passTiming();
  if (timed) context.shadingTimer.start();
  shadeChildren(action, inPath, peel, context);
  if (timed) {
    context.shadingTimer.stop();
    statistics_.gpuShadingMs = context.shadingTimer.elapsedMs();  // waits for the GPU
  }
  shading_.end();
  SoShapeStyleElement::setShadowsRendering(state, FALSE);
  // The state render pushed is popped before the bindings above are undone, so Coin's
  // elements put back their GL state first, as they always have.
  state->pop();
}

bool TransparentShadowGroupImpl::render(SoGLRenderAction* action, bool inPath, bool peel) {
  // A traced group draws the shapes it does not trace through paths that may run through this
  // group, or are its own: as a separator.
  if (TracerActivity::active(TracerActivity::DrawingUntraced)) {
    tracer_.restoreDepth(action);
    return false;
  }
  SoState* state = action->getState();
  // Inside a peeling (an enclosing peeling group's or a SoPeelingSeparator's) every pass has
  // its variant of the enclosing shading bound; this group's own programs would write colours
  // into the peel targets. Its children are drawn as a plain separator's, peeled and shaded
  // with the rest.
  if (ShadowGroupElement::peeling(state)) {
    peelStatistics_.passes = 0;
    statistics_.renderer.clear();
    return false;
  }
  // Inside an enclosing group's capture (its RAYS lights' surfaces), likewise: this group's
  // own passes wrote its colours into the capture targets, and the enclosing group's shadows
  // fell on nothing below it (the floor around a nested group's glass stayed lit).
  if (ShadowGroupElement::capturing(state)) {
    statistics_.renderer.clear();
    return false;
  }
  // Traced, the group needs none of the GL path's programs or maps.
  if (traced(action) && renderTraced(action)) {
    statistics_.renderer = "TRACER";
    return true;
  }
  // Set once GL has drawn the children shaded; a failure below draws them plain.
  statistics_.renderer.clear();
  IdleFields::sayIfSet(*static_cast<SoTransparentShadowGroup*>(owner_), "movingResolution",
                       "GL draws the children here, every frame in full (only a traced group "
                       "reduces its frames)");
  warnCoarseDepth(owner_, state);
  Context* found = contextFor(action);
  if (found == nullptr) return false;
  Context& context = *found;
  // The maps, uniforms and texture bindings belong to this frame; a render cache above the
  // group must not replay them.
  SoCacheElement::invalidate(state);

  contents_.update(action);
  if (context.mapsVersion != contents_.mapsVersion())
    buildMaps(action, context);
  else
    refitToView(action, context);

  const bool bounced = updateBounce(action, context);

  state->push();
  ShadingUniforms* uniforms = beginShading(action, context, bounced);
  if (uniforms == nullptr) {
    state->pop();
    return false;
  }
  // From here on, the RAYS captures included, texture coordinate functions below reach this
  // shading (TexGenWatchElement).
  ShadowGroupElement::setShading(state, &shading_);
  const int rayCount = packMaps(*uniforms, context);
  packBounce(*uniforms, context, bounced);
  shading_.apply();
  if (rayCount > 0) {
    updateRays(action, inPath, context, *uniforms);
    shading_.apply();
  }
  drawShaded(action, inPath, peel, context, rayCount > 0, bounced);
  statistics_.renderer = "RASTER";
  return true;
}

}  // namespace ivshadow
