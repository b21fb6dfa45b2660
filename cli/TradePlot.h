#pragma once

#include <string>
#include <vector>

namespace ivshadow {

class OutputFiles;

// The kinds of trade's rows (trade.csv's `kind` column), each the legend's entry that gives its
// points their colour and shape.
namespace trade_kind {
inline constexpr const char* kMap = "deep shadow map";
inline constexpr const char* kOpacityMap = "opacity map";
inline constexpr const char* kRays = "rays";
inline constexpr const char* kVolumes = "shadow volumes";
inline constexpr const char* kTracer = "tracer";
inline constexpr const char* kBaseline = "baseline";
}  // namespace trade_kind

struct TradePoint {
  std::string label;
  std::string method;   // one of trade_kind
  double timeMs = 0.0;  // x: cost
  double rmse = 0.0;    // RMSE in 8-bit steps against the reference: what the front minimises
  double psnrDb = 0.0;  // y: the same error in dB; infinite for the reference itself
  bool baseline = false;
  bool pareto = false;
};

// Marks the points no other point beats in both time and error (the Pareto front).
void markParetoFront(std::vector<TradePoint>& points);

// Draws the error in dB (PSNR against the reference, higher is closer) against time on a log
// axis, with round ticks: each method in a colour and shape of its own, named in a legend; the
// Pareto front as a staircase, its points and the baselines labelled, labels kept off one
// another; the reference, whose PSNR is infinite, on a band above the axis. An SVG picture
// (1100 x 720 units), which browsers and Markdown pages show.
std::string tradePlotSvg(const std::string& title, const std::vector<TradePoint>& points);

// Adds tradePlotSvg's picture to `outputs` as `path`, written with the command's other files.
void addTradePlot(OutputFiles& outputs, const std::string& path, const std::string& title,
                  const std::vector<TradePoint>& points);

}  // namespace ivshadow
