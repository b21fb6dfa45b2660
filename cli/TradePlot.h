#pragma once

#include <string>
#include <vector>

namespace ivshadow {

class OutputFiles;

struct TradePoint {
  std::string label;
  double timeMs = 0.0;  // x: cost
  double error = 0.0;   // y: RMSE in 8-bit steps against the reference
  bool baseline = false;
  bool pareto = false;
  // A method's one setting (RAYS, VOLUMES): named wherever it falls, so that every method is
  // on the chart by name, not only those on the front.
  bool method = false;
  // Drawn as a diamond, not a circle: an opacity map's setting, told apart from the deep
  // shadow map's on the same chart.
  bool diamond = false;
};

// Marks the points no other point beats in both time and error (the Pareto front).
void markParetoFront(std::vector<TradePoint>& points);

// Draws error against time (log time axis), one dot per setting (a diamond for an opacity
// map's), the Pareto front joined and labelled, baselines as squares, labels moved off one
// another; adds the PNG to `outputs`, written with the command's other files. Needs no
// display (Qt's offscreen platform is used when there is none).
void addTradePlot(OutputFiles& outputs, const std::string& path, const std::string& title,
                  const std::vector<TradePoint>& points);

}  // namespace ivshadow
