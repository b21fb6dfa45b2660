#pragma once

#include "cli/RenderCommand.h"
#include "headless/OffscreenRenderer.h"
#include "ivshadow/DeepShadowStatistics.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

class SoNode;

namespace ivshadow {

// The `--stats` of a render (docs/CLI.md, "--stats keys"): the frames' times, the machine,
// and what the nodes under `root` did. `before`, for a scene kept from an earlier render
// (cli/KeptScene.h), is what its groups had counted before this render's frames: the counts
// are then this render's, and a figure this render did not make again reads 0, as from a
// scene read afresh. Defined in RenderCommand.cpp.
nlohmann::json renderStatistics(const RenderOptions& options, const OffscreenRenderer& renderer,
                                const std::vector<double>& wallMs, const std::vector<double>& gpuMs,
                                const std::string& transparency, SoNode* root,
                                const DeepShadowStatistics* before = nullptr);

}  // namespace ivshadow
