#pragma once

#include <vector>

namespace ivshadow {

// Summaries of per-frame times in milliseconds. Medians resist the first frame's one-off costs
// (shader compilation, display-list building) that the minimum and the list still show.
struct FrameStatistics {
  static double median(std::vector<double> values);
  static double minimum(const std::vector<double>& values);
};

}  // namespace ivshadow
