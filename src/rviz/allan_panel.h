// rviz panel "imu_lab/AllanPanel": the live Allan deviation of allan_monitor (allan/gyro,
// allan/accel, allan/noise) for a chosen triad, axis and statistic. The logic is
// panel::AllanPanelModel; this class subscribes, converts and lays out the widgets.
#pragma once

#ifndef Q_MOC_RUN
#include <imu_lab/AllanDeviation.h>
#include <imu_lab/NoiseParameters.h>
#include <ros/ros.h>
#include <rviz/panel.h>

#include "allan_plot_widget.h"
#include "imu_lab/panel/allan_plot.h"
#endif

class QComboBox;
class QLabel;

namespace imu_lab {
namespace rviz_plugins {

class AllanPanel : public rviz::Panel {
  Q_OBJECT
 public:
  explicit AllanPanel(QWidget* parent = nullptr);
  void onInitialize() override;
  void load(const rviz::Config& config) override;
  void save(rviz::Config config) const override;

 private Q_SLOTS:
  void refresh();
  void selection_changed();

 private:
  void on_curves(const imu_lab::AllanDeviation::ConstPtr& message);
  void on_noise(const imu_lab::NoiseParameters::ConstPtr& message);
  // Adds the sensors and statistics seen so far to the choices, keeping the current selection.
  void update_choices();
  void log_painted(std::size_t measured_points, std::size_t model_series);

  ros::NodeHandle node_;
  ros::Subscriber gyro_subscriber_;
  ros::Subscriber accel_subscriber_;
  ros::Subscriber noise_subscriber_;
  panel::AllanPanelModel model_;
  QComboBox* sensor_choice_;
  QComboBox* axis_choice_;
  QComboBox* statistic_choice_;
  AllanPlotWidget* plot_;
  QLabel* status_text_;
  QLabel* record_text_;
  // Selections from the config, applied once the choice appears.
  QString wanted_sensor_ = "gyro";
  QString wanted_statistic_ = "oadev";
  std::string last_logged_;
};

}  // namespace rviz_plugins
}  // namespace imu_lab
