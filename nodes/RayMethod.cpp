#include "nodes/RayMethod.h"

#include "gl/GlStateScope.h"
#include "gl/RayShadowPass.h"
#include "gl/ShadowVolumePass.h"
#include "ivshadow/DeepShadowStatistics.h"
#include "nodes/GroupContents.h"
#include "nodes/GroupShading.h"
#include "nodes/MapState.h"
#include "nodes/RayCasters.h"
#include "nodes/ShadowGroupElement.h"
#include "nodes/SuspendedRenderCaches.h"
#include "nodes/TransparencyOverride.h"
#include "raytrace/ScreenShadowTracer.h"
#include "raytrace/ShadowVolumes.h"

#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/elements/SoDepthBufferElement.h>
#include <Inventor/elements/SoGLLazyElement.h>
#include <Inventor/elements/SoModelMatrixElement.h>
#include <Inventor/elements/SoProjectionMatrixElement.h>
#include <Inventor/elements/SoViewingMatrixElement.h>
#include <Inventor/elements/SoViewportRegionElement.h>
#include <Inventor/errors/SoDebugError.h>
#include <Inventor/nodes/SoSeparator.h>

#include <chrono>
#include <optional>

namespace ivshadow {

RayMethod::RayMethod(int textureUnit)
    : pass_(std::make_unique<RayShadowPass>(textureUnit)), textureUnit_(textureUnit) {}

RayMethod::~RayMethod() = default;

std::string RayMethod::update(SoGLRenderAction* action, const GroupContents& contents,
                              GroupShading& shading, const RayCasters& casters,
                              const std::vector<MapState>& maps,
                              const ChildrenRenderer& renderChildren, bool inPath,
                              DeepShadowStatistics& statistics) {
  SoState* state = action->getState();
  const SbViewportRegion& region = SoViewportRegionElement::get(state);
  const SbVec2s origin = region.getViewportOriginPixels();
  const SbVec2s size = region.getViewportSizePixels();
  TraceKey key;
  key.mapsVersion = contents.mapsVersion();
  key.capture.castersVersion = contents.castersVersion();
  key.capture.viewVersion = contents.viewVersion();
  key.capture.viewport = {origin[0], origin[1], size[0], size[1]};
  const SbMatrix* matrices[3] = {&SoViewingMatrixElement::get(state),
                                 &SoProjectionMatrixElement::get(state),
                                 &SoModelMatrixElement::get(state)};
  for (int m = 0; m < 3; ++m)
    for (int i = 0; i < 16; ++i)
      key.capture.matrices[std::size_t(m * 16 + i)] = (*matrices[m])[i / 4][i % 4];
  // Nothing that the traced shadows depend on changed: the last trace still holds.
  if (traceValid_ && key == traced_) return {};
  const auto start = std::chrono::steady_clock::now();
  // Only lights changed: the camera sees the same surfaces, which are traced again as they
  // were captured.
  const bool recapture = !traceValid_ || !(key.capture == traced_.capture);
  std::string failure;
  if (recapture) failure = capture(action, contents, shading, renderChildren, inPath, statistics);
  const auto captured = std::chrono::steady_clock::now();

  std::vector<RayLight> lights;
  std::vector<int> tracedLights;  // screen light of each traced one
  int screenLights = 0, volumeLights = 0;
  for (const MapState& map : maps) {
    if (!shadowsPerPixel(map.method)) continue;
    ++screenLights;
    const bool volumes = map.method == ShadowMethod::Volumes;
    if (volumes) ++volumeLights;
    if (volumes || !casters.scene()) continue;
    tracedLights.push_back(screenLights - 1);
    RayLight light;
    for (int i = 0; i < 3; ++i) light.position[i] = map.position[i];
    light.directional = map.kind == LightKind::Directional;
    light.model = map.model;
    lights.push_back(light);
  }
  const std::size_t traced =
      casters.scene()
          ? traceScreenShadows(*casters.scene(), surfaces_, capturedLayers_, lights, visibility_)
          : 0;
  const auto tracedAt = std::chrono::steady_clock::now();
  if (traced == 0) visibility_.clear();
  const std::string uploaded =
      pass_->upload(surfaces_, int(capturedLayers_), recapture, visibility_, tracedLights,
                    screenLights, volumeLights > 0);
  if (failure.empty()) failure = uploaded;
  volumeFailure_.clear();
  if (failure.empty()) drawVolumes(state, shading, contents, maps, statistics);
  traced_ = key;
  traceValid_ = true;
  statistics.raysTraced = traced;
  statistics.rayLayers = int(capturedLayers_);
  statistics.rayCaptureMs =
      recapture ? std::chrono::duration<double, std::milli>(captured - start).count() : 0.0;
  statistics.rayTraceMs = std::chrono::duration<double, std::milli>(tracedAt - captured).count();
  statistics.raysMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  ++statistics.rayFrames;
  if (recapture) ++statistics.rayCaptures;
  return failure;
}

std::string RayMethod::capture(SoGLRenderAction* action, const GroupContents& contents,
                               GroupShading& shading, const ChildrenRenderer& renderChildren,
                               bool inPath, DeepShadowStatistics& statistics) {
  SoState* state = action->getState();
  const SbViewportRegion& region = SoViewportRegionElement::get(state);
  const SbVec2s origin = region.getViewportOriginPixels();
  const SbVec2s size = region.getViewportSizePixels();
  RayShadowPass& rays = *pass_;
  std::vector<SurfaceLayer>& layers = surfaces_;
  std::size_t layerCount = 0;
  // When the capture's state pops, Coin's depth element sends the depth function it believes
  // in force (LEQUAL unless a node set one), which need not be GL's: FreeCAD draws with
  // GL_LESS set directly, and draws a selected face's highlight before drawing the whole shape
  // again, which LEQUAL let over it. GL's depth state is put back as the capture found it.
  const GlStateScope depth(GlStateScope::kDepth);
  state->push();
  // Transparent shapes drawn at once and unblended, where the capture program sees them.
  overrideTransparencyType(state, SoGLRenderAction::NONE);
  SoDepthBufferElement::set(state, TRUE, TRUE, SoDepthBufferElement::LESS, SbVec2f(0.0f, 1.0f));
  // A peeling separator below draws its children plainly, with the capture program.
  ShadowGroupElement::setCapturing(state, true);
  // A render cache recorded here would hold the capture's state and uniforms and replay them
  // in the shading pass (Mesa then fails the display list): the captures record none.
  std::optional<SuspendedRenderCaches> noCaches(std::in_place);
  const bool timed = passTiming();
  if (timed) captureTimer_.start();
  const std::string failure = rays.beginCapture(origin[0], origin[1], size[0], size[1]);
  // Without a transparent caster there is rarely a transparent surface to capture: one pass
  // then does (a transparent shape that only receives takes the opaque surface's shadow).
  const int lastLayer =
      contents.casters().hasTransparent ? RayShadowPass::kMaxTransparentLayers : 0;
  for (int layer = 0; failure.empty() && layer <= lastLayer; ++layer) {
    const ShadingLocations* capture = shading.bind(
        action, layer == 0 ? ShadingVariant::CaptureOpaque : ShadingVariant::CaptureTransparent);
    if (capture == nullptr) break;  // Coin has said why it did not build
    rays.startLayer(layer, *capture);
    renderChildren(action, inPath);
    if (layers.size() <= std::size_t(layer)) layers.emplace_back();
    const bool any = rays.finishLayer(layer, layers[std::size_t(layer)]);
    if (layer > 0 && !any) break;  // no transparent surface left in front of the opaque one
    ++layerCount;
  }
  rays.endCapture();
  if (timed) {
    captureTimer_.stop();
    statistics.gpuCaptureMs = captureTimer_.elapsedMs();
  }
  noCaches.reset();
  state->pop();
  // The captures drew into targets Coin did not choose; GL is restored, and Coin must not
  // trust what it believes it last sent.
  SoGLLazyElement::getInstance(state)->reset(state, SoLazyElement::ALL_MASK);

  capturedLayers_ = layerCount;
  receivers_.makeEmpty();
  for (std::size_t l = 0; l < layerCount; ++l) {
    const SurfaceLayer& layer = layers[l];
    const std::size_t pixels = layer.position.size() / 4;
    for (std::size_t i = 0; i < pixels; ++i)
      if (layer.traced(i))
        receivers_.extendBy(
            SbVec3f(layer.position[i * 4], layer.position[i * 4 + 1], layer.position[i * 4 + 2]));
  }
  return failure;
}

bool RayMethod::volumesAvailable(std::string& whyNot) {
  if (!volumePass_ && volumePassFailure_.empty()) {
    volumePass_ = ShadowVolumePass::create(volumePassFailure_);
    if (!volumePass_ && volumePassFailure_.empty()) volumePassFailure_ = "unknown";
  }
  whyNot = volumePassFailure_;
  return volumePass_ != nullptr;
}

void RayMethod::drawVolumes(SoState* state, const GroupShading& shading,
                            const GroupContents& contents, const std::vector<MapState>& maps,
                            DeepShadowStatistics& statistics) {
  statistics.volumeFaces = 0;
  if (pass_->layers() == 0) return;
  ShadowVolumePass::View view{};
  const SbMatrix& toEye = shading.localToEye();
  const SbMatrix& projection = shading.projection();
  // A perspective view draws the volumes with its far plane at infinity (seeds/000 eq. 2.1):
  // faces beyond the scene are kept and those in front of the near plane, which are never
  // beyond a surface, are clipped. Clamping depth instead would keep faces reaching behind
  // the eye too, where the rasteriser's clipping of coordinates near w = 0 leaves cracks
  // between faces (single pixels counted once too often). A parallel view has no such place
  // and clamps.
  SbMatrix volumeProjection = projection;
  view.depthClamp = projection[3][3] != 0.0f;
  if (!view.depthClamp) {
    const float near = projection[3][2] / (projection[2][2] - 1.0f);
    volumeProjection[2][2] = -1.0f;
    volumeProjection[3][2] = -2.0f * near;
  }
  const SbMatrix toClip = toEye * volumeProjection;
  for (int i = 0; i < 16; ++i) {
    view.localToEye[i] = toEye[i / 4][i % 4];
    view.localToClip[i] = toClip[i / 4][i % 4];
  }
  view.winding = toEye.det3() < 0.0f ? -1.0f : 1.0f;
  const SbViewportRegion& region = SoViewportRegionElement::get(state);
  const SbVec2s origin = region.getViewportOriginPixels();
  const SbVec2s size = region.getViewportSizePixels();
  view.viewport[0] = origin[0];
  view.viewport[1] = origin[1];
  view.viewport[2] = size[0];
  view.viewport[3] = size[1];
  int screenLight = -1;
  for (const MapState& map : maps) {
    if (!shadowsPerPixel(map.method)) continue;
    ++screenLight;
    if (map.method != ShadowMethod::Volumes) continue;
    // The group asked volumesAvailable() before it gave the light this method.
    if (!volumePass_) continue;
    Volumes& volumes = volumes_[std::size_t(map.model)];
    if (!volumes.volumes || volumes.version != contents.castersVersion()) {
      volumes.volumes = std::make_unique<ShadowVolumes>(contents.casters(), map.model);
      volumes.version = contents.castersVersion();
      // Once while the count stays: every VOLUMES light of the group casts from the same
      // casters, which are read again after changes that need not touch these triangles.
      const std::size_t approximated = volumes.volumes->approximatedTriangles();
      if (approximated > 0 && approximated != warnedApproximated_) {
        warnedApproximated_ = approximated;
        SoDebugError::postWarning(
            "SoDeepShadowLight",
            "method VOLUMES: %zu of the casters' triangles change colour across their face "
            "(per-vertex colours or a texture); each casts one colour, its mean",
            approximated);
      }
    }
    const glm::vec3 light(map.position[0], map.position[1], map.position[2]);
    // Nothing captured: the volumes need reach only past the casters.
    const SbBox3f& box = receivers_.isEmpty() ? contents.casters().bounds : receivers_;
    const SbVec3f& low = box.getMin();
    const SbVec3f& high = box.getMax();
    volumes.volumes->build(light, map.kind == LightKind::Directional,
                           glm::vec3(low[0], low[1], low[2]), glm::vec3(high[0], high[1], high[2]),
                           faces_);
    statistics.volumeFaces += faces_.size() / 3;
    const std::string failure = volumePass_->draw(
        faces_, view, pass_->positionTexture(), pass_->layers(), pass_->visibilityTexture(),
        screenLight * pass_->layers(), pass_->width(), pass_->height(), textureUnit_);
    if (!failure.empty()) volumeFailure_ = failure;
  }
}

}  // namespace ivshadow
