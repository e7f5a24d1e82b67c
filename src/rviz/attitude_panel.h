// rviz panel "imu_lab/AttitudePanel": roll, pitch and yaw of the navigator's solution
// (nav/odometry) with the 1-sigma its alignment predicted (nav/alignment), and the nodes' input
// health (/diagnostics). The logic is panel::AttitudePanelModel; this class subscribes, converts
// and paints its strings.
#pragma once

#ifndef Q_MOC_RUN
#include <diagnostic_msgs/DiagnosticArray.h>
#include <imu_lab/Alignment.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <rviz/panel.h>

#include <QElapsedTimer>
#include <functional>

#include "imu_lab/panel/attitude_view.h"
#endif

class QTimer;

namespace imu_lab {
namespace rviz_plugins {

// Paints a panel::AttitudeView: the three angle rows as a table, the solution line, and the health
// lines coloured by level.
class AttitudeViewWidget : public QWidget {
 public:
  explicit AttitudeViewWidget(QWidget* parent = nullptr);
  void set_view(panel::AttitudeView view);
  QSize sizeHint() const override { return QSize(420, 260); }

  std::function<void()> on_painted;

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  panel::AttitudeView view_;
};

class AttitudePanel : public rviz::Panel {
  Q_OBJECT
 public:
  explicit AttitudePanel(QWidget* parent = nullptr);
  void onInitialize() override;

 private Q_SLOTS:
  void refresh();

 private:
  void on_odometry(const nav_msgs::Odometry::ConstPtr& message);
  void on_alignment(const imu_lab::Alignment::ConstPtr& message);
  void on_diagnostics(const diagnostic_msgs::DiagnosticArray::ConstPtr& message);
  double now_s() const { return clock_.elapsed() * 1e-3; }
  void log_painted();

  ros::NodeHandle node_;
  ros::Subscriber odometry_subscriber_;
  ros::Subscriber alignment_subscriber_;
  ros::Subscriber diagnostics_subscriber_;
  // The panel's own monotonic clock for staleness: a bag replayed with sim time says nothing about
  // whether messages still arrive.
  QElapsedTimer clock_;
  QTimer* stale_timer_;
  panel::AttitudePanelModel model_;
  AttitudeViewWidget* view_widget_;
  std::string last_logged_;
};

}  // namespace rviz_plugins
}  // namespace imu_lab
