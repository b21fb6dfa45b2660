#pragma once

#include <string>
#include <vector>

namespace ivshadow {

struct TradeOptions {
  std::string scene;
  std::string outputDir;
  std::string size = "320x240";
  std::vector<int> resolutions{256, 512, 1024};
  std::vector<int> layers{1, 2, 4, 8};
  std::vector<std::string> precisions{"half", "float"};
  std::vector<std::string> filters{"none", "bilinear", "pcf"};
  std::vector<int> slices{4, 16};  // the opacity maps'
  // rays and volumes: one setting each, exact; map and opacity: their sweeps
  std::vector<std::string> methods{"map", "rays", "volumes", "opacity", "tracer"};
  int frames = 5;
};

// `ivshadow trade`: renders the scene with every combination of the deep shadow settings
// (resolution x layers x precision x filter for the deep shadow map, resolution x slices x
// precision x filter for the opacity map),
// times each (map build and frame separately, median of --frames), measures its error against
// the exact reference and writes DIR/trade.csv and DIR/trade.png (error against time, Pareto
// front marked) with the baselines. Exit 0, 2 on bad input, 3 without GL, 1 otherwise.
int runTrade(const TradeOptions& options);

}  // namespace ivshadow
