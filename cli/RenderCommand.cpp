#include "cli/RenderCommand.h"

#include "cli/RenderSession.h"
#include "cli/RenderStatistics.h"
#include "gl/GlCapabilities.h"
#include "headless/FrameStatistics.h"
#include "ivshadow/DeepShadowStatistics.h"
#include "ivshadow/PeelStatistics.h"

#include <algorithm>

namespace ivshadow {

namespace {

// A kept scene's groups (cli/KeptScene.h) count from the scene's first render on, and keep
// the figures of the last trace or read that made them. A scene is kept only from renders
// that traced a group and nothing else (RenderSession.cpp), so only the tracer's counts and
// figures can come from before this render.
DeepShadowStatistics sinceBefore(DeepShadowStatistics now, const DeepShadowStatistics& before) {
  now.tracerScenes -= before.tracerScenes;
  now.tracerFrames -= before.tracerFrames;
  now.tracerRefines -= before.tracerRefines;
  if (now.tracerScenes == 0) now.tracerSceneMs = 0.0;
  if (now.tracerLightsMs == before.tracerLightsMs) now.tracerLightsMs = 0.0;
  if (now.tracerFrames == 0) {
    now.tracerMs = 0.0;
    now.tracerWidth = now.tracerHeight = 0;
    now.tracerCameraRays = 0;
    now.tracerReduced = 0;
    if (now.rayFrames == before.rayFrames) now.raysTraced = 0;
  }
  return now;
}

}  // namespace

nlohmann::json renderStatistics(const RenderOptions& options, const OffscreenRenderer& renderer,
                                const std::vector<double>& wallMs, const std::vector<double>& gpuMs,
                                const std::string& transparency, SoNode* root,
                                const DeepShadowStatistics* before) {
  nlohmann::json stats;
  stats["scene"] = options.scene;
  stats["width"] = renderer.width();
  stats["height"] = renderer.height();
  stats["frames"] = wallMs.size();
  stats["frame_ms_median"] = FrameStatistics::median(wallMs);
  stats["frame_ms_min"] = FrameStatistics::minimum(wallMs);
  stats["gpu_ms_median"] = FrameStatistics::median(gpuMs);
  stats["gpu_ms_min"] = FrameStatistics::minimum(gpuMs);
  stats["frame_ms"] = wallMs;
  stats["gpu_ms"] = gpuMs;
  stats["transparency"] = transparency;
  stats["gl_renderer"] = renderer.capabilities().renderer;
  stats["gl_version"] = renderer.capabilities().version;
  stats["egl_platform"] = renderer.platform();
  stats["passes"] = {{"scene_ms", FrameStatistics::median(gpuMs)}};
  // Deep shadow maps are built only when something changed, so their cost is reported per
  // build, not per frame: the frame times above include it only for frames that rebuilt.
  const DeepShadowStatistics shadows = before != nullptr
                                           ? sinceBefore(collectDeepShadowStatistics(root), *before)
                                           : collectDeepShadowStatistics(root);
  stats["passes"]["dsm_build_ms"] = shadows.lastBuildMs;
  // GPU time of each pass (GL_TIMESTAMP queries; on llvmpipe the rasteriser's threads).
  stats["passes"]["dsm_build_gpu_ms"] = shadows.gpuBuildMs;
  stats["passes"]["shading_gpu_ms"] = shadows.gpuShadingMs;
  stats["passes"]["rays_capture_gpu_ms"] = shadows.gpuCaptureMs;
  stats["dsm_rebuilds"] = shadows.rebuilds;
  stats["dsm_caster_triangles"] = shadows.casterTriangles;
  std::uint64_t bytes = 0;
  nlohmann::json lights = nlohmann::json::array();
  std::vector<std::string> methods;
  for (const DeepShadowLightStatistics& light : shadows.lights) {
    bytes += light.bytes;
    const std::string name = shadowMethodName(light.method);
    lights.push_back({{"light", light.name},
                      {"faces", light.layersUsed},
                      {"passes", light.passes},
                      {"bytes", light.bytes},
                      {"peak_bytes", light.peakBytes},
                      {"colored", light.coloured},
                      {"resolution", light.resolution},
                      {"near_radius", light.nearRadius},
                      {"far_radius", light.farRadius},
                      {"projection", light.projection},
                      {"extent", light.extent},
                      {"method", name},
                      {"map_build", light.mapBuild},
                      {"list_fragments", light.listFragments},
                      {"merged_texels", light.mergedTexels},
                      {"merge_error", light.mergeError}});
    if (std::find(methods.begin(), methods.end(), name) == methods.end()) methods.push_back(name);
  }
  // The shadow method of each deep shadow light after AUTO was resolved, joined when they
  // differ ("MAP+RAYS"); empty without deep shadow lights.
  std::string method;
  for (const std::string& m : methods) method += (method.empty() ? "" : "+") + m;
  stats["passes"]["shadow_method"] = method;
  stats["passes"]["rays_ms"] = shadows.raysMs;
  stats["passes"]["rays_capture_ms"] = shadows.rayCaptureMs;
  stats["passes"]["rays_trace_ms"] = shadows.rayTraceMs;
  stats["ray_layers"] = shadows.rayLayers;
  stats["passes"]["bvh_build_ms"] = shadows.bvhBuildMs;
  stats["rays_traced"] = shadows.raysTraced;
  stats["volume_faces"] = shadows.volumeFaces;
  stats["ray_frames"] = shadows.rayFrames;
  stats["ray_captures"] = shadows.rayCaptures;
  stats["bvh_bytes"] = shadows.bvhBytes;
  stats["bvh_builds"] = shadows.bvhBuilds;
  stats["bvh_refits"] = shadows.bvhRefits;
  stats["bounce_lights"] = shadows.bounceLights;
  stats["bounce_samples"] = shadows.bounceSamples;
  stats["passes"]["bounce_place_ms"] = shadows.bouncePlaceMs;
  stats["passes"]["bounce_map_ms"] = shadows.bounceMapMs;
  stats["bounce_bytes"] = shadows.bounceBytes;
  stats["renderer"] = shadows.renderer;
  stats["tracer_scenes"] = shadows.tracerScenes;
  stats["tracer_frames"] = shadows.tracerFrames;
  stats["tracer_size"] = {shadows.tracerWidth, shadows.tracerHeight};
  stats["passes"]["tracer_scene_ms"] = shadows.tracerSceneMs;
  stats["passes"]["tracer_lights_ms"] = shadows.tracerLightsMs;
  stats["passes"]["tracer_ms"] = shadows.tracerMs;
  stats["dsm_layers_used"] = lights;
  stats["dsm_bytes"] = bytes;
  // Peeling runs every frame; these are the last frame's figures, summed over separators.
  const PeelStatistics peeling = collectPeelStatistics(root);
  stats["passes"]["peel_ms"] = peeling.peelMs;
  stats["passes"]["peel_gpu_ms"] = peeling.gpuPeelMs;
  stats["peel_passes"] = peeling.passes;
  stats["list_passes"] = peeling.listPasses;
  stats["list_fragments"] = peeling.listFragments;
  stats["list_slots"] = peeling.listSlots;
  stats["peel_traced_frames"] = peeling.tracedFrames;
  return stats;
}

int runRender(const RenderOptions& options) {
  RenderSession session;
  return session.render(options);
}

}  // namespace ivshadow
