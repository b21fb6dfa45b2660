#include "cli/RenderSession.h"

#include "cli/ExitStatus.h"
#include "cli/GroupTransparency.h"
#include "cli/ImageArguments.h"
#include "cli/InterruptGuard.h"
#include "cli/OpenRenderer.h"
#include "cli/RenderMemory.h"
#include "cli/RenderStatistics.h"
#include "gl/GlCapabilities.h"
#include "headless/FrameStatistics.h"
#include "headless/OffscreenRenderer.h"
#include "image_files/AtomicFile.h"
#include "image_files/ImageFile.h"
#include "image_files/ImageSize.h"
#include "image_files/MemoryBudget.h"
#include "image_files/OutputFiles.h"
#include "image_files/PngFile.h"
#include "ivshadow/DeepShadowStatistics.h"
#include "ivshadow/IvShadowInit.h"
#include "ivshadow/PeelStatistics.h"
#include "scene/InputError.h"
#include "scene/WarnOnce.h"
#include "scene_input/FieldAssignment.h"
#include "scene_input/SceneLoader.h"
#include "scene_input/TransparencyType.h"
#include "scene_input/ViewSetup.h"

#include <Inventor/SbViewportRegion.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/nodes/SoSeparator.h>

#include <iostream>
#include <optional>

namespace ivshadow {

namespace {

// Whether the frames of a render traced one group's picture on their first frame and did
// nothing else that keeps state across renders: no deep shadow map, no shadow rays of GL's
// path, no bounce, no depth peeling. Only then is a scene kept, so that the statistics of the
// render after it start from a tracer's counts alone (RenderStatistics.h takes those off)
// and the pictures are the tracer's, which re-reads and re-traces exactly what changed.
bool tracedAlone(const DeepShadowStatistics& before, const DeepShadowStatistics& after,
                 const PeelStatistics& peeling) {
  return after.tracerFrames - before.tracerFrames == 1 && after.lights.empty() &&
         after.rebuilds == 0 && after.rayFrames == 0 && after.bvhBuilds == 0 &&
         after.bounceLights == 0 && after.bounceSamples == 0 && peeling.frames == 0 &&
         peeling.tracedFrames == 0;
}

// Writes the picture the frames left, and their statistics with --stats, and says so: 0, or
// the interrupt's exit status when a signal came first. `before`: the statistics the kept
// scene had before the frames, which the render's own statistics leave out.
int writeOutputs(const RenderOptions& options, const ImageSize& size, OffscreenRenderer& renderer,
                 SoNode* root, const std::vector<double>& wallMs, const std::vector<double>& gpuMs,
                 const DeepShadowStatistics* before) {
  // Both files or neither: statistics that cannot be written (a full disk) take the
  // picture with them, as the exit status says.
  const Image picture = renderer.read();
  OutputFiles outputs;
  outputs.addImage(options.output, picture);
  if (!options.statsPath.empty()) {
    const std::string name = transparencyTypeName(renderer.action().getTransparencyType());
    outputs.addText(
        options.statsPath,
        renderStatistics(options, renderer, wallMs, gpuMs, name, root, before).dump(2) + "\n");
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
            << FrameStatistics::median(wallMs) << " ms on "
            << renderer.capabilities().renderer
            // Which EGL platform: on a GPU machine, whether the GPU's device was the one used.
            << " through EGL " << renderer.platform() << ")\n";
  return 0;
}

}  // namespace

int RenderSession::render(const RenderOptions& options) {
  bool keep = false;
  const int status = renderScene(options, keep);
  // A failed render may have left its scene half assigned or half drawn.
  if (status != 0 || !keep) kept_.reset();
  return status;
}

int RenderSession::renderScene(const RenderOptions& options, bool& keep) {
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
    checkPictureOutputs(options.scene, options.output, "--stats", options.statsPath);
    if (!options.statsPath.empty()) AtomicFile::checkWritable(options.statsPath, "statistics");

    init();
    // What an earlier render said it says again here, as a process of its own would.
    forgetAllWarnings();
    // The statistics report GPU time per pass; without them no pass waits for its timer.
    setPassTiming(!options.statsPath.empty());
    const std::optional<KeptScene::FileState> file = KeptScene::stateOf(options.scene);
    const bool reused = prepareScene(options, assignments, file);
    LoadedScene& scene = kept_->scene();
    OffscreenRenderer* renderer = rendererFor(size, scene.root.get());
    if (!renderer) return 3;
    // A render before this one may have set another type: without --transparency, Coin's
    // default, as a process of its own would have it.
    renderer->action().setTransparencyType(defaultTransparency_);
    if (transparency) {
      const GroupTransparency chosen = GroupTransparency::choose(scene.root.get(), *transparency);
      if (!chosen.warning.empty()) std::cerr << chosen.warning << '\n';
      renderer->action().setTransparencyType(chosen.type);
    }
    const ViewSetup view = ViewSetup::prepare(
        scene.root.get(),
        SbViewportRegion(static_cast<short>(size.width), static_cast<short>(size.height)));

    const DeepShadowStatistics before = collectDeepShadowStatistics(view.root.get());
    std::vector<double> wallMs, gpuMs;
    for (int frame = 0; frame < options.frames; ++frame) {
      const OffscreenRenderer::FrameTiming timing = renderer->render(view.root.get());
      wallMs.push_back(timing.wallMs);
      gpuMs.push_back(timing.gpuMs);
    }
    // The tracer takes the frame after a frame that traced for a change for a motion, traced
    // at a reduced size: a scene is kept from a render whose last frame drew the picture kept,
    // or whose one frame was the scene's first picture, never from one that traced a change
    // on its last frame.
    keep = file && (options.frames >= 2 || !reused) &&
           tracedAlone(before, collectDeepShadowStatistics(view.root.get()),
                       collectPeelStatistics(view.root.get()));
    return writeOutputs(options, size, *renderer, view.root.get(), wallMs, gpuMs,
                        reused ? &before : nullptr);
  });
}

bool RenderSession::prepareScene(const RenderOptions& options,
                                 const std::vector<FieldAssignment>& assignments,
                                 const std::optional<KeptScene::FileState>& file) {
  // A render that would neither put back nor assign anything finds nothing changed: its
  // frames would trace nothing, and its statistics would not be a fresh read's.
  const bool reused = kept_ && file && kept_->serves(options, *file) &&
                      (kept_->assigned() || !assignments.empty()) && kept_->restore();
  if (!reused) {
    kept_.reset();
    kept_ = std::make_unique<KeptScene>(loadScene(options.scene), options,
                                        file.value_or(KeptScene::FileState{}));
  }
  LoadedScene& scene = kept_->scene();
  for (const std::string& warning : scene.warnings) std::cerr << warning << '\n';
  kept_->remember(assignments);
  for (const FieldAssignment& assignment : assignments) {
    assignment.apply(scene.root.get(), options.scene);
  }
  return reused;
}

OffscreenRenderer* RenderSession::rendererFor(const ImageSize& size, SoNode* root) {
  // Before the frame buffer is allocated (seconds at the largest sizes): what the scene
  // needs whatever the GL; AUTO counts as a map until the renderer says it traces.
  const auto checkMemory = [&](bool softwareRenderer) {
    const RenderMemory memory = RenderMemory::of(root, softwareRenderer);
    MemoryBudget::check(size, memory.cost, memory.what, 1, MemoryBudget::available());
  };
  checkMemory(false);
  if (renderer_ && (renderer_->width() != size.width || renderer_->height() != size.height))
    renderer_.reset();
  if (!renderer_) {
    renderer_ = openRenderer(size);
    if (!renderer_) return nullptr;
    defaultTransparency_ = renderer_->action().getTransparencyType();
  }
  checkMemory(renderer_->capabilities().isSoftwareRenderer());
  return renderer_.get();
}

}  // namespace ivshadow
