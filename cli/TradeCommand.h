#pragma once

#include <string>
#include <vector>

namespace ivshadow {

// The values --method, --precision and --filter accept, each list the one place that names
// them: the options' defaults, their help and the messages refusing other values read them.
inline const std::vector<std::string> kTradeMethods{"map", "rays", "volumes", "opacity", "tracer"};
inline const std::vector<std::string> kTradePrecisions{"half", "float"};
inline const std::vector<std::string> kTradeFilters{"none", "bilinear", "pcf"};

// "a, b and c", for help and messages.
std::string joinedList(const std::vector<std::string>& values, const std::string& last);

struct TradeOptions {
  std::string scene;
  std::string outputDir;
  std::string size = "320x240";
  std::vector<int> resolutions{256, 512, 1024};
  std::vector<int> layers{1, 2, 4, 8};
  std::vector<std::string> precisions = kTradePrecisions;
  std::vector<std::string> filters = kTradeFilters;
  std::vector<int> slices{4, 16};  // the opacity maps'
  // rays and volumes: one setting each, exact; map and opacity: their sweeps
  std::vector<std::string> methods = kTradeMethods;
  int frames = 5;
};

// `ivshadow trade`: renders the scene with every combination of the deep shadow settings
// (resolution x layers x precision x filter for the deep shadow map, resolution x slices x
// precision x filter for the opacity map),
// times each (map build and frame separately, median of --frames), measures its error against
// the exact reference and writes DIR/trade.csv and DIR/trade.svg (error against time, Pareto
// front marked) with the baselines. Exit 0, 2 on bad input, 3 without GL, 1 otherwise.
int runTrade(const TradeOptions& options);

}  // namespace ivshadow
