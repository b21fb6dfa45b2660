#include "cli/TradePlot.h"

#include "image/OutputFiles.h"

#include <QFont>
#include <QFontMetricsF>
#include <QGuiApplication>
#include <QImage>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <stdexcept>

namespace ivshadow {

void markParetoFront(std::vector<TradePoint>& points) {
  for (TradePoint& p : points) {
    p.pareto = !p.baseline;
    for (const TradePoint& q : points) {
      if (&q == &p || q.baseline) continue;
      const bool noWorse = q.timeMs <= p.timeMs && q.error <= p.error;
      const bool better = q.timeMs < p.timeMs || q.error < p.error;
      if (noWorse && better) {
        p.pareto = false;
        break;
      }
    }
  }
}

void addTradePlot(OutputFiles& outputs, const std::string& path, const std::string& title,
                  const std::vector<TradePoint>& points) {
  // Text needs a QGuiApplication; a command-line run has no display, so it gets Qt's
  // offscreen platform.
  std::unique_ptr<QGuiApplication> app;
  if (QGuiApplication::instance() == nullptr) {
    if (std::getenv("QT_QPA_PLATFORM") == nullptr) setenv("QT_QPA_PLATFORM", "offscreen", 1);
    static int argc = 1;
    static char name[] = "ivshadow";
    static char* argv[] = {name, nullptr};
    app = std::make_unique<QGuiApplication>(argc, argv);
  }
  constexpr int kWidth = 1000, kHeight = 700;
  constexpr int kLeft = 90, kRight = 30, kTop = 50, kBottom = 70;
  QImage image(kWidth, kHeight, QImage::Format_RGB32);
  image.fill(Qt::white);
  QPainter painter(&image);
  painter.setRenderHint(QPainter::Antialiasing);
  QFont font("DejaVu Sans", 10);
  painter.setFont(font);

  double tMin = 1e300, tMax = 0.0, eMax = 0.0;
  for (const TradePoint& p : points) {
    tMin = std::min(tMin, std::max(p.timeMs, 1e-3));
    tMax = std::max(tMax, std::max(p.timeMs, 1e-3));
    eMax = std::max(eMax, p.error);
  }
  if (points.empty()) tMin = tMax = 1.0;
  const double lo = std::floor(std::log10(tMin)),
               hi = std::max(lo + 1.0, std::ceil(std::log10(tMax)));
  eMax = eMax > 0.0 ? eMax * 1.1 : 1.0;
  const double plotW = kWidth - kLeft - kRight, plotH = kHeight - kTop - kBottom;
  const auto x = [&](double ms) {
    return kLeft + (std::log10(std::max(ms, 1e-3)) - lo) / (hi - lo) * plotW;
  };
  const auto y = [&](double error) { return kTop + plotH - error / eMax * plotH; };

  painter.setPen(QPen(QColor(220, 220, 220), 1));
  for (double decade = lo; decade <= hi; decade += 1.0) {
    for (int m = 1; m < 10; ++m) {
      const double ms = std::pow(10.0, decade) * m;
      if (ms > std::pow(10.0, hi)) break;
      painter.drawLine(QPointF(x(ms), kTop), QPointF(x(ms), kTop + plotH));
    }
  }
  for (int i = 0; i <= 5; ++i)
    painter.drawLine(QPointF(kLeft, y(eMax * i / 5)), QPointF(kLeft + plotW, y(eMax * i / 5)));
  painter.setPen(QPen(Qt::black, 1));
  painter.drawRect(QRectF(kLeft, kTop, plotW, plotH));
  for (double decade = lo; decade <= hi; decade += 1.0) {
    const double ms = std::pow(10.0, decade);
    painter.drawText(QRectF(x(ms) - 40, kTop + plotH + 5, 80, 20), Qt::AlignCenter,
                     QString::number(ms) + " ms");
  }
  for (int i = 0; i <= 5; ++i)
    painter.drawText(QRectF(0, y(eMax * i / 5) - 10, kLeft - 8, 20),
                     Qt::AlignRight | Qt::AlignVCenter, QString::number(eMax * i / 5, 'f', 2));
  painter.drawText(QRectF(kLeft, kHeight - 35, plotW, 25), Qt::AlignCenter,
                   "time per setting (ms, log scale)");
  painter.save();
  painter.translate(20, kTop + plotH / 2);
  painter.rotate(-90);
  painter.drawText(QRectF(-plotH / 2, -12, plotH, 24), Qt::AlignCenter,
                   "RMSE against the exact reference (8-bit steps)");
  painter.restore();
  QFont bold = font;
  bold.setBold(true);
  bold.setPointSize(12);
  painter.setFont(bold);
  painter.drawText(QRectF(0, 10, kWidth, 30), Qt::AlignCenter, QString::fromStdString(title));
  painter.setFont(font);

  std::vector<const TradePoint*> front;
  for (const TradePoint& p : points)
    if (p.pareto) front.push_back(&p);
  std::sort(front.begin(), front.end(),
            [](const TradePoint* a, const TradePoint* b) { return a->timeMs < b->timeMs; });
  painter.setPen(QPen(QColor(200, 40, 40), 2));
  for (std::size_t i = 1; i < front.size(); ++i)
    painter.drawLine(QPointF(x(front[i - 1]->timeMs), y(front[i - 1]->error)),
                     QPointF(x(front[i]->timeMs), y(front[i]->error)));
  // A label right of its point, or left of it where it would leave the image; moved down or
  // up a line at a time, away from labels drawn before it, where it would cover one.
  std::vector<QRectF> placed;
  const auto label = [&](const QPointF& at, double dy, const std::string& text) {
    const QString t = QString::fromStdString(text);
    const QFontMetricsF metrics(painter.font());
    const double width = metrics.horizontalAdvance(t), height = metrics.height();
    const double left = at.x() + 8 + width > kWidth - 4 ? at.x() - 8 - width : at.x() + 8;
    QRectF box(left, at.y() + dy - metrics.ascent(), width, height);
    for (int step = 1; step <= 8; ++step) {
      const bool covers = std::any_of(placed.begin(), placed.end(),
                                      [&](const QRectF& other) { return other.intersects(box); });
      if (!covers) break;
      const double shift = (step % 2 == 1 ? 1.0 : -1.0) * ((step + 1) / 2) * height;
      box.moveTop(at.y() + dy - metrics.ascent() + shift);
    }
    placed.push_back(box);
    painter.drawText(QPointF(box.left(), box.top() + metrics.ascent()), t);
  };
  const auto dot = [&](const TradePoint& p, const QPointF& at, double radius) {
    if (!p.diamond) {
      painter.drawEllipse(at, radius, radius);
      return;
    }
    const double r = radius * 1.4;
    const QPointF corners[4] = {at + QPointF(0, -r), at + QPointF(r, 0), at + QPointF(0, r),
                                at + QPointF(-r, 0)};
    painter.drawPolygon(corners, 4);
  };
  for (const TradePoint& p : points) {
    const QPointF at(x(p.timeMs), y(p.error));
    if (p.baseline) {
      painter.setPen(QPen(QColor(30, 90, 200), 2));
      painter.setBrush(Qt::NoBrush);
      painter.drawRect(QRectF(at.x() - 5, at.y() - 5, 10, 10));
      label(at, -6, p.label);
    } else if (p.pareto) {
      painter.setPen(QPen(QColor(200, 40, 40), 1));
      painter.setBrush(QColor(200, 40, 40));
      dot(p, at, 5);
      label(at, -6, p.label);
    } else {
      painter.setPen(QPen(QColor(120, 120, 120), 1));
      painter.setBrush(QColor(160, 160, 160));
      dot(p, at, 3.5);
      // Below the dot: the front's and the baselines' labels sit above theirs.
      if (p.method) label(at, 14, p.label);
    }
  }
  painter.setPen(Qt::black);
  painter.drawText(QRectF(kLeft + 10, kTop + 8, plotW - 20, 20), Qt::AlignRight,
                   "red: Pareto front (labelled)   grey: other settings (methods named)   "
                   "diamonds: opacity maps   blue squares: baselines");
  painter.end();

  // QImage shares its pixels: the copy costs nothing.
  outputs.add(path, [path, image](const std::string& file) {
    if (!image.save(QString::fromStdString(file), "PNG"))
      throw std::runtime_error(path + ": error: cannot write the plot");
  });
}

}  // namespace ivshadow
