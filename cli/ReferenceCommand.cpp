#include "cli/ReferenceCommand.h"

#include "cli/InterruptGuard.h"

#include "cli/ExitStatus.h"
#include "cli/ImageArguments.h"
#include "cli/ProgressBar.h"
#include "cli/ReferenceOverlay.h"
#include "cli/RenderMemory.h"
#include "headless/CoinOffscreenContexts.h"
#include "image_files/AtomicFile.h"
#include "image_files/ImageFile.h"
#include "image_files/ImageSize.h"
#include "image_files/MemoryBudget.h"
#include "image_files/OutputFiles.h"
#include "image_files/PfmFile.h"
#include "image_files/PngFile.h"
#include "ivshadow/IvShadowInit.h"
#include "ivshadow/SoTransparentShadowGroup.h"
#include "nodes/NodesOfType.h"
#include "reference/ReferenceRenderer.h"
#include "scene/InputError.h"
#include "scene_input/FieldAssignment.h"
#include "scene_input/SceneLoader.h"
#include "scene_input/ViewSetup.h"

#include <Inventor/SbViewportRegion.h>
#include <Inventor/nodes/SoSeparator.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <future>
#include <iostream>

namespace ivshadow {
namespace {

// Only the groups that ask for it bounce: --bounce says so where none does.
void warnIfNothingBounces(const ReferenceCommandOptions& options, SoNode* root) {
  if (!options.bounceGiven || options.bounce <= 0) return;
  bool groups = false;
  forEachNodeOfType<SoTransparentShadowGroup>(root, [&](SoTransparentShadowGroup& g) {
    groups = groups || (g.isActive.getValue() && g.bounce.getValue());
  });
  if (!groups)
    std::cerr << options.scene
              << ": warning: --bounce: no active TransparentShadowGroup has bounce TRUE, so "
                 "no light bounces\n";
}

// Traces `root` on a thread of its own while this one shows the rows done as a progress bar,
// for a trace that makes the user wait (a second from `start`). Nothing when interrupted.
std::optional<ReferenceResult> traceWithProgress(SoNode* root, ReferenceOptions reference,
                                                 std::chrono::steady_clock::time_point start) {
  std::atomic<int> rows{0};
  reference.rowsDone = &rows;
  auto future = std::async(std::launch::async, [&] { return renderReference(root, reference); });
  ProgressBar bar;
  bool shown = false;
  while (future.wait_for(std::chrono::milliseconds(100)) != std::future_status::ready) {
    if (std::chrono::steady_clock::now() - start < std::chrono::seconds(1)) continue;
    if (bar.terminal() || !shown) bar.update(rows.load(), reference.height, "rows");
    shown = true;
  }
  std::optional<ReferenceResult> result = future.get();
  if (shown && bar.terminal() && rows.load() < reference.height) std::cerr << '\n';
  return result;
}

// The picture and, with --pfm, its unrounded floats: both files or neither. False when a
// signal came after the trace's last row or during the writes, which leaves no file either.
bool writeFiles(const ReferenceCommandOptions& options, const ReferenceResult& result,
                const std::atomic<bool>& interrupted) {
  const Image picture = result.image.toImage();
  OutputFiles outputs;
  outputs.addImage(options.output, picture);
  if (!options.pfm.empty()) {
    const FloatImage& image = result.image;
    outputs.add(options.pfm, [&](const std::string& file) {
      writePfmTo(file, options.pfm, image.width, image.height, image.rgb);
    });
  }
  return outputs.commit(&interrupted);
}

}  // namespace

int runReference(const ReferenceCommandOptions& options) {
  // From the start: Ctrl-C while the scene loads stops the render as soon as it begins, so
  // the user always gets the same answer (exit 128 + the signal, nothing written).
  const InterruptGuard guard;
  std::atomic<bool>& interrupted = InterruptGuard::flag();
  const int status = withExitStatus([&] {
    if (options.bounce < 0 || options.bounce > 65536)
      throw InputError("--bounce " + std::to_string(options.bounce) +
                       ": error: expected 0 (no bounce) .. 65536 rays per point");
    if (options.threads < 0 || options.threads > 1024)
      throw InputError("--threads " + std::to_string(options.threads) +
                       ": error: expected 0 (every core) to 1024");
    const ImageSize size = ImageSize::parse(options.size, "--size");
    std::vector<FieldAssignment> assignments;
    for (const std::string& text : options.assignments)
      assignments.push_back(FieldAssignment::parse(text));
    checkPictureOutputs(options.scene, options.output, "--pfm", options.pfm);
    MemoryBudget::check(size, kReferenceCost, "the reference render", 1, MemoryBudget::available());
    if (!options.pfm.empty()) AtomicFile::checkWritable(options.pfm, "the float image");

    init();
    installCoinOffscreenContexts();
    LoadedScene scene = loadScene(options.scene);
    for (const std::string& warning : scene.warnings) std::cerr << warning << '\n';
    for (const FieldAssignment& assignment : assignments)
      assignment.apply(scene.root.get(), options.scene);
    const ViewSetup view = ViewSetup::prepare(
        scene.root.get(), SbViewportRegion(short(size.width), short(size.height)));
    warnIfNothingBounces(options, scene.root.get());

    ReferenceOptions reference;
    reference.width = size.width;
    reference.height = size.height;
    reference.threads = options.threads;
    reference.bounceSamples = options.bounce;
    reference.cancel = &interrupted;
    const auto start = std::chrono::steady_clock::now();
    std::optional<ReferenceResult> result = traceWithProgress(view.root.get(), reference, start);
    if (!result) {
      std::cerr << "ivshadow: interrupted; nothing written\n";
      return InterruptGuard::exitStatus();
    }
    for (const std::string& warning : result->warnings)
      std::cerr << options.scene << ": warning: " << warning << '\n';
    if (const std::string error = drawUntracedOver(view.root.get(), reference.background, *result);
        !error.empty())
      std::cerr << options.scene << ": warning: the shapes GL draws are missing: " << error << '\n';
    if (!writeFiles(options, *result, interrupted)) {
      std::cerr << "ivshadow: interrupted; nothing written\n";
      return InterruptGuard::exitStatus();
    }
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::cout << "wrote " << options.output << " (" << size.toString() << ", " << result->triangles
              << " triangles, " << result->shadowRays << " shadow rays, "
              << (result->bounceRays > 0 ? std::to_string(result->bounceRays) + " bounce rays, "
                                         : "")
              << ms << " ms)\n";
    return 0;
  });
  return status;
}

}  // namespace ivshadow
