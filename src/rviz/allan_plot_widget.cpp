#include "allan_plot_widget.h"

#include <QFontMetrics>
#include <QPainter>
#include <QPainterPath>
#include <QPolygonF>
#include <cmath>

namespace imu_lab {
namespace rviz_plugins {
namespace {

// Colours that stay apart for readers with a colour-vision deficiency (Okabe and Ito, "Color
// Universal Design", 2008), one per term in report order.
const QColor kTermColours[] = {QColor(0, 114, 178), QColor(213, 94, 0),   QColor(0, 158, 115),  QColor(204, 121, 167),
                               QColor(230, 159, 0), QColor(86, 180, 233), QColor(120, 120, 120)};
const QColor kMeasuredColour(20, 20, 20);
const QColor kBandColour(150, 150, 150, 90);
const QColor kTotalColour(200, 0, 0);

QString decade_label(int exponent) { return QString("1e%1").arg(exponent); }

}  // namespace

AllanPlotWidget::AllanPlotWidget(QWidget* parent) : QWidget(parent) {
  setMinimumSize(360, 260);
  setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
}

void AllanPlotWidget::set_plot(panel::AllanPlot plot) {
  plot_ = std::move(plot);
  update();
}

void AllanPlotWidget::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  painter.setRenderHint(QPainter::Antialiasing);
  painter.fillRect(rect(), Qt::white);
  const QFontMetrics metrics(font());
  if (plot_.empty()) {
    painter.setPen(Qt::darkGray);
    painter.drawText(rect(), Qt::AlignCenter, "waiting for allan/gyro and allan/accel (allan_monitor)");
    return;
  }

  const int left = metrics.horizontalAdvance("1e-10") + 12;
  const int top = metrics.height() + 8;
  const int bottom = metrics.height() * 2 + 10;
  const QRectF area(left, top, std::max(10, width() - left - 12), std::max(10, height() - top - bottom));
  const double tau_low = plot_.tau_decades.low;
  const double tau_span = plot_.tau_decades.high - tau_low;
  const double dev_low = plot_.deviation_decades.low;
  const double dev_span = plot_.deviation_decades.high - dev_low;
  const auto to_screen = [&](double log10_tau, double log10_deviation) {
    return QPointF(area.left() + (log10_tau - tau_low) / tau_span * area.width(),
                   area.bottom() - (log10_deviation - dev_low) / dev_span * area.height());
  };

  // Grid: a line per decade, fainter ones at 2..9 of each decade.
  painter.setPen(QPen(QColor(235, 235, 235), 1));
  for (int decade = plot_.tau_decades.low; decade < plot_.tau_decades.high; ++decade) {
    for (int step = 2; step < 10; ++step) {
      const double x = to_screen(decade + std::log10(step), dev_low).x();
      painter.drawLine(QPointF(x, area.top()), QPointF(x, area.bottom()));
    }
  }
  for (int decade = plot_.deviation_decades.low; decade < plot_.deviation_decades.high; ++decade) {
    for (int step = 2; step < 10; ++step) {
      const double y = to_screen(tau_low, decade + std::log10(step)).y();
      painter.drawLine(QPointF(area.left(), y), QPointF(area.right(), y));
    }
  }
  painter.setPen(QPen(QColor(190, 190, 190), 1));
  for (int decade = plot_.tau_decades.low; decade <= plot_.tau_decades.high; ++decade) {
    const double x = to_screen(decade, dev_low).x();
    painter.drawLine(QPointF(x, area.top()), QPointF(x, area.bottom()));
    painter.setPen(Qt::black);
    painter.drawText(QRectF(x - 30, area.bottom() + 2, 60, metrics.height()), Qt::AlignHCenter, decade_label(decade));
    painter.setPen(QPen(QColor(190, 190, 190), 1));
  }
  for (int decade = plot_.deviation_decades.low; decade <= plot_.deviation_decades.high; ++decade) {
    const double y = to_screen(tau_low, decade).y();
    painter.drawLine(QPointF(area.left(), y), QPointF(area.right(), y));
    painter.setPen(Qt::black);
    painter.drawText(QRectF(0, y - metrics.height() / 2.0, left - 6, metrics.height()),
                     Qt::AlignRight | Qt::AlignVCenter, decade_label(decade));
    painter.setPen(QPen(QColor(190, 190, 190), 1));
  }
  painter.setPen(Qt::black);
  painter.drawRect(area);
  painter.drawText(QRectF(area.left(), area.bottom() + metrics.height() + 4, area.width(), metrics.height()),
                   Qt::AlignHCenter, "tau (s)");
  painter.drawText(QRectF(area.left(), 2, area.width(), metrics.height()), Qt::AlignHCenter,
                   QString::fromStdString(plot_.title));

  painter.save();
  painter.setClipRect(area);
  // The band: upper bounds forwards, lower bounds back.
  if (plot_.band.size() >= 2) {
    QPolygonF band;
    for (const auto& point : plot_.band) band << to_screen(point.log10_tau, point.log10_upper);
    for (auto point = plot_.band.rbegin(); point != plot_.band.rend(); ++point) {
      band << to_screen(point->log10_tau, point->log10_lower);
    }
    painter.setPen(Qt::NoPen);
    painter.setBrush(kBandColour);
    painter.drawPolygon(band);
    painter.setBrush(Qt::NoBrush);
  }
  const auto polyline = [&](const panel::PlotSeries& series) {
    QPolygonF line;
    for (const auto& point : series.points) line << to_screen(point.log10_tau, point.log10_deviation);
    painter.drawPolyline(line);
  };
  // Terms under the data, the measured line, the fitted total over it (a good fit runs along the
  // data), the measured points on top.
  std::vector<std::pair<QPen, QString>> legend;
  for (std::size_t i = 1; i < plot_.model.size(); ++i) {
    const panel::PlotSeries& series = plot_.model[i];
    const QPen pen(kTermColours[(i - 1) % (sizeof kTermColours / sizeof kTermColours[0])], 1.5,
                   series.constrained ? Qt::DashLine : Qt::DotLine);
    painter.setPen(pen);
    polyline(series);
    legend.emplace_back(pen,
                        QString::fromStdString(series.constrained ? series.label : series.label + " (unconstrained)"));
  }
  const QPen measured_pen(kMeasuredColour, 1.2);
  painter.setPen(measured_pen);
  polyline(plot_.measured);
  if (!plot_.model.empty()) {
    const QPen total_pen(kTotalColour, 2.0);
    painter.setPen(total_pen);
    polyline(plot_.model.front());
    legend.insert(legend.begin(), {total_pen, QString::fromStdString(plot_.model.front().label)});
  }
  painter.setPen(measured_pen);
  painter.setBrush(kMeasuredColour);
  for (const auto& point : plot_.measured.points) {
    painter.drawEllipse(to_screen(point.log10_tau, point.log10_deviation), 3.0, 3.0);
  }
  painter.setBrush(Qt::NoBrush);
  painter.restore();
  legend.insert(legend.begin(), {measured_pen, QString::fromStdString(plot_.measured.label) + " (band shaded)"});

  // Legend in the upper right corner, on white so that it stays readable over the curves.
  int legend_width = 0;
  for (const auto& entry : legend) legend_width = std::max(legend_width, metrics.horizontalAdvance(entry.second));
  legend_width += 40;
  const int line_height = metrics.height() + 2;
  const QRectF box(area.right() - legend_width - 6, area.top() + 6, legend_width,
                   line_height * static_cast<int>(legend.size()) + 6);
  painter.setPen(QColor(190, 190, 190));
  painter.setBrush(QColor(255, 255, 255, 230));
  painter.drawRect(box);
  painter.setBrush(Qt::NoBrush);
  for (std::size_t i = 0; i < legend.size(); ++i) {
    const double y = box.top() + 3 + line_height * (i + 0.5);
    painter.setPen(legend[i].first);
    painter.drawLine(QPointF(box.left() + 6, y), QPointF(box.left() + 30, y));
    painter.setPen(Qt::black);
    painter.drawText(QRectF(box.left() + 34, y - line_height / 2.0, legend_width - 36, line_height),
                     Qt::AlignLeft | Qt::AlignVCenter, legend[i].second);
  }
  if (on_painted) on_painted(plot_.measured.points.size(), plot_.model.size());
}

}  // namespace rviz_plugins
}  // namespace imu_lab
