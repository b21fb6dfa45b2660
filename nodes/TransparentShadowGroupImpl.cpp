#include "nodes/TransparentShadowGroupImpl.h"

#include "callbacks/DeepShadowPass.h"
#include "callbacks/GlStateScope.h"
#include "callbacks/ShadingUniforms.h"
#include "nodes/SoDeepShadowLight.h"

#include <Inventor/SoPath.h>
#include <Inventor/actions/SoCallbackAction.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/actions/SoGetMatrixAction.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/elements/SoCacheElement.h>
#include <Inventor/elements/SoEnvironmentElement.h>
#include <Inventor/elements/SoGLCacheContextElement.h>
#include <Inventor/elements/SoGLLazyElement.h>
#include <Inventor/elements/SoLightElement.h>
#include <Inventor/elements/SoModelMatrixElement.h>
#include <Inventor/elements/SoShapeStyleElement.h>
#include <Inventor/elements/SoViewingMatrixElement.h>
#include <Inventor/errors/SoDebugError.h>
#include <Inventor/misc/SoNotification.h>
#include <Inventor/nodes/SoCamera.h>
#include <Inventor/nodes/SoEnvironment.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoShaderProgram.h>

#include <algorithm>
#include <chrono>
#include <cmath>
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
}  // namespace

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
  // Moving the camera or changing an ordinary light changes no shadow map.
  if (node->isOfType(SoCamera::getClassTypeId())) return;
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

    MapRequest request;
    for (int i = 0; i < 3; ++i) request.light[i] = map.position[i];
    request.nearRadius = map.nearRadius;
    request.farRadius = map.farRadius;
    request.resolution = map.settings.resolution;
    request.layers = map.settings.maxLayers;
    request.coloured = map.coloured;
    request.halfPrecision = map.settings.halfPrecision;
    request.colourModel = !map.coloured ? ShadowColourModel::Monochrome
                          : map.settings.colorModel == SoDeepShadowLight::POWER
                              ? ShadowColourModel::Power
                              : ShadowColourModel::Saturate;
    const MapBuildResult built = pass.build(int(slot), request);
    map.faceFirst = built.firstLayer;
    map.faceLayers = built.layersUsed;

    DeepShadowLightStatistics light;
    light.name = entry.light->getName().getString();
    light.layersUsed = built.layersUsed;
    light.passes = built.passes;
    light.bytes = pass.mapBytes(int(slot));
    light.peakBytes = pass.mapPeakBytes(int(slot));
    light.coloured = map.coloured;
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
  }
  const SbMatrix eyeToLocal = toEye.inverse();
  for (int row = 0; row < 4; ++row)
    for (int column = 0; column < 4; ++column)
      uniforms.eyeToLocal[row * 4 + column] = eyeToLocal[row][column];
  uniforms.fogType = fogType(state);
  uniforms.apply(program, *context.pass);
  darkenLights(outside);

  {
    const std::unique_ptr<GlStateScope> bound = context.pass->bindMaps(int(context.maps.size()));
    SoShapeStyleElement::setShadowsRendering(state, TRUE);
    TransparentShadowGroupImpl* outer = activeGroupNow;
    if (deepShadows_) activeGroupNow = this;
    renderingPass_ = context.pass.get();
    renderChildren_(action, inPath);
    renderingPass_ = nullptr;
    activeGroupNow = outer;
    SoShapeStyleElement::setShadowsRendering(state, FALSE);
    state->pop();
  }
  return true;
}

}  // namespace ivshadow
