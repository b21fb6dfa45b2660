#pragma once

#include <string>
#include <vector>

namespace ivshadow {

class OutputFiles;

struct TradePoint {
  std::string label;
  // The legend's entry, which gives the point its colour and shape: "deep shadow map",
  // "opacity map", "rays", "shadow volumes", "tracer" or "baseline".
  std::string method;
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
// another; the reference, whose PSNR is infinite, on a band above the axis. Adds the PNG to
// `outputs`, written with the command's other files. Needs no display (Qt's offscreen
// platform is used when there is none).
void addTradePlot(OutputFiles& outputs, const std::string& path, const std::string& title,
                  const std::vector<TradePoint>& points);

}  // namespace ivshadow
