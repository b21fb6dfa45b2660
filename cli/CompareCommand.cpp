#include "cli/CompareCommand.h"

#include "cli/ExitStatus.h"
#include "cli/ImageArguments.h"
#include "cli/InterruptGuard.h"
#include "image_files/AtomicFile.h"
#include "image_files/CommandPaths.h"
#include "image_files/ImageComparison.h"
#include "image_files/ImageFile.h"
#include "image_files/OutputFiles.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <iostream>

namespace ivshadow {
namespace {

nlohmann::json channelJson(const ImageComparison::Channel& channel) {
  return {
      {"rmse", channel.rmse},
      {"max_abs_error", channel.maxError},
      // JSON has no infinity: identical channels report null.
      {"psnr_db", std::isfinite(channel.psnr) ? nlohmann::json(channel.psnr) : nlohmann::json()},
      {"share_above_2", channel.shareAbove2}};
}

void printRow(const char* name, const ImageComparison::Channel& channel) {
  char psnr[32];
  if (std::isfinite(channel.psnr))
    std::snprintf(psnr, sizeof(psnr), "%.2f", channel.psnr);
  else
    std::snprintf(psnr, sizeof(psnr), "inf");
  std::printf("%-6s %9.4f %5d %9s %9.3f %%\n", name, channel.rmse, channel.maxError, psnr,
              100.0 * channel.shareAbove2);
}

}  // namespace

int runCompare(const CompareOptions& options) {
  return withExitStatus([&] {
    CommandPaths()
        .input("reference", options.reference)
        .input("candidate", options.candidate)
        .output("--diff", options.diffPath)
        .output("--json", options.jsonPath)
        .check();
    checkImageInput("reference", options.reference);
    checkImageInput("candidate", options.candidate);
    if (!options.diffPath.empty()) {
      checkImageOutput("--diff", options.diffPath);
      imageFormatFor(options.diffPath);
      AtomicFile::checkWritable(options.diffPath, "the diff image");
    }
    if (!options.jsonPath.empty()) AtomicFile::checkWritable(options.jsonPath, "the metrics");
    const Image a = readImage(options.reference);
    const Image b = readImage(options.candidate);
    const ImageComparison result =
        ImageComparison::compare(a, b, options.reference.c_str(), options.candidate.c_str());
    std::printf("%-6s %9s %5s %9s %11s\n", "", "RMSE", "max", "PSNR dB", "> 2/255");
    const char* names[3] = {"red", "green", "blue"};
    for (int c = 0; c < 3; ++c) printRow(names[c], result.channels[std::size_t(c)]);
    printRow("all", result.all);
    std::printf("largest error %d at pixel (%d, %d)\n", result.all.maxError, result.maxErrorX,
                result.maxErrorY);
    // The heat map and the metrics together or neither.
    OutputFiles outputs;
    const int scale = options.scale > 0 ? options.scale : std::max(result.all.maxError, 1);
    Image heatMap;
    if (!options.diffPath.empty()) {
      heatMap = errorHeatMap(a, b, scale);
      outputs.addImage(options.diffPath, heatMap);
    }
    if (!options.jsonPath.empty()) {
      nlohmann::json json = {{"reference", options.reference},
                             {"candidate", options.candidate},
                             {"width", a.width()},
                             {"height", a.height()},
                             {"red", channelJson(result.channels[0])},
                             {"green", channelJson(result.channels[1])},
                             {"blue", channelJson(result.channels[2])},
                             {"all", channelJson(result.all)}};
      outputs.addText(options.jsonPath, json.dump(2) + "\n");
    }
    // A signal during the writes leaves none of them (cli/InterruptGuard.h).
    const InterruptGuard guard;
    if (!outputs.commit(&InterruptGuard::flag())) {
      std::cerr << "ivshadow: interrupted; nothing written\n";
      return InterruptGuard::exitStatus();
    }
    if (!options.diffPath.empty())
      std::printf("wrote %s (white = %d steps or more)\n", options.diffPath.c_str(), scale);
    return 0;
  });
}

}  // namespace ivshadow
