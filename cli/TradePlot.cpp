#include "cli/TradePlot.h"

#include "cli/SvgDocument.h"
#include "image_files/OutputFiles.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace ivshadow {
namespace {

constexpr int kWidth = 1100, kHeight = 720;
// The plot's frame; the legend sits right of it, the reference's band above it.
constexpr double kLeft = 80, kRight = 900, kTop = 110, kBottom = 640;
constexpr double kBandTop = 70;

// The chart's type: 9 and 8 points at 96 dpi, the title 12 points bold.
const SvgFont kFont{12.0};
const SvgFont kSmall{10.7};
const SvgFont kTitle{16.0, true};

const SvgColour kBlack{0, 0, 0};
const SvgColour kWhite{255, 255, 255};
const SvgColour kGrid{215, 215, 215};
const SvgColour kMinorGrid{240, 240, 240};
const SvgColour kBand{244, 244, 244};
const SvgColour kBandText{90, 90, 90};
const SvgColour kNote{80, 80, 80};
const SvgColour kLeader{120, 120, 120};
const SvgColour kFrontLine{0, 0, 0, 170.0 / 255.0};
// A white ground keeps a label legible over grid lines and the front's line.
const SvgColour kLabelGround{255, 255, 255, 220.0 / 255.0};
constexpr double kFrontWidth = 2.5;

enum class Shape { Circle, Diamond, TriangleUp, Square, TriangleDown, HollowSquare };

struct Style {
  const char* method;
  SvgColour colour;
  Shape shape;
};

// One colour and shape per method (a colour-blind-safe palette), in the legend's order.
const Style kStyles[] = {
    {trade_kind::kMap, {0, 114, 178}, Shape::Circle},
    {trade_kind::kOpacityMap, {230, 159, 0}, Shape::Diamond},
    {trade_kind::kRays, {0, 158, 115}, Shape::TriangleUp},
    {trade_kind::kVolumes, {204, 121, 167}, Shape::Square},
    {trade_kind::kTracer, {213, 94, 0}, Shape::TriangleDown},
    {trade_kind::kBaseline, {40, 40, 40}, Shape::HollowSquare},
};

const Style& styleOf(const TradePoint& point) {
  for (const Style& style : kStyles)
    if (point.method == style.method) return style;
  return kStyles[0];
}

void drawMarker(SvgDocument& svg, const Style& style, SvgPoint at, double r, bool outlined) {
  const SvgColour edge = style.colour.darker(1.3);
  const bool hollow = style.shape == Shape::HollowSquare;
  SvgStyle paint{hollow ? &kWhite : &style.colour, outlined ? &kBlack : &edge,
                 outlined ? 1.5 : 1.0};
  const auto corners = [&](std::initializer_list<SvgPoint> offsets) {
    std::vector<SvgPoint> out;
    for (const SvgPoint& o : offsets) out.push_back({at.x + o.x * r, at.y + o.y * r});
    return out;
  };
  switch (style.shape) {
    case Shape::Circle:
      svg.circle(at, r, paint);
      break;
    case Shape::Diamond:
      svg.polygon(corners({{0, -1.3}, {1.3, 0}, {0, 1.3}, {-1.3, 0}}), paint);
      break;
    case Shape::TriangleUp:
      svg.polygon(corners({{0, -1.3}, {1.2, 1}, {-1.2, 1}}), paint);
      break;
    case Shape::TriangleDown:
      svg.polygon(corners({{0, 1.3}, {1.2, -1}, {-1.2, -1}}), paint);
      break;
    case Shape::Square:
    case Shape::HollowSquare:
      if (hollow) paint = {&kWhite, &style.colour, 2.0};
      svg.rect(at.x - r, at.y - r, 2 * r, 2 * r, paint);
      break;
  }
}

// A round step for about `wanted` ticks over `span`: 1, 2 or 5 times a power of ten.
double roundStep(double span, int wanted) {
  const double raw = span / wanted;
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * power >= raw) return m * power;
  return 10.0 * power;
}

std::string tickText(double value) {
  std::ostringstream out;
  out.precision(6);
  out << value;
  return out.str();
}

// The axes' ranges and the mapping of a point onto the picture: time on a log axis over every
// point, dB over the finite ones, both a little wider so that no marker sits on the frame;
// infinite dB (an exact picture) on the band above the frame.
struct Axes {
  double lo = 0.0, hi = 1.0;  // log10 of ms at the frame's left and right
  double dbLo = 0.0, dbHi = 1.0, dbStep = 1.0;

  explicit Axes(const std::vector<TradePoint>& points) {
    double tMin = 1e300, tMax = 0.0, dbMin = 1e300, dbMax = -1e300;
    for (const TradePoint& p : points) {
      tMin = std::min(tMin, std::max(p.timeMs, 1e-3));
      tMax = std::max(tMax, std::max(p.timeMs, 1e-3));
      if (std::isfinite(p.psnrDb)) {
        dbMin = std::min(dbMin, p.psnrDb);
        dbMax = std::max(dbMax, p.psnrDb);
      }
    }
    if (tMax <= 0.0) tMin = tMax = 1.0;
    if (dbMin > dbMax) dbMin = dbMax = 30.0;
    lo = std::log10(tMin) - 0.08;
    hi = std::max(std::log10(tMax) + 0.08, lo + 1.0);
    dbStep = roundStep(std::max(dbMax - dbMin, 5.0), 7);
    dbLo = std::floor((dbMin - 0.3 * dbStep) / dbStep) * dbStep;
    dbHi = std::ceil((dbMax + 0.3 * dbStep) / dbStep) * dbStep;
  }

  double x(double ms) const {
    return kLeft + (std::log10(std::max(ms, 1e-3)) - lo) / (hi - lo) * (kRight - kLeft);
  }
  double y(double db) const {
    return std::isfinite(db) ? kBottom - (db - dbLo) / (dbHi - dbLo) * (kBottom - kTop)
                             : (kBandTop + kTop - 6) / 2;
  }
  SvgPoint at(const TradePoint& p) const { return {x(p.timeMs), y(p.psnrDb)}; }
};

struct Box {
  double x, y, w, h;
  bool inside(const Box& o) const {
    return x >= o.x && y >= o.y && x + w <= o.x + o.w && y + h <= o.y + o.h;
  }
  bool intersects(const Box& o) const {
    return x < o.x + o.w && o.x < x + w && y < o.y + o.h && o.y < y + h;
  }
};

// Places labels next to their points without covering one another, a point or the frame:
// the nearest free place among eight around the point, further out if none is free (with a
// line back to the point), and where nothing is free at all, beside the point regardless.
class LabelPlacer {
 public:
  LabelPlacer(SvgDocument& svg, const Box& area) : svg_(svg), area_(area) {}

  void avoid(const Box& box) { taken_.push_back(box); }

  void place(SvgPoint at, const std::string& text) {
    const double w = kSmall.width(text) + 4, h = kSmall.size * 1.25;
    for (double distance : {7.0, 18.0, 32.0, 50.0, 75.0}) {
      const SvgPoint offsets[8] = {{distance, -h / 2},
                                   {-distance - w, -h / 2},
                                   {-w / 2, -distance - h},
                                   {-w / 2, distance},
                                   {distance, -distance - h},
                                   {distance, distance},
                                   {-distance - w, -distance - h},
                                   {-distance - w, distance}};
      for (const SvgPoint& offset : offsets) {
        const Box box{at.x + offset.x, at.y + offset.y, w, h};
        if (!box.inside(area_) || covers(box)) continue;
        draw(at, box, text, distance > 7.0);
        return;
      }
    }
    draw(at, {at.x + 7, at.y - h / 2, w, h}, text, false);
  }

 private:
  bool covers(const Box& box) const {
    return std::any_of(taken_.begin(), taken_.end(),
                       [&](const Box& other) { return other.intersects(box); });
  }

  void draw(SvgPoint at, const Box& box, const std::string& text, bool leader) {
    if (leader) {
      const SvgPoint nearest{std::clamp(at.x, box.x, box.x + box.w),
                             std::clamp(at.y, box.y, box.y + box.h)};
      svg_.line(at, nearest, kLeader, 0.8);
    }
    svg_.rect(box.x, box.y, box.w, box.h, {&kLabelGround});
    svg_.text({box.x + box.w / 2, box.y + box.h / 2}, text, kSmall, SvgAnchor::Middle, kBlack);
    taken_.push_back(box);
  }

  SvgDocument& svg_;
  Box area_;
  std::vector<Box> taken_;
};

// Grid and round ticks: 1, 2 and 5 times a power of ten on the time axis (only the powers of
// ten labelled when the range spans more than three decades), a round step in dB.
void drawGrid(SvgDocument& svg, const Axes& axes) {
  const bool manyDecades = axes.hi - axes.lo > 3.0;
  for (double decade = std::floor(axes.lo); decade <= std::ceil(axes.hi); decade += 1.0)
    for (int m = 1; m < 10; ++m) {
      const double ms = std::pow(10.0, decade) * m;
      const double at = axes.x(ms);
      if (at < kLeft - 0.5 || at > kRight + 0.5) continue;
      const bool labelled = m == 1 || (!manyDecades && (m == 2 || m == 5));
      svg.line({at, kTop}, {at, kBottom}, labelled ? kGrid : kMinorGrid, 1);
      if (labelled) svg.text({at, kBottom + 14}, tickText(ms), kFont, SvgAnchor::Middle, kBlack);
    }
  for (double db = axes.dbLo; db <= axes.dbHi + 1e-9; db += axes.dbStep) {
    svg.line({kLeft, axes.y(db)}, {kRight, axes.y(db)}, kGrid, 1);
    svg.text({kLeft - 8, axes.y(db)}, tickText(db), kFont, SvgAnchor::End, kBlack);
  }
}

// The frame, the axes' titles, the band of exact pictures (the reference, and any setting that
// matches it to the last bit: their PSNR is infinite, off any dB scale), the title and how to
// read the chart.
void drawFrameAndTitles(SvgDocument& svg, const std::string& title) {
  svg.rect(kLeft, kTop, kRight - kLeft, kBottom - kTop, {nullptr, &kBlack, 1});
  svg.text({(kLeft + kRight) / 2, kBottom + 40},
           "time per frame with a rebuild (ms, log scale): further left is faster", kFont,
           SvgAnchor::Middle, kBlack);
  svg.text({22, (kTop + kBottom) / 2}, "PSNR against the exact reference (dB): higher is closer",
           kFont, SvgAnchor::Middle, kBlack, -90);
  svg.rect(kLeft, kBandTop, kRight - kLeft, kTop - 6 - kBandTop, {&kBand});
  // Two lines: one would be wider than the margin left of the frame.
  const double bandMiddle = (kBandTop + kTop - 6) / 2;
  svg.text({kLeft - 8, bandMiddle - 7}, "exact", kSmall, SvgAnchor::End, kBandText);
  svg.text({kLeft - 8, bandMiddle + 7}, "(\u221e dB)", kSmall, SvgAnchor::End, kBandText);
  svg.text({kWidth / 2.0, 21}, title, kTitle, SvgAnchor::Middle, kBlack);
  svg.text({kWidth / 2.0, 44},
           "Take a setting on the Pareto front (outlined, on the black line): no other setting "
           "is both faster and closer to the reference.",
           kFont, SvgAnchor::Middle, kBlack);
}

// The front, fastest first.
std::vector<const TradePoint*> frontOf(const std::vector<TradePoint>& points) {
  std::vector<const TradePoint*> front;
  for (const TradePoint& p : points)
    if (p.pareto) front.push_back(&p);
  std::sort(front.begin(), front.end(),
            [](const TradePoint* a, const TradePoint* b) { return a->timeMs < b->timeMs; });
  return front;
}

// The front as a staircase: from each of its points the best error reached so far holds until
// a slower point of the front does better, and from the last on to the frame's edge, so that a
// front of one point (the tracer, where it wins) still shows as a line.
void drawFront(SvgDocument& svg, const Axes& axes, const std::vector<const TradePoint*>& front) {
  if (front.empty()) return;
  std::vector<SvgPoint> stairs{axes.at(*front[0])};
  for (std::size_t i = 1; i < front.size(); ++i) {
    stairs.push_back({axes.x(front[i]->timeMs), axes.y(front[i - 1]->psnrDb)});
    stairs.push_back(axes.at(*front[i]));
  }
  stairs.push_back({kRight, axes.y(front.back()->psnrDb)});
  svg.polyline(stairs, kFrontLine, kFrontWidth);
}

// Points off the front first, small, so that the front's are drawn over them; then the labels:
// the baselines, the front, and each method's only setting (rays, volumes, the tracer)
// wherever it falls, so that every method is named on the chart itself.
void drawPoints(SvgDocument& svg, const Axes& axes, const std::vector<TradePoint>& points,
                const std::vector<const TradePoint*>& front) {
  LabelPlacer labels(svg, {kLeft + 2, kBandTop + 2, kRight - kLeft - 4, kBottom - kBandTop - 4});
  for (const TradePoint& p : points)
    labels.avoid({axes.x(p.timeMs) - 6, axes.y(p.psnrDb) - 6, 12, 12});
  for (const TradePoint& p : points)
    if (!p.pareto && !p.baseline) drawMarker(svg, styleOf(p), axes.at(p), 3.5, false);
  for (const TradePoint& p : points)
    if (p.pareto || p.baseline) drawMarker(svg, styleOf(p), axes.at(p), 5.5, p.pareto);
  for (const TradePoint& p : points)
    if (p.baseline) labels.place(axes.at(p), p.label);
  for (const TradePoint* p : front) labels.place(axes.at(*p), p->label);
  for (const TradePoint& p : points)
    if (!p.pareto && !p.baseline && p.method != trade_kind::kMap &&
        p.method != trade_kind::kOpacityMap)
      labels.place(axes.at(p), p.label);
}

// The legend: the methods the chart shows, then what the outlines and the line mean.
void drawLegend(SvgDocument& svg, const std::vector<TradePoint>& points) {
  const double x = kRight + 22;
  double y = kTop + 4;
  svg.text({x, y + 6}, "method", kFont, SvgAnchor::Start, kBlack);
  y += 24;
  for (const Style& style : kStyles) {
    const bool shown = std::any_of(points.begin(), points.end(),
                                   [&](const TradePoint& p) { return p.method == style.method; });
    if (!shown) continue;
    drawMarker(svg, style, {x + 8, y}, 5, false);
    svg.text({x + 22, y}, style.method, kFont, SvgAnchor::Start, kBlack);
    y += 22;
  }
  y += 10;
  drawMarker(svg, kStyles[0], {x + 8, y}, 5.5, true);
  svg.text({x + 22, y}, "on the front (labelled)", kFont, SvgAnchor::Start, kBlack);
  y += 22;
  svg.line({x, y}, {x + 16, y}, kFrontLine, kFrontWidth);
  svg.text({x + 22, y}, "Pareto front", kFont, SvgAnchor::Start, kBlack);
  y += 30;
  for (const char* line :
       {"Small markers: the other", "settings of the maps' sweeps;", "trade.csv names each."}) {
    svg.text({x, y}, line, kSmall, SvgAnchor::Start, kNote);
    y += 15;
  }
}

}  // namespace

void markParetoFront(std::vector<TradePoint>& points) {
  for (TradePoint& p : points) {
    p.pareto = !p.baseline;
    for (const TradePoint& q : points) {
      if (&q == &p || q.baseline) continue;
      const bool noWorse = q.timeMs <= p.timeMs && q.rmse <= p.rmse;
      const bool better = q.timeMs < p.timeMs || q.rmse < p.rmse;
      if (noWorse && better) {
        p.pareto = false;
        break;
      }
    }
  }
}

std::string tradePlotSvg(const std::string& title, const std::vector<TradePoint>& points) {
  SvgDocument svg(kWidth, kHeight);
  svg.rect(0, 0, kWidth, kHeight, {&kWhite});
  const Axes axes(points);
  drawGrid(svg, axes);
  drawFrameAndTitles(svg, title);
  const std::vector<const TradePoint*> front = frontOf(points);
  drawFront(svg, axes, front);
  drawPoints(svg, axes, points, front);
  drawLegend(svg, points);
  return svg.str();
}

void addTradePlot(OutputFiles& outputs, const std::string& path, const std::string& title,
                  const std::vector<TradePoint>& points) {
  outputs.addText(path, tradePlotSvg(title, points));
}

}  // namespace ivshadow
