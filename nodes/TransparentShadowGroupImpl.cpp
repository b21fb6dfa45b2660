#include "nodes/TransparentShadowGroupImpl.h"

#include "callbacks/DeepShadowPass.h"
#include "callbacks/GlCapabilities.h"
#include "callbacks/GlStateScope.h"
#include "callbacks/RayShadowPass.h"
#include "callbacks/ShadingUniforms.h"
#include "ivshadow/SoDeepShadowLight.h"
#include "nodes/TransparencyOverride.h"

#include <Inventor/SoPath.h>
#include <Inventor/actions/SoCallbackAction.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/actions/SoGetMatrixAction.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/elements/SoCacheElement.h>
#include <Inventor/elements/SoDepthBufferElement.h>
#include <Inventor/elements/SoEnvironmentElement.h>
#include <Inventor/elements/SoGLCacheContextElement.h>
#include <Inventor/elements/SoGLLazyElement.h>
#include <Inventor/elements/SoLightElement.h>
#include <Inventor/elements/SoModelMatrixElement.h>
#include <Inventor/elements/SoProjectionMatrixElement.h>
#include <Inventor/elements/SoShapeStyleElement.h>
#include <Inventor/elements/SoViewingMatrixElement.h>
#include <Inventor/elements/SoViewportRegionElement.h>
#include <Inventor/errors/SoDebugError.h>
#include <Inventor/misc/SoNotification.h>
#include <Inventor/nodes/SoCamera.h>
#include <Inventor/nodes/SoEnvironment.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoShaderProgram.h>

#include <unistd.h>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <set>

namespace ivshadow {
namespace {

constexpr int kMaxLights = ShadingUniforms::kMaxLights;

// Distance from `point` to the box (0 inside) and to its farthest corner.
void distanceRange(const SbBox3f& box, const SbVec3f& point, float& nearest, float& farthest) {
  const SbVec3f& low = box.getMin();
  const SbVec3f& high = box.getMax();
  float inside = 0.0f, outside = 0.0f;
  for (int i = 0; i < 3; ++i) {
    const float below = std::max(low[i] - point[i], 0.0f);
    const float above = std::max(point[i] - high[i], 0.0f);
    inside += (below + above) * (below + above);
    const float corner = std::max(std::fabs(point[i] - low[i]), std::fabs(point[i] - high[i]));
    outside += corner * corner;
  }
  nearest = std::sqrt(inside);
  farthest = std::sqrt(outside);
}

}  // namespace

namespace {
thread_local TransparentShadowGroupImpl* activeGroupNow = nullptr;
thread_local bool capturingNow = false;

const char* methodName(int method) {
  return method == SoDeepShadowLight::RAYS ? "RAYS" : "MAP";
}

// Embree may use at most half the machine's memory (IVSHADOW_EMBREE_MEMORY_LIMIT, in bytes,
// overrides it): past that a light keeps its map rather than the process running out.
std::int64_t embreeMemoryLimit() {
  const std::int64_t half =
      std::int64_t(sysconf(_SC_PHYS_PAGES)) * std::int64_t(sysconf(_SC_PAGE_SIZE)) / 2;
  const char* text = std::getenv("IVSHADOW_EMBREE_MEMORY_LIMIT");
  if (text == nullptr) return half;
  char* end = nullptr;
  const long long bytes = std::strtoll(text, &end, 10);
  if (end == text || *end != '\0' || bytes <= 0) {
    SoDebugError::postWarning("SoDeepShadowLight",
                              "IVSHADOW_EMBREE_MEMORY_LIMIT is '%s', expected a number of bytes "
                              "above 0; using half the memory",
                              text);
    return half;
  }
  return bytes;
}

std::string lightName(const SoDeepShadowLight& light) {
  const std::string name = light.getName().getString();
  return name.empty() ? std::string("(unnamed)") : "'" + name + "'";
}

}  // namespace

bool TransparentShadowGroupImpl::capturing() {
  return capturingNow;
}

bool TransparentShadowGroupImpl::rayCastersReady(const SoDeepShadowLight& light) {
  if (embreeError_.empty() && rayCasters_ && rayCastersVersion_ != castersVersion_) {
    // The same triangles recoloured or moved keep their tree.
    const auto start = std::chrono::steady_clock::now();
    const CasterScene::Update update = rayCasters_->update(casters_);
    if (update != CasterScene::Update::Rebuild) {
      rayCastersVersion_ = castersVersion_;
      if (update == CasterScene::Update::Refit) {
        ++statistics_.bvhRefits;
        statistics_.bvhBuildMs =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count();
      }
    }
  }
  if (embreeError_.empty() && (!rayCasters_ || rayCastersVersion_ != castersVersion_)) {
    const auto start = std::chrono::steady_clock::now();
    rayCasters_.reset();
    if (!embreeDevice_) {
      embreeMemory_.limit = embreeMemoryLimit();
      embreeDevice_ = createEmbreeDevice(embreeError_, &embreeMemory_);
    }
    if (embreeDevice_)
      rayCasters_ = CasterScene::build(embreeDevice_.get(), casters_, embreeError_);
    rayCastersVersion_ = castersVersion_;
    ++statistics_.bvhBuilds;
    statistics_.bvhBuildMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    statistics_.bvhBytes = std::uint64_t(std::max<std::int64_t>(embreeMemory_.bytes.load(), 0));
    if (!rayCasters_ && embreeError_.empty()) embreeError_ = "Embree failed";
  }
  if (rayCasters_) return true;
  if (embreeWarned_.insert(&light).second)
    SoDebugError::postWarning("SoDeepShadowLight",
                              "light %s: cannot trace shadow rays (%s); using its deep shadow map",
                              lightName(light).c_str(), embreeError_.c_str());
  return false;
}

TransparentShadowGroupImpl::TransparentShadowGroupImpl(SoSeparator* owner, bool deepShadows,
                                                       ChildrenRenderer renderChildren)
    : owner_(owner), deepShadows_(deepShadows), renderChildren_(std::move(renderChildren)) {}

TransparentShadowGroupImpl::~TransparentShadowGroupImpl() = default;

TransparentShadowGroupImpl* TransparentShadowGroupImpl::activeGroup() {
  return activeGroupNow;
}

unsigned int TransparentShadowGroupImpl::bindPeelProgram(SoGLRenderAction* action) {
  if (renderingPass_ == nullptr) return 0;
  peelProgram_.node()->GLRender(action);
  const unsigned int program = currentProgram();
  if (program != 0) uniforms_.apply(program, *renderingPass_);
  return program;
}

void TransparentShadowGroupImpl::changed(SoNotList* list) {
  const SoNotRec* record = list->getFirstRecAtNode();
  const SoBase* origin = record ? record->getBase() : nullptr;
  if (origin == nullptr || origin == owner_) {
    lightsValid_ = false;
    castersValid_ = false;
    ++mapsVersion_;
    return;
  }
  if (!origin->isOfType(SoNode::getClassTypeId())) return;
  const auto* node = static_cast<const SoNode*>(origin);
  // Moving the camera or changing an ordinary light changes no shadow map; a camera inside
  // the group moves what RAYS lights traced, which the state does not show yet when the group
  // starts (the camera is traversed later).
  if (node->isOfType(SoCamera::getClassTypeId())) {
    ++viewVersion_;
    return;
  }
  lightsValid_ = false;
  if (node->isOfType(SoDeepShadowLight::getClassTypeId())) {
    ++mapsVersion_;
    return;
  }
  if (node->isOfType(SoLight::getClassTypeId())) return;
  castersValid_ = false;
  ++mapsVersion_;
}

void TransparentShadowGroupImpl::findLights() {
  lights_.clear();
  subgraphLightsOn_ = 0;
  SoSearchAction cameras;
  cameras.setType(SoCamera::getClassTypeId());
  cameras.setInterest(SoSearchAction::LAST);
  cameras.apply(owner_);
  cameraPath_ = CoinRef<SoPath>(cameras.getPath() ? cameras.getPath()->copy() : nullptr);
  SoSearchAction environments;
  environments.setType(SoEnvironment::getClassTypeId());
  environments.setInterest(SoSearchAction::LAST);
  environments.apply(owner_);
  environmentPath_ =
      CoinRef<SoPath>(environments.getPath() ? environments.getPath()->copy() : nullptr);

  SoSearchAction search;
  search.setType(SoLight::getClassTypeId());
  search.setInterest(SoSearchAction::ALL);
  search.setSearchingAll(FALSE);
  search.apply(owner_);
  const SoPathList& paths = search.getPaths();
  for (int i = 0; i < paths.getLength(); ++i) {
    auto* light = static_cast<SoLight*>(paths[i]->getTail());
    if (!light->on.getValue()) continue;
    ++subgraphLightsOn_;
    if (deepShadows_ && light->isOfType(SoDeepShadowLight::getClassTypeId()) &&
        int(lights_.size()) < DeepShadowPass::kMaxSlots) {
      Light entry;
      entry.path = CoinRef<SoPath>(paths[i]->copy());
      entry.light = static_cast<SoDeepShadowLight*>(light);
      lights_.push_back(std::move(entry));
    }
  }
  lightsValid_ = true;
}

void TransparentShadowGroupImpl::buildMaps(SoGLRenderAction* action, Context& context) {
  const auto start = std::chrono::steady_clock::now();
  context.buildTimer.start();
  DeepShadowPass& pass = *context.pass;
  context.maps.assign(lights_.size(), MapState{});
  statistics_.lights.clear();
  SoGetMatrixAction matrixAction(action->getViewportRegion());
  for (std::size_t slot = 0; slot < lights_.size(); ++slot) {
    const Light& entry = lights_[slot];
    MapState& map = context.maps[slot];
    map.settings = resolveSettings(*entry.light, pass.maxTextureSize());
    matrixAction.apply(entry.path.get());
    matrixAction.getMatrix().multVecMatrix(entry.light->location.getValue(), map.position);
    float nearest = 0.0f, farthest = 1.0f;
    if (!casters_.bounds.isEmpty()) distanceRange(casters_.bounds, map.position, nearest, farthest);
    // The map must reach past the farthest caster; the near plane may not cut off any of
    // them, and reversed floating-point depth keeps a 1e5 ratio precise.
    const float far = farthest > 0.0f ? farthest * 1.01f : 1.0f;
    map.farRadius = map.settings.farRadius > 0.0f ? map.settings.farRadius : far;
    map.nearRadius = map.settings.nearRadius > 0.0f ? map.settings.nearRadius
                                                    : std::max(nearest * 0.99f, far * 1e-5f);
    if (map.nearRadius >= map.farRadius) map.nearRadius = map.farRadius * 1e-5f;
    int method = map.settings.method;
    if (method == SoDeepShadowLight::AUTO_METHOD) {
      method = context.softwareRenderer ? SoDeepShadowLight::RAYS : SoDeepShadowLight::MAP;
      if (methodLogged_.insert(entry.light).second)
        SoDebugError::postInfo("SoDeepShadowLight", "light %s: method AUTO uses %s on %s",
                               lightName(*entry.light).c_str(), methodName(method),
                               context.renderer.c_str());
    }
    if (method == SoDeepShadowLight::RAYS && !rayCastersReady(*entry.light))
      method = SoDeepShadowLight::MAP;
    map.rays = method == SoDeepShadowLight::RAYS;
    switch (map.settings.shadowColor) {
      case SoDeepShadowLight::COLORED:
        map.coloured = true;
        break;
      case SoDeepShadowLight::MONOCHROME:
        map.coloured = false;
        break;
      default:
        map.coloured = casters_.hasColouredTransparent;
        break;
    }

    map.model = !map.coloured ? ShadowColourModel::Monochrome
                : map.settings.colorModel == SoDeepShadowLight::POWER ? ShadowColourModel::Power
                                                                      : ShadowColourModel::Saturate;
    DeepShadowLightStatistics light;
    light.name = entry.light->getName().getString();
    light.coloured = map.coloured;
    light.method = methodName(method);
    if (map.rays) {
      statistics_.lights.push_back(light);
      continue;
    }
    MapRequest request;
    for (int i = 0; i < 3; ++i) request.light[i] = map.position[i];
    request.nearRadius = map.nearRadius;
    request.farRadius = map.farRadius;
    request.resolution = map.settings.resolution;
    request.layers = map.settings.maxLayers;
    request.coloured = map.coloured;
    request.halfPrecision = map.settings.halfPrecision;
    request.colourModel = map.model;
    const MapBuildResult built = pass.build(int(slot), request);
    map.faceFirst = built.firstLayer;
    map.faceLayers = built.layersUsed;

    light.layersUsed = built.layersUsed;
    light.passes = built.passes;
    light.bytes = pass.mapBytes(int(slot));
    light.peakBytes = pass.mapPeakBytes(int(slot));
    light.resolution = request.resolution;
    light.nearRadius = map.nearRadius;
    light.farRadius = map.farRadius;
    statistics_.lights.push_back(light);
  }
  pass.keepSlots(int(lights_.size()));
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
  statistics_.casterTriangles = int(casters_.triangleCount());
  context.mapsVersion = mapsVersion_;
}

SbMatrix TransparentShadowGroupImpl::localToEye(SoState* state) const {
  if (!cameraPath_) return SoModelMatrixElement::get(state) * SoViewingMatrixElement::get(state);
  // A camera inside the group is traversed after the group sets its uniforms; the viewing
  // matrix it will set, relative to the group's coordinates, is what maps them to the eye.
  SbMatrix viewing = SbMatrix::identity();
  SoCallbackAction action;
  action.addPostCallback(
      SoCamera::getClassTypeId(),
      [](void* data, SoCallbackAction* a, const SoNode*) {
        *static_cast<SbMatrix*>(data) = a->getViewingMatrix();
        return SoCallbackAction::CONTINUE;
      },
      &viewing);
  action.apply(cameraPath_.get());
  return viewing;
}

int TransparentShadowGroupImpl::fogType(SoState* state) const {
  // Like a camera, an environment inside the group is traversed after the uniforms are set.
  if (environmentPath_)
    return static_cast<const SoEnvironment*>(environmentPath_->getTail())->fogType.getValue();
  return int(SoEnvironmentElement::getFogType(state));
}

bool TransparentShadowGroupImpl::render(SoGLRenderAction* action, bool inPath) {
  SoState* state = action->getState();
  Context* found = contexts_.get(SoGLCacheContextElement::get(state), [this] {
    std::string whyNot;
    auto pass = DeepShadowPass::create(whyNot);
    if (!pass) {
      // One warning per node class, naming the class the user put in the scene.
      static std::set<std::string> warned;
      const std::string node = owner_->getTypeId().getName().getString();
      if (warned.insert(node).second)
        SoDebugError::postWarning(node.c_str(), "rendering without %s: %s",
                                  deepShadows_ ? "deep shadows" : "depth peeling", whyNot.c_str());
      return std::unique_ptr<Context>();
    }
    auto context = std::make_unique<Context>();
    context->pass = std::move(pass);
    const GlCapabilities capabilities = GlCapabilities::queryCurrent();
    context->softwareRenderer = capabilities.isSoftwareRenderer();
    context->renderer = capabilities.renderer;
    return context;
  });
  if (found == nullptr) return false;
  Context& context = *found;
  // The maps, uniforms and texture bindings belong to this frame; a render cache above the
  // group must not replay them.
  SoCacheElement::invalidate(state);

  if (!lightsValid_) findLights();
  // Without deep shadows (a peeling separator on its own) there is nothing to cast into.
  if (!castersValid_ && deepShadows_) {
    casters_ = extractShadowCasters(owner_);
    castersValid_ = true;
    // Neither method can cast a shadow from lines or points: say so once per shape.
    static std::set<std::string> warnedShapes;
    for (const std::string& shape : casters_.withoutTriangles)
      if (warnedShapes.insert(shape).second)
        SoDebugError::postWarning(owner_->getTypeId().getName().getString(),
                                  "%s is drawn with lines or points, which cast no shadow",
                                  shape.c_str());
    ++castersVersion_;
  }
  if (context.castersVersion != castersVersion_) {
    context.pass->uploadCasters(casters_);
    context.castersVersion = castersVersion_;
  }
  if (context.mapsVersion != mapsVersion_) buildMaps(action, context);

  state->push();
  program_.node()->GLRender(action);
  const unsigned int program = currentProgram();
  if (program == 0) {
    state->pop();
    return false;
  }
  ShadingUniforms& uniforms = uniforms_;
  uniforms = ShadingUniforms{};
  const int outside = SoLightElement::getLights(state).getLength();
  uniforms.lightCount = std::min(kMaxLights, outside + subgraphLightsOn_);
  const SbMatrix toEye = localToEye(state);
  uniforms.mapCount = int(std::min(lights_.size(), context.maps.size()));
  int rayCount = 0;
  for (std::size_t slot = 0; slot < std::size_t(uniforms.mapCount); ++slot) {
    const MapState& map = context.maps[slot];
    SbVec3f eye;
    toEye.multVecMatrix(map.position, eye);
    for (int i = 0; i < 3; ++i) {
      uniforms.mapLight[slot * 3 + std::size_t(i)] = map.position[i];
      uniforms.mapLightEye[slot * 3 + std::size_t(i)] = eye[i];
    }
    uniforms.mapParams[slot * 4 + 0] = float(map.settings.resolution);
    for (std::size_t face = 0; face < 6; ++face) {
      uniforms.mapFaceFirst[slot * 6 + face] = map.faceFirst[face];
      uniforms.mapFaceLayers[slot * 6 + face] = map.faceLayers[face];
    }
    uniforms.mapParams[slot * 4 + 2] = map.settings.bias;
    uniforms.mapParams[slot * 4 + 3] = float(map.settings.filterRadius);
    uniforms.mapColoured[slot] = map.coloured ? 1 : 0;
    if (map.rays) uniforms.mapRay[slot] = rayCount++;
  }
  const SbMatrix eyeToLocal = toEye.inverse();
  for (int row = 0; row < 4; ++row)
    for (int column = 0; column < 4; ++column)
      uniforms.eyeToLocal[row * 4 + column] = eyeToLocal[row][column];
  uniforms.fogType = fogType(state);
  uniforms.apply(program, *context.pass);
  darkenLights(outside);
  if (rayCount > 0) {
    traceRays(action, context, program, inPath);
    uniforms.rayLayers = context.rays->layers();
    uniforms.apply(program, *context.pass);
  }

  {
    const std::unique_ptr<GlStateScope> bound = context.pass->bindMaps(int(context.maps.size()));
    const std::unique_ptr<GlStateScope> traced =
        rayCount > 0 ? context.rays->bind() : std::unique_ptr<GlStateScope>();
    SoShapeStyleElement::setShadowsRendering(state, TRUE);
    TransparentShadowGroupImpl* outer = activeGroupNow;
    if (deepShadows_) activeGroupNow = this;
    renderingPass_ = context.pass.get();
    const bool timed = passTiming();
    if (timed) context.shadingTimer.start();
    renderChildren_(action, inPath);
    if (timed) {
      context.shadingTimer.stop();
      statistics_.gpuShadingMs = context.shadingTimer.elapsedMs();  // waits for the GPU
    }
    renderingPass_ = nullptr;
    activeGroupNow = outer;
    SoShapeStyleElement::setShadowsRendering(state, FALSE);
    state->pop();
  }
  return true;
}

void TransparentShadowGroupImpl::traceRays(SoGLRenderAction* action, Context& context,
                                           unsigned int program, bool inPath) {
  SoState* state = action->getState();
  const SbViewportRegion& region = SoViewportRegionElement::get(state);
  const SbVec2s origin = region.getViewportOriginPixels();
  const SbVec2s size = region.getViewportSizePixels();
  TraceKey key;
  key.mapsVersion = mapsVersion_;
  key.viewVersion = viewVersion_;
  key.viewport = {origin[0], origin[1], size[0], size[1]};
  const SbMatrix* matrices[3] = {&SoViewingMatrixElement::get(state),
                                 &SoProjectionMatrixElement::get(state),
                                 &SoModelMatrixElement::get(state)};
  for (int m = 0; m < 3; ++m)
    for (int i = 0; i < 16; ++i)
      key.matrices[std::size_t(m * 16 + i)] = (*matrices[m])[i / 4][i % 4];
  // Nothing that the traced shadows depend on changed: the last trace still holds.
  if (context.traceValid && key == context.traced) return;
  const auto start = std::chrono::steady_clock::now();
  if (!context.rays) context.rays = std::make_unique<RayShadowPass>();
  RayShadowPass& rays = *context.rays;

  std::vector<SurfaceLayer>& layers = context.surfaces;
  std::size_t layerCount = 0;
  state->push();
  // Transparent shapes drawn at once and unblended, where the capture program sees them.
  overrideTransparencyType(state, SoGLRenderAction::NONE);
  SoDepthBufferElement::set(state, TRUE, TRUE, SoDepthBufferElement::LESS, SbVec2f(0.0f, 1.0f));
  const bool outerCapture = capturingNow;  // a group inside another group's capture
  capturingNow = true;
  // A render cache recorded here would hold the capture's state and uniforms and replay them
  // in the shading pass (Mesa then fails the display list): the captures record none.
  const int renderCaches = SoSeparator::getNumRenderCaches();
  SoSeparator::setNumRenderCaches(0);
  const bool timed = passTiming();
  if (timed) context.captureTimer.start();
  rays.beginCapture(origin[0], origin[1], size[0], size[1]);
  // Without a transparent caster there is rarely a transparent surface to capture: one pass
  // then does (a transparent shape that only receives takes the opaque surface's shadow).
  const int lastLayer = casters_.hasTransparent ? RayShadowPass::kMaxTransparentLayers : 0;
  for (int layer = 0; layer <= lastLayer; ++layer) {
    rays.startLayer(layer, program);
    renderChildren_(action, inPath);
    if (layers.size() <= std::size_t(layer)) layers.emplace_back();
    const bool any = rays.finishLayer(layer, layers[std::size_t(layer)]);
    if (layer > 0 && !any) break;  // no transparent surface left in front of the opaque one
    ++layerCount;
  }
  rays.endCapture(program);
  if (timed) {
    context.captureTimer.stop();
    statistics_.gpuCaptureMs = context.captureTimer.elapsedMs();
  }
  SoSeparator::setNumRenderCaches(renderCaches);
  capturingNow = outerCapture;
  state->pop();
  // The captures drew into targets Coin did not choose; GL is restored, and Coin must not
  // trust what it believes it last sent.
  SoGLLazyElement::getInstance(state)->reset(state, SoLazyElement::ALL_MASK);

  const auto captured = std::chrono::steady_clock::now();
  std::vector<RayLight> lights;
  for (const MapState& map : context.maps) {
    if (!map.rays) continue;
    RayLight light;
    for (int i = 0; i < 3; ++i) light.position[i] = map.position[i];
    light.model = map.model;
    lights.push_back(light);
  }
  const std::size_t traced =
      rayCasters_ ? traceScreenShadows(*rayCasters_, layers, layerCount, lights, context.visibility)
                  : 0;
  const auto tracedAt = std::chrono::steady_clock::now();
  rays.upload(layers, int(layerCount), context.visibility,
              context.visibility.empty() ? 0 : int(lights.size()));
  context.traced = key;
  context.traceValid = true;
  statistics_.raysTraced = traced;
  statistics_.rayLayers = int(layerCount);
  statistics_.rayCaptureMs = std::chrono::duration<double, std::milli>(captured - start).count();
  statistics_.rayTraceMs = std::chrono::duration<double, std::milli>(tracedAt - captured).count();
  statistics_.raysMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  ++statistics_.rayFrames;
}

}  // namespace ivshadow
