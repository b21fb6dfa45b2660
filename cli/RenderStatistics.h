#pragma once

#include "cli/RenderCommand.h"
#include "headless/OffscreenRenderer.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

class SoNode;

namespace ivshadow {

// The `--stats` of a render (docs/CLI.md, "--stats keys"): the frames' times, the machine,
// and what the nodes under `root` did. Defined in RenderCommand.cpp.
nlohmann::json renderStatistics(const RenderOptions& options, const OffscreenRenderer& renderer,
                                const std::vector<double>& wallMs, const std::vector<double>& gpuMs,
                                const std::string& transparency, SoNode* root);

}  // namespace ivshadow
