#include "cli/TradePlot.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <regex>

namespace ivshadow {
namespace {

// What the chart draws, read back from its SVG text.
struct Drawn {
  std::vector<std::pair<double, double>> circles;          // centres
  std::map<std::string, std::pair<double, double>> texts;  // text -> where
  std::vector<std::string> polylines;                      // their points="..." values
};

Drawn parse(const std::string& svg) {
  Drawn drawn;
  const std::regex circle(R"re(<circle cx="([-0-9.]+)" cy="([-0-9.]+)")re");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), circle); it != std::sregex_iterator();
       ++it)
    drawn.circles.emplace_back(std::stod((*it)[1]), std::stod((*it)[2]));
  const std::regex text(R"re(<text x="([-0-9.]+)" y="([-0-9.]+)"[^>]*>([^<]*)</text>)re");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), text); it != std::sregex_iterator();
       ++it)
    drawn.texts[(*it)[3]] = {std::stod((*it)[1]), std::stod((*it)[2])};
  const std::regex polyline(R"re(<polyline points="([^"]*)")re");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), polyline);
       it != std::sregex_iterator(); ++it)
    drawn.polylines.push_back((*it)[1]);
  return drawn;
}

TradePoint point(const std::string& label, double ms, double db) {
  // RMSE in 8-bit steps from PSNR: the front is chosen on RMSE, the chart drawn in dB.
  return {label, trade_kind::kMap, ms, 255.0 * std::pow(10.0, -db / 20.0), db, false, false};
}

// Coordinates are written with two decimals.
constexpr double kWritten = 0.01;

// The axes are read as a reader reads them: a point drawn at 10 ms and 30 dB lies where the
// ticks labelled 10 and 30 are, and equal ratios of time are equal distances (a log axis).
TEST(TradePlot, PointsLieOnTheirTicksOnALogTimeAxis) {
  std::vector<TradePoint> points{point("a", 1.0, 20.0), point("b", 10.0, 30.0),
                                 point("c", 100.0, 40.0)};
  markParetoFront(points);
  const Drawn drawn = parse(tradePlotSvg("title", points));
  // The points first, then the legend's two: the method's marker and "on the front".
  ASSERT_EQ(drawn.circles.size(), 3u + 2u);
  const auto at = [&](const std::string& tick) { return drawn.texts.at(tick); };
  EXPECT_NEAR(drawn.circles[0].first, at("1").first, kWritten);
  EXPECT_NEAR(drawn.circles[1].first, at("10").first, kWritten);
  EXPECT_NEAR(drawn.circles[2].first, at("100").first, kWritten);
  EXPECT_NEAR(drawn.circles[1].first - drawn.circles[0].first,
              drawn.circles[2].first - drawn.circles[1].first, 2 * kWritten);
  EXPECT_NEAR(drawn.circles[0].second, at("20").second, kWritten);
  EXPECT_NEAR(drawn.circles[1].second, at("30").second, kWritten);
  EXPECT_NEAR(drawn.circles[2].second, at("40").second, kWritten);
  // Closer (more dB) is higher on the picture, whose y grows downwards.
  EXPECT_LT(drawn.circles[2].second, drawn.circles[0].second);
}

// The front is a staircase through its points, slowest last, on to the frame's right edge;
// a point both slower and further off than another is off it and unlabelled.
TEST(TradePlot, TheFrontIsAStaircaseThroughTheUnbeatenPoints) {
  std::vector<TradePoint> points{point("fast", 2.0, 20.0), point("beaten", 20.0, 18.0),
                                 point("slow", 50.0, 35.0)};
  markParetoFront(points);
  EXPECT_TRUE(points[0].pareto);
  EXPECT_FALSE(points[1].pareto);
  EXPECT_TRUE(points[2].pareto);
  const Drawn drawn = parse(tradePlotSvg("title", points));
  EXPECT_EQ(drawn.texts.count("beaten"), 0u);
  // The front's line is the one polyline of five vertices: fast, the corner below slow,
  // slow, the frame's edge at slow's height.
  const auto fast = drawn.texts.at("fast");
  std::vector<std::string> stairs;
  for (const std::string& line : drawn.polylines)
    if (std::count(line.begin(), line.end(), ' ') == 3) stairs.push_back(line);
  ASSERT_EQ(stairs.size(), 1u) << "one staircase of four points";
  double x[4], y[4];
  ASSERT_EQ(std::sscanf(stairs[0].c_str(), "%lf,%lf %lf,%lf %lf,%lf %lf,%lf", &x[0], &y[0], &x[1],
                        &y[1], &x[2], &y[2], &x[3], &y[3]),
            8);
  EXPECT_LT(x[0], fast.first) << "the label is placed right of its point";
  EXPECT_NEAR(y[1], y[0], kWritten) << "the fast point's error holds until the slow one";
  EXPECT_NEAR(x[2], x[1], kWritten);
  EXPECT_LT(y[2], y[1]) << "then the slow point, closer, is higher";
  EXPECT_NEAR(y[3], y[2], kWritten);
  EXPECT_GT(x[3], x[2]);
}

// Baselines are never on the front, and an exact picture (infinite dB) sits on the band
// above the frame, not off the picture.
TEST(TradePlot, BaselinesAreOffTheFrontAndExactPicturesOnTheBand) {
  std::vector<TradePoint> points{point("map", 5.0, 25.0),
                                 {"exact (CPU reference)", trade_kind::kBaseline, 100.0, 0.0,
                                  std::numeric_limits<double>::infinity(), true, false},
                                 {"plain", trade_kind::kBaseline, 1.0, 40.0, 16.0, true, false}};
  markParetoFront(points);
  EXPECT_TRUE(points[0].pareto);
  EXPECT_FALSE(points[1].pareto);
  EXPECT_FALSE(points[2].pareto);
  const Drawn drawn = parse(tradePlotSvg("title", points));
  const double band = drawn.texts.at("exact").second;
  const double reference = drawn.texts.at("exact (CPU reference)").second;
  EXPECT_NEAR(reference, band + 7, 8) << "labelled beside its marker on the band";
  EXPECT_LT(reference, drawn.texts.at("map").second);
}

// Labels come from scene files and --set values: whatever they hold, the SVG stays XML.
TEST(TradePlot, TextIsEscapedForXml) {
  std::vector<TradePoint> points{point("a <b> & \"c\"", 5.0, 25.0)};
  markParetoFront(points);
  const std::string svg = tradePlotSvg("scene <1>.iv & more", points);
  EXPECT_NE(svg.find("a &lt;b&gt; &amp; &quot;c&quot;"), std::string::npos);
  EXPECT_NE(svg.find("scene &lt;1&gt;.iv &amp; more"), std::string::npos);
  EXPECT_EQ(svg.find("<b>"), std::string::npos);
  EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
  EXPECT_NE(svg.find("</svg>\n"), std::string::npos);
}

}  // namespace
}  // namespace ivshadow
