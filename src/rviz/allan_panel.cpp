#include "allan_panel.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QVBoxLayout>
#include <pluginlib/class_list_macros.hpp>
#include <rviz/visualization_manager.h>

#include "imu_lab/ros_io/msg/panel_messages.h"

namespace imu_lab {
namespace rviz_plugins {
namespace {

QString joined_lines(const std::vector<std::string>& lines) {
  QStringList text;
  for (const std::string& line : lines) text << QString::fromStdString(line);
  return text.join("\n");
}

// Selects `wanted` in `choice` when it is there.
void select_text(QComboBox* choice, const QString& wanted) {
  const int index = choice->findText(wanted);
  if (index >= 0) choice->setCurrentIndex(index);
}

}  // namespace

AllanPanel::AllanPanel(QWidget* parent) : rviz::Panel(parent) {
  sensor_choice_ = new QComboBox;
  axis_choice_ = new QComboBox;
  axis_choice_->addItems({"x", "y", "z"});
  statistic_choice_ = new QComboBox;
  auto* choices = new QHBoxLayout;
  choices->addWidget(new QLabel("triad"));
  choices->addWidget(sensor_choice_);
  choices->addWidget(new QLabel("axis"));
  choices->addWidget(axis_choice_);
  choices->addWidget(new QLabel("statistic"));
  choices->addWidget(statistic_choice_);
  choices->addStretch();

  plot_ = new AllanPlotWidget;
  plot_->on_painted = [this](std::size_t measured_points, std::size_t model_series) {
    log_painted(measured_points, model_series);
  };
  status_text_ = new QLabel;
  record_text_ = new QLabel;
  for (QLabel* label : {status_text_, record_text_}) {
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    label->setAlignment(Qt::AlignLeft | Qt::AlignTop);
  }
  auto* texts = new QHBoxLayout;
  texts->addWidget(status_text_, 1);
  texts->addWidget(record_text_, 1);

  auto* layout = new QVBoxLayout;
  layout->addLayout(choices);
  layout->addWidget(plot_, 1);
  layout->addLayout(texts);
  setLayout(layout);

  connect(sensor_choice_, SIGNAL(activated(int)), this, SLOT(selection_changed()));
  connect(axis_choice_, SIGNAL(activated(int)), this, SLOT(selection_changed()));
  connect(statistic_choice_, SIGNAL(activated(int)), this, SLOT(selection_changed()));
}

void AllanPanel::onInitialize() {
  // Callbacks on rviz's GUI thread: they touch the widgets.
  node_.setCallbackQueue(vis_manager_->getUpdateQueue());
  gyro_subscriber_ = node_.subscribe("allan/gyro", 4, &AllanPanel::on_curves, this);
  accel_subscriber_ = node_.subscribe("allan/accel", 4, &AllanPanel::on_curves, this);
  noise_subscriber_ = node_.subscribe("allan/noise", 1, &AllanPanel::on_noise, this);
  refresh();
}

void AllanPanel::on_curves(const imu_lab::AllanDeviation::ConstPtr& message) {
  model_.add_curves(ros_io::to_stability_curves(*message));
  update_choices();
  refresh();
}

void AllanPanel::on_noise(const imu_lab::NoiseParameters::ConstPtr& message) {
  model_.set_noise_report(ros_io::to_noise_report(*message));
  refresh();
}

void AllanPanel::update_choices() {
  for (const std::string& sensor : model_.sensors()) {
    const QString name = QString::fromStdString(sensor);
    if (sensor_choice_->findText(name) < 0) {
      sensor_choice_->addItem(name);
      if (name == wanted_sensor_) select_text(sensor_choice_, name);
    }
  }
  for (const std::string& statistic : model_.statistics(sensor_choice_->currentText().toStdString())) {
    const QString name = QString::fromStdString(statistic);
    if (statistic_choice_->findText(name) < 0) {
      statistic_choice_->addItem(name);
      if (name == wanted_statistic_) select_text(statistic_choice_, name);
    }
  }
}

void AllanPanel::selection_changed() {
  wanted_sensor_ = sensor_choice_->currentText();
  wanted_statistic_ = statistic_choice_->currentText();
  update_choices();
  refresh();
  Q_EMIT configChanged();
}

void AllanPanel::refresh() {
  const panel::AllanPlot plot =
      model_.plot(sensor_choice_->currentText().toStdString(), statistic_choice_->currentText().toStdString(),
                  axis_choice_->currentIndex());
  status_text_->setText(joined_lines(plot.status_lines));
  record_text_->setText(joined_lines(plot.record_length_lines));
  plot_->set_plot(plot);
}

// One line on rviz's log for each new kind of picture drawn, with where it is on the screen: the
// rviz test waits for it before taking its screenshot, and crops the panel from it.
void AllanPanel::log_painted(std::size_t measured_points, std::size_t model_series) {
  const std::string what =
      sensor_choice_->currentText().toStdString() + " " + axis_choice_->currentText().toStdString() + " " +
      statistic_choice_->currentText().toStdString() + (model_series > 0 ? " with the fitted model" : "");
  if (what == last_logged_) return;
  last_logged_ = what;
  const QPoint origin = plot_->mapToGlobal(QPoint(0, 0));
  ROS_INFO("imu_lab allan panel: painted %s (%zu points, %zu model curves) at screen %d %d size %d %d", what.c_str(),
           measured_points, model_series, origin.x(), origin.y(), plot_->width(), plot_->height());
}

void AllanPanel::load(const rviz::Config& config) {
  rviz::Panel::load(config);
  QString text;
  if (config.mapGetString("Triad", &text)) wanted_sensor_ = text;
  if (config.mapGetString("Statistic", &text)) wanted_statistic_ = text;
  if (config.mapGetString("Axis", &text)) select_text(axis_choice_, text);
  update_choices();
}

void AllanPanel::save(rviz::Config config) const {
  rviz::Panel::save(config);
  config.mapSetValue("Triad", wanted_sensor_);
  config.mapSetValue("Axis", axis_choice_->currentText());
  config.mapSetValue("Statistic", wanted_statistic_);
}

}  // namespace rviz_plugins
}  // namespace imu_lab

PLUGINLIB_EXPORT_CLASS(imu_lab::rviz_plugins::AllanPanel, rviz::Panel)
