#include "attitude_panel.h"

#include <QPainter>
#include <QTimer>
#include <QVBoxLayout>
#include <pluginlib/class_list_macros.hpp>
#include <rviz/visualization_manager.h>

#include "imu_lab/ros_io/msg/panel_messages.h"

namespace imu_lab {
namespace rviz_plugins {
namespace {

// Health lines by diagnostic level: OK, WARN, ERROR, STALE.
QColor level_colour(int level) {
  switch (level) {
    case 0: return QColor(0, 130, 0);
    case 1: return QColor(200, 120, 0);
    case 2: return QColor(200, 0, 0);
    default: return QColor(120, 120, 120);
  }
}

}  // namespace

AttitudeViewWidget::AttitudeViewWidget(QWidget* parent) : QWidget(parent) { setMinimumSize(320, 200); }

void AttitudeViewWidget::set_view(panel::AttitudeView view) {
  view_ = std::move(view);
  update();
}

void AttitudeViewWidget::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  painter.fillRect(rect(), Qt::white);
  painter.setPen(Qt::black);
  const QFontMetrics metrics(painter.font());
  const int line = metrics.height() + 2;
  const int margin = 8;
  int y = margin + metrics.ascent();
  const int value_x = margin + metrics.horizontalAdvance("pitch") + 16;
  const int sigma_x = value_x + metrics.horizontalAdvance("-180.000 deg") + 16;
  QFont bold = painter.font();
  bold.setBold(true);
  painter.setFont(bold);
  painter.drawText(margin, y, "angle");
  painter.drawText(value_x, y, "value");
  painter.drawText(sigma_x, y, "alignment 1-sigma");
  painter.setFont(QFont());
  for (const panel::AttitudeRow& row : view_.rows) {
    y += line;
    painter.drawText(margin, y, QString::fromStdString(row.angle));
    painter.drawText(value_x, y, QString::fromStdString(row.value));
    painter.drawText(sigma_x, y, QString::fromStdString(row.sigma));
  }
  y += line;
  painter.drawText(QRect(margin, y - metrics.ascent(), width() - 2 * margin, 2 * line), Qt::TextWordWrap,
                   QString::fromStdString(view_.solution_line));
  y += 2 * line + line / 2;
  painter.setFont(bold);
  painter.setPen(view_.worst_health_level < 0 ? QColor(Qt::black) : level_colour(view_.worst_health_level));
  painter.drawText(margin, y, QString::fromStdString(view_.health_summary));
  painter.setFont(QFont());
  for (std::size_t i = 0; i < view_.health_lines.size() && y < height(); ++i) {
    y += line;
    const panel::HealthLine& health = view_.health_lines[i];
    painter.setPen(level_colour(health.level));
    painter.drawText(margin, y,
                     metrics.elidedText(QString::fromStdString(health.text), Qt::ElideRight, width() - 2 * margin));
  }
  if (on_painted) on_painted();
}

AttitudePanel::AttitudePanel(QWidget* parent) : rviz::Panel(parent) {
  view_widget_ = new AttitudeViewWidget;
  view_widget_->on_painted = [this] { log_painted(); };
  auto* layout = new QVBoxLayout;
  layout->addWidget(view_widget_, 1);
  setLayout(layout);
  clock_.start();
  // Staleness shows without new messages.
  stale_timer_ = new QTimer(this);
  connect(stale_timer_, SIGNAL(timeout()), this, SLOT(refresh()));
  stale_timer_->start(1000);
}

void AttitudePanel::onInitialize() {
  // Callbacks on rviz's GUI thread: they touch the widgets.
  node_.setCallbackQueue(vis_manager_->getUpdateQueue());
  odometry_subscriber_ = node_.subscribe("nav/odometry", 10, &AttitudePanel::on_odometry, this);
  alignment_subscriber_ = node_.subscribe("nav/alignment", 1, &AttitudePanel::on_alignment, this);
  diagnostics_subscriber_ = node_.subscribe("/diagnostics", 20, &AttitudePanel::on_diagnostics, this);
  refresh();
}

void AttitudePanel::on_odometry(const nav_msgs::Odometry::ConstPtr& message) {
  model_.set_attitude(ros_io::to_attitude_sample(*message), now_s());
  refresh();
}

void AttitudePanel::on_alignment(const imu_lab::Alignment::ConstPtr& message) {
  model_.set_alignment(ros_io::to_alignment_summary(*message));
  refresh();
}

void AttitudePanel::on_diagnostics(const diagnostic_msgs::DiagnosticArray::ConstPtr& message) {
  for (const auto& status : message->status) model_.set_health(ros_io::to_health_status(status), now_s());
  refresh();
}

void AttitudePanel::refresh() { view_widget_->set_view(model_.view(now_s())); }

// One line on rviz's log for each new kind of picture, with where it is on the screen: the rviz
// test waits for it before its screenshot and crops the panel from it.
void AttitudePanel::log_painted() {
  const panel::AttitudeView view = model_.view(now_s());
  const std::string what = std::string(view.have_attitude ? "the attitude" : "no attitude") +
                           (view.have_alignment ? " with the alignment's sigmas" : "") + " and " +
                           std::to_string(view.health_lines.size()) + " health statuses";
  if (what == last_logged_) return;
  last_logged_ = what;
  const QPoint origin = view_widget_->mapToGlobal(QPoint(0, 0));
  ROS_INFO("imu_lab attitude panel: painted %s at screen %d %d size %d %d", what.c_str(), origin.x(), origin.y(),
           view_widget_->width(), view_widget_->height());
}

}  // namespace rviz_plugins
}  // namespace imu_lab

PLUGINLIB_EXPORT_CLASS(imu_lab::rviz_plugins::AttitudePanel, rviz::Panel)
