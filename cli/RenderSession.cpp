#include "cli/RenderSession.h"

#include "callbacks/GlCapabilities.h"
#include "cli/ExitStatus.h"
#include "cli/GroupTransparency.h"
#include "cli/ImageArguments.h"
#include "cli/InterruptGuard.h"
#include "cli/OpenRenderer.h"
#include "cli/RenderMemory.h"
#include "cli/RenderStatistics.h"
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
#include "scene/FieldAssignment.h"
#include "scene/InputError.h"
#include "scene/SceneLoader.h"
#include "scene/TransparencyType.h"
#include "scene/ViewSetup.h"
#include "scene/WarnOnce.h"

#include <Inventor/SbViewportRegion.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/nodes/SoSeparator.h>

#include <iostream>
#include <optional>

namespace ivshadow {

int RenderSession::render(const RenderOptions& options) {
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
    // What an earlier render said it says again here, as a process of its own would.
    forgetAllWarnings();
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
    if (renderer_ && (renderer_->width() != size.width || renderer_->height() != size.height))
      renderer_.reset();
    if (!renderer_) {
      renderer_ = openRenderer(size);
      if (!renderer_) return 3;
      defaultTransparency_ = renderer_->action().getTransparencyType();
    }
    OffscreenRenderer* renderer = renderer_.get();
    checkMemory(renderer->capabilities().isSoftwareRenderer());
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
          renderStatistics(options, *renderer, wallMs, gpuMs, name, view.root.get()).dump(2) +
              "\n");
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
