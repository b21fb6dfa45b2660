#include "cli/RenderCommand.h"

#include "callbacks/GlCapabilities.h"
#include "cli/ExitStatus.h"
#include "cli/GroupTransparency.h"
#include "cli/ImageArguments.h"
#include "cli/InterruptGuard.h"
#include "cli/OpenRenderer.h"
#include "cli/RenderMemory.h"
#include "headless/FrameStatistics.h"
#include "headless/OffscreenRenderer.h"
#include "image/AtomicFile.h"
#include "image/CommandPaths.h"
#include "image/ImageFile.h"
#include "image/ImageSize.h"
#include "image/MemoryBudget.h"
#include "image/OutputFiles.h"
#include "image/PngFile.h"
#include "ivshadow/DeepShadowStatistics.h"
#include "ivshadow/IvShadowInit.h"
#include "ivshadow/PeelStatistics.h"
#include "scene/FieldAssignment.h"
#include "scene/InputError.h"
#include "scene/SceneLoader.h"
#include "scene/TransparencyType.h"
#include "scene/ViewSetup.h"

#include <Inventor/SbViewportRegion.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/nodes/SoSeparator.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <iostream>
#include <optional>

namespace ivshadow {
namespace {

nlohmann::json statistics(const RenderOptions& options, const OffscreenRenderer& renderer,
                          const std::vector<double>& wallMs, const std::vector<double>& gpuMs,
                          const std::string& transparency, SoNode* root) {
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
  const DeepShadowStatistics shadows = collectDeepShadowStatistics(root);
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
                      {"method", light.method},
                      {"map_build", light.mapBuild},
                      {"list_fragments", light.listFragments},
                      {"merged_texels", light.mergedTexels},
                      {"merge_error", light.mergeError}});
    if (std::find(methods.begin(), methods.end(), light.method) == methods.end())
      methods.push_back(light.method);
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

}  // namespace

int runRender(const RenderOptions& options) {
  return withExitStatus([&] {
    const ImageSize size = ImageSize::parse(options.size, "--size");
    if (options.frames < 1) {
      throw InputError("--frames " + std::to_string(options.frames) +
                       ": error: expected a whole number of at least 1");
    }
    std::optional<SoGLRenderAction::TransparencyType> transparency;
    if (!options.transparency.empty()) {
      transparency = transparencyTypeFromName(options.transparency);
    }
    std::vector<FieldAssignment> assignments;
    for (const std::string& text : options.assignments) {
      assignments.push_back(FieldAssignment::parse(text));
    }
    CommandPaths()
        .input("scene", options.scene)
        .output("-o", options.output)
        .output("--stats", options.statsPath)
        .check();
    checkImageOutput("-o", options.output);
    imageFormatFor(options.output);
    AtomicFile::checkWritable(options.output, "the image");
    if (!options.statsPath.empty()) AtomicFile::checkWritable(options.statsPath, "statistics");

    init();
    // The statistics report GPU time per pass; without them no pass waits for its timer.
    setPassTiming(!options.statsPath.empty());
    LoadedScene scene = loadScene(options.scene);
    for (const std::string& warning : scene.warnings) std::cerr << warning << '\n';
    for (const FieldAssignment& assignment : assignments) {
      assignment.apply(scene.root.get(), options.scene);
    }

    // Before the frame buffer is allocated (seconds at the largest sizes): what the scene
    // needs whatever the GL; AUTO counts as a map until the renderer says it traces.
    const auto checkMemory = [&](bool softwareRenderer) {
      const RenderMemory memory = RenderMemory::of(scene.root.get(), softwareRenderer);
      MemoryBudget::check(size, memory.cost, memory.what, 1, MemoryBudget::available());
    };
    checkMemory(false);
    std::unique_ptr<OffscreenRenderer> renderer = openRenderer(size);
    if (!renderer) return 3;
    checkMemory(renderer->capabilities().isSoftwareRenderer());
    if (transparency) {
      const GroupTransparency chosen = GroupTransparency::choose(scene.root.get(), *transparency);
      if (!chosen.warning.empty()) std::cerr << chosen.warning << '\n';
      renderer->action().setTransparencyType(chosen.type);
    }
    const ViewSetup view = ViewSetup::prepare(
        scene.root.get(),
        SbViewportRegion(static_cast<short>(size.width), static_cast<short>(size.height)));

    std::vector<double> wallMs, gpuMs;
    for (int frame = 0; frame < options.frames; ++frame) {
      const OffscreenRenderer::FrameTiming timing = renderer->render(view.root.get());
      wallMs.push_back(timing.wallMs);
      gpuMs.push_back(timing.gpuMs);
    }
    // Both files or neither: statistics that cannot be written (a full disk) take the
    // picture with them, as the exit status says.
    const Image picture = renderer->read();
    OutputFiles outputs;
    outputs.addImage(options.output, picture);
    if (!options.statsPath.empty()) {
      const std::string name = transparencyTypeName(renderer->action().getTransparencyType());
      outputs.addText(
          options.statsPath,
          statistics(options, *renderer, wallMs, gpuMs, name, view.root.get()).dump(2) + "\n");
    }
    // From here a signal would leave the temporaries behind: it is held off until the files
    // are written, then none of them is kept.
    const InterruptGuard guard;
    if (!outputs.commit(&InterruptGuard::flag())) {
      std::cerr << "ivshadow: interrupted; nothing written\n";
      return InterruptGuard::exitStatus();
    }
    std::cout << "wrote " << options.output << " (" << size.toString() << ", " << options.frames
              << (options.frames == 1 ? " frame, " : " frames, median ")
              << FrameStatistics::median(wallMs) << " ms on " << renderer->capabilities().renderer
              << ")\n";
    return 0;
  });
}

}  // namespace ivshadow
