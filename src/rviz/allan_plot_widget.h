// Draws a panel::AllanPlot with QPainter: log-log axes with a grid per decade, the confidence band,
// the measured curve, the fitted total and its terms, and a legend.
#pragma once

#include <QWidget>
#include <functional>

#include "imu_lab/panel/allan_plot.h"

namespace imu_lab {
namespace rviz_plugins {

class AllanPlotWidget : public QWidget {
 public:
  explicit AllanPlotWidget(QWidget* parent = nullptr);
  void set_plot(panel::AllanPlot plot);
  QSize sizeHint() const override { return QSize(640, 420); }

  // Called after each paint that drew curves, with the number of measured points and model series.
  std::function<void(std::size_t, std::size_t)> on_painted;

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  panel::AllanPlot plot_;
};

}  // namespace rviz_plugins
}  // namespace imu_lab
