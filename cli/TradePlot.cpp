#include "cli/TradePlot.h"

#include "image/OutputFiles.h"

#include <QFont>
#include <QFontMetricsF>
#include <QGuiApplication>
#include <QImage>
#include <QPainter>
#include <QPainterPath>
#include <QtGlobal>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <stdexcept>

namespace ivshadow {
namespace {

constexpr int kWidth = 1100, kHeight = 720;
// The plot's frame; the legend sits right of it, the reference's band above it.
constexpr double kLeft = 80, kRight = 900, kTop = 110, kBottom = 640;
constexpr double kBandTop = 70;

enum class Shape { Circle, Diamond, TriangleUp, Square, TriangleDown, HollowSquare };

struct Style {
  const char* method;
  QColor colour;
  Shape shape;
};

// One colour and shape per method (a colour-blind-safe palette), in the legend's order.
const Style kStyles[] = {
    {trade_kind::kMap, QColor(0, 114, 178), Shape::Circle},
    {trade_kind::kOpacityMap, QColor(230, 159, 0), Shape::Diamond},
    {trade_kind::kRays, QColor(0, 158, 115), Shape::TriangleUp},
    {trade_kind::kVolumes, QColor(204, 121, 167), Shape::Square},
    {trade_kind::kTracer, QColor(213, 94, 0), Shape::TriangleDown},
    {trade_kind::kBaseline, QColor(40, 40, 40), Shape::HollowSquare},
};

const Style& styleOf(const TradePoint& point) {
  for (const Style& style : kStyles)
    if (point.method == style.method) return style;
  return kStyles[0];
}

void drawMarker(QPainter& painter, const Style& style, const QPointF& at, double radius,
                bool outlined) {
  painter.setPen(outlined ? QPen(Qt::black, 1.5) : QPen(style.colour.darker(130), 1));
  painter.setBrush(style.shape == Shape::HollowSquare ? QBrush(Qt::white) : QBrush(style.colour));
  const double r = radius;
  switch (style.shape) {
    case Shape::Circle:
      painter.drawEllipse(at, r, r);
      break;
    case Shape::Diamond: {
      const QPointF c[4] = {at + QPointF(0, -1.3 * r), at + QPointF(1.3 * r, 0),
                            at + QPointF(0, 1.3 * r), at + QPointF(-1.3 * r, 0)};
      painter.drawPolygon(c, 4);
      break;
    }
    case Shape::TriangleUp: {
      const QPointF c[3] = {at + QPointF(0, -1.3 * r), at + QPointF(1.2 * r, r),
                            at + QPointF(-1.2 * r, r)};
      painter.drawPolygon(c, 3);
      break;
    }
    case Shape::TriangleDown: {
      const QPointF c[3] = {at + QPointF(0, 1.3 * r), at + QPointF(1.2 * r, -r),
                            at + QPointF(-1.2 * r, -r)};
      painter.drawPolygon(c, 3);
      break;
    }
    case Shape::Square:
    case Shape::HollowSquare:
      if (style.shape == Shape::HollowSquare) painter.setPen(QPen(style.colour, 2));
      painter.drawRect(QRectF(at.x() - r, at.y() - r, 2 * r, 2 * r));
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

QString tickText(double value) {
  return QString::number(value, 'g', 6);
}

// Qt looks for a Wayland display socket in XDG_RUNTIME_DIR when it starts, before it reads
// QT_QPA_PLATFORM, and warns on stderr where that is unset (ssh, batch jobs, containers). The
// offscreen platform the chart is drawn on needs no runtime directory, so that one warning,
// while the application starts, says nothing to the user; every other message goes on.
QtMessageHandler qtHandler = nullptr;
void withoutRuntimeDirWarning(QtMsgType type, const QMessageLogContext& context,
                              const QString& message) {
  if (type == QtWarningMsg && message.startsWith("QStandardPaths: XDG_RUNTIME_DIR not set")) return;
  qtHandler(type, context, message);
}

std::unique_ptr<QGuiApplication> offscreenApplication() {
  if (QGuiApplication::instance() != nullptr) return nullptr;
  // Text needs a QGuiApplication; a command-line run has no display.
  if (std::getenv("QT_QPA_PLATFORM") == nullptr) setenv("QT_QPA_PLATFORM", "offscreen", 1);
  static int argc = 1;
  static char name[] = "ivshadow";
  static char* argv[] = {name, nullptr};
  qtHandler = qInstallMessageHandler(withoutRuntimeDirWarning);
  auto app = std::make_unique<QGuiApplication>(argc, argv);
  qInstallMessageHandler(qtHandler);
  return app;
}

// Places labels next to their points without covering one another, a point or the frame:
// the nearest free place among eight around the point, further out if none is free (with a
// line back to the point), and where nothing is free at all, beside the point regardless.
class LabelPlacer {
 public:
  LabelPlacer(QPainter& painter, const QRectF& area) : painter_(painter), area_(area) {}

  void avoid(const QRectF& box) { taken_.push_back(box); }

  void place(const QPointF& at, const QString& text) {
    const QFontMetricsF metrics(painter_.font());
    const double w = metrics.horizontalAdvance(text) + 4, h = metrics.height();
    for (double distance : {7.0, 18.0, 32.0, 50.0, 75.0}) {
      const QPointF offsets[8] = {{distance, -h / 2},
                                  {-distance - w, -h / 2},
                                  {-w / 2, -distance - h},
                                  {-w / 2, distance},
                                  {distance, -distance - h},
                                  {distance, distance},
                                  {-distance - w, -distance - h},
                                  {-distance - w, distance}};
      for (const QPointF& offset : offsets) {
        const QRectF box(at + offset, QSizeF(w, h));
        if (!area_.contains(box) || covers(box)) continue;
        draw(at, box, text, distance > 7.0);
        return;
      }
    }
    const QRectF box(at + QPointF(7, -h / 2), QSizeF(w, h));
    draw(at, box, text, false);
  }

 private:
  bool covers(const QRectF& box) const {
    return std::any_of(taken_.begin(), taken_.end(),
                       [&](const QRectF& other) { return other.intersects(box); });
  }

  void draw(const QPointF& at, const QRectF& box, const QString& text, bool leader) {
    if (leader) {
      const QPointF nearest(std::clamp(at.x(), box.left(), box.right()),
                            std::clamp(at.y(), box.top(), box.bottom()));
      painter_.setPen(QPen(QColor(120, 120, 120), 0.8));
      painter_.drawLine(at, nearest);
    }
    // A white ground keeps the text legible over grid lines and the front's line.
    painter_.fillRect(box, QColor(255, 255, 255, 220));
    painter_.setPen(Qt::black);
    painter_.drawText(box, Qt::AlignCenter, text);
    taken_.push_back(box);
  }

  QPainter& painter_;
  QRectF area_;
  std::vector<QRectF> taken_;
};

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

void addTradePlot(OutputFiles& outputs, const std::string& path, const std::string& title,
                  const std::vector<TradePoint>& points) {
  const std::unique_ptr<QGuiApplication> app = offscreenApplication();
  QImage image(kWidth, kHeight, QImage::Format_RGB32);
  image.fill(Qt::white);
  QPainter painter(&image);
  painter.setRenderHint(QPainter::Antialiasing);
  const QFont font("DejaVu Sans", 9);
  QFont small = font;
  small.setPointSizeF(8);
  QFont bold = font;
  bold.setBold(true);
  bold.setPointSize(12);

  // The axes' ranges: time over every point, dB over the finite ones, both a little wider so
  // that no marker sits on the frame.
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
  const double lo = std::log10(tMin) - 0.08, hi = std::max(std::log10(tMax) + 0.08, lo + 1.0);
  const double dbStep = roundStep(std::max(dbMax - dbMin, 5.0), 7);
  const double dbLo = std::floor((dbMin - 0.3 * dbStep) / dbStep) * dbStep,
               dbHi = std::ceil((dbMax + 0.3 * dbStep) / dbStep) * dbStep;
  const auto x = [&](double ms) {
    return kLeft + (std::log10(std::max(ms, 1e-3)) - lo) / (hi - lo) * (kRight - kLeft);
  };
  const auto y = [&](double db) {
    return std::isfinite(db) ? kBottom - (db - dbLo) / (dbHi - dbLo) * (kBottom - kTop)
                             : (kBandTop + kTop - 6) / 2;
  };
  const QRectF frame(QPointF(kLeft, kTop), QPointF(kRight, kBottom));

  // Grid and round ticks: 1, 2 and 5 times a power of ten on the time axis (only the powers
  // of ten labelled when the range spans more than three decades), a round step in dB.
  const bool manyDecades = hi - lo > 3.0;
  painter.setFont(font);
  for (double decade = std::floor(lo); decade <= std::ceil(hi); decade += 1.0)
    for (int m = 1; m < 10; ++m) {
      const double ms = std::pow(10.0, decade) * m;
      const double at = x(ms);
      if (at < kLeft - 0.5 || at > kRight + 0.5) continue;
      const bool labelled = m == 1 || (!manyDecades && (m == 2 || m == 5));
      painter.setPen(QPen(labelled ? QColor(215, 215, 215) : QColor(240, 240, 240), 1));
      painter.drawLine(QPointF(at, kTop), QPointF(at, kBottom));
      if (!labelled) continue;
      painter.setPen(Qt::black);
      painter.drawText(QRectF(at - 40, kBottom + 6, 80, 18), Qt::AlignHCenter | Qt::AlignTop,
                       tickText(ms));
    }
  for (double db = dbLo; db <= dbHi + 1e-9; db += dbStep) {
    painter.setPen(QPen(QColor(215, 215, 215), 1));
    painter.drawLine(QPointF(kLeft, y(db)), QPointF(kRight, y(db)));
    painter.setPen(Qt::black);
    painter.drawText(QRectF(0, y(db) - 9, kLeft - 8, 18), Qt::AlignRight | Qt::AlignVCenter,
                     tickText(db));
  }
  painter.setPen(QPen(Qt::black, 1));
  painter.setBrush(Qt::NoBrush);
  painter.drawRect(frame);
  painter.drawText(QRectF(kLeft, kBottom + 30, kRight - kLeft, 20), Qt::AlignCenter,
                   "time per frame with a rebuild (ms, log scale): further left is faster");
  painter.save();
  painter.translate(22, (kTop + kBottom) / 2);
  painter.rotate(-90);
  painter.drawText(QRectF(-(kBottom - kTop) / 2, -10, kBottom - kTop, 20), Qt::AlignCenter,
                   "PSNR against the exact reference (dB): higher is closer");
  painter.restore();
  // The band of exact pictures (the reference, and any setting that matches it to the last
  // bit): their PSNR is infinite, off any dB scale.
  painter.fillRect(QRectF(QPointF(kLeft, kBandTop), QPointF(kRight, kTop - 6)),
                   QColor(244, 244, 244));
  painter.setPen(QColor(90, 90, 90));
  painter.setFont(small);
  painter.drawText(QRectF(4, kBandTop, kLeft - 10, kTop - 6 - kBandTop),
                   Qt::AlignRight | Qt::AlignVCenter, QString::fromUtf8("exact (\u221e dB)"));
  painter.setFont(bold);
  painter.setPen(Qt::black);
  painter.drawText(QRectF(0, 8, kWidth, 26), Qt::AlignCenter, QString::fromStdString(title));
  painter.setFont(font);
  painter.drawText(QRectF(0, 34, kWidth, 20), Qt::AlignCenter,
                   "Take a setting on the Pareto front (outlined, on the black line): no "
                   "other setting is both faster and closer to the reference.");

  // The front as a staircase: from each of its points the best error reached so far holds
  // until a slower point of the front does better, and from the last on to the frame's edge,
  // so that a front of one point (the tracer, where it wins) still shows as a line.
  std::vector<const TradePoint*> front;
  for (const TradePoint& p : points)
    if (p.pareto) front.push_back(&p);
  std::sort(front.begin(), front.end(),
            [](const TradePoint* a, const TradePoint* b) { return a->timeMs < b->timeMs; });
  if (!front.empty()) {
    QPainterPath stairs;
    stairs.moveTo(x(front[0]->timeMs), y(front[0]->psnrDb));
    for (std::size_t i = 1; i < front.size(); ++i) {
      stairs.lineTo(x(front[i]->timeMs), y(front[i - 1]->psnrDb));
      stairs.lineTo(x(front[i]->timeMs), y(front[i]->psnrDb));
    }
    stairs.lineTo(kRight, y(front.back()->psnrDb));
    painter.setPen(QPen(QColor(0, 0, 0, 170), 2.5));
    painter.setBrush(Qt::NoBrush);
    painter.drawPath(stairs);
  }

  // Points off the front first, small, so that the front's are drawn over them.
  LabelPlacer labels(painter,
                     QRectF(QPointF(kLeft + 2, kBandTop + 2), QPointF(kRight - 2, kBottom - 2)));
  for (const TradePoint& p : points) labels.avoid(QRectF(x(p.timeMs) - 6, y(p.psnrDb) - 6, 12, 12));
  for (const TradePoint& p : points)
    if (!p.pareto && !p.baseline)
      drawMarker(painter, styleOf(p), QPointF(x(p.timeMs), y(p.psnrDb)), 3.5, false);
  for (const TradePoint& p : points)
    if (p.pareto || p.baseline)
      drawMarker(painter, styleOf(p), QPointF(x(p.timeMs), y(p.psnrDb)), 5.5, p.pareto);
  // Labelled: the baselines, the front, and each method's only setting (rays, volumes, the
  // tracer) wherever it falls, so that every method is named on the chart itself.
  painter.setFont(small);
  for (const TradePoint& p : points)
    if (p.baseline)
      labels.place(QPointF(x(p.timeMs), y(p.psnrDb)), QString::fromStdString(p.label));
  for (const TradePoint* p : front)
    labels.place(QPointF(x(p->timeMs), y(p->psnrDb)), QString::fromStdString(p->label));
  for (const TradePoint& p : points)
    if (!p.pareto && !p.baseline && p.method != trade_kind::kMap &&
        p.method != trade_kind::kOpacityMap)
      labels.place(QPointF(x(p.timeMs), y(p.psnrDb)), QString::fromStdString(p.label));

  // The legend: the methods the chart shows, then what the outlines and the line mean.
  painter.setFont(font);
  double legendY = kTop + 4;
  const double legendX = kRight + 22;
  painter.setPen(Qt::black);
  painter.drawText(QPointF(legendX, legendY + 10), "method");
  legendY += 24;
  for (const Style& style : kStyles) {
    const bool shown = std::any_of(points.begin(), points.end(),
                                   [&](const TradePoint& p) { return p.method == style.method; });
    if (!shown) continue;
    drawMarker(painter, style, QPointF(legendX + 8, legendY), 5, false);
    painter.setPen(Qt::black);
    painter.drawText(QPointF(legendX + 22, legendY + 4), style.method);
    legendY += 22;
  }
  legendY += 10;
  drawMarker(painter, kStyles[0], QPointF(legendX + 8, legendY), 5.5, true);
  painter.setPen(Qt::black);
  painter.drawText(QPointF(legendX + 22, legendY + 4), "on the front (labelled)");
  legendY += 22;
  painter.setPen(QPen(QColor(0, 0, 0, 170), 2.5));
  painter.drawLine(QPointF(legendX, legendY), QPointF(legendX + 16, legendY));
  painter.setPen(Qt::black);
  painter.drawText(QPointF(legendX + 22, legendY + 4), "Pareto front");
  legendY += 30;
  painter.setFont(small);
  painter.setPen(QColor(80, 80, 80));
  painter.drawText(QRectF(legendX, legendY, kWidth - legendX - 8, 120), Qt::TextWordWrap,
                   "Small markers: the other settings of the maps' sweeps; trade.csv names "
                   "each.");
  painter.end();

  // QImage shares its pixels: the copy costs nothing.
  outputs.add(path, [path, image](const std::string& file) {
    if (!image.save(QString::fromStdString(file), "PNG"))
      throw std::runtime_error(path + ": error: cannot write the plot");
  });
}

}  // namespace ivshadow
