// lot_report: M units of one model, each analysed by `allan` (its output directory: noise.yaml
// and oadev.csv) -> per unit the identified terms and across units a datasheet-style summary in
// the field's units (typical = median, worst = max, spread with its chi-squared interval), the
// lot's typical model, and one plot per axis overlaying the units' Allan curves with that model.
// Writes DIR/lot.csv, lot.yaml, lot.md, lot_model.csv and lot_allan.png
// (scripts/plot_lot.py) as one set. See include/imu_lab/repeatability/lot.h and doc/lot.md.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "imu_lab/common/atomic_file.h"
#include "imu_lab/common/config_error.h"
#include "imu_lab/common/format_number.h"
#include "imu_lab/common/tool_main.h"
#include "imu_lab/common/tool_options.h"
#include "imu_lab/identify/noise_report.h"
#include "imu_lab/io/stability_table.h"
#include "imu_lab/repeatability/lot.h"
#include "imu_lab/ros_io/node/config_paths.h"

namespace {

namespace rep = imu_lab::repeatability;

std::string read_text(const std::string& path, const std::string& what) {
  std::ifstream in(path);
  if (!in) throw imu_lab::InputError("cannot read " + what + " " + path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string base_name(std::string path) {
  while (path.size() > 1 && path.back() == '/') path.pop_back();
  const std::size_t slash = path.rfind('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

// Log-spaced taus over the span of the units' curves, 10 per decade.
std::vector<double> model_taus(const std::vector<std::string>& directories) {
  double smallest = INFINITY, largest = 0.0;
  for (const std::string& directory : directories) {
    const std::string path = directory + "/oadev.csv";
    std::vector<imu_lab::io::ChannelCurve> curves;
    try {
      curves = imu_lab::io::parse_stability_csv(read_text(path, "Allan curves"));
    } catch (const imu_lab::InputError&) {
      throw;
    } catch (const std::exception& error) {
      throw imu_lab::InputError("Allan curves " + path + ": " + error.what());
    }
    for (const auto& curve : curves) {
      for (const auto& point : curve.points) {
        smallest = std::min(smallest, point.tau_s);
        largest = std::max(largest, point.tau_s);
      }
    }
  }
  if (!(largest > smallest)) throw imu_lab::InputError("the units' oadev.csv files hold no curve");
  std::vector<double> taus;
  for (double tau_s = smallest; tau_s <= largest * (1.0 + 1e-9); tau_s *= std::pow(10.0, 0.1)) taus.push_back(tau_s);
  return taus;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Lot of M units of one model: datasheet summary (typical = median, worst = max) and Allan overlay."};
  std::vector<std::string> directories, names;
  std::string out_directory = "lot";
  double confidence = 0.95;
  bool no_plot = false;
  app.add_option("units", directories, "each unit's allan output directory (noise.yaml, oadev.csv)");
  app.add_option("-o,--out", out_directory, "report directory (created)")->capture_default_str();
  app.add_option("--names", names, "the units' names, in order (default: the directories' names)");
  app.add_option("--confidence", confidence, "two-sided confidence of the spreads' chi-squared intervals")
      ->capture_default_str();
  app.add_flag("--no-plot", no_plot, "do not write lot_allan.png");
  if (const auto status = imu_lab::parse_tool_options("lot_report", app, argc, argv)) return *status;

  return imu_lab::run_tool_main("lot_report", [&] {
    if (!(confidence > 0.0 && confidence < 1.0)) {
      throw imu_lab::ConfigError("lot_report", "--confidence", "must be between 0 and 1");
    }
    if (directories.size() < 2) {
      throw imu_lab::ConfigError("lot_report", "units", "give the allan output directories of at least 2 units");
    }
    if (!names.empty() && names.size() != directories.size()) {
      throw imu_lab::ConfigError("lot_report", "--names",
                                 "gives " + std::to_string(names.size()) + " names for " +
                                     std::to_string(directories.size()) + " units; give one per unit, in order");
    }
    if (names.empty()) {
      for (const std::string& directory : directories) names.push_back(base_name(directory));
    }
    for (std::size_t k = 0; k < names.size(); ++k) {
      if (std::count(names.begin(), names.end(), names[k]) > 1) {
        throw imu_lab::ConfigError("lot_report", "--names",
                                   "two units are named " + names[k] + "; name them with --names");
      }
    }
    std::vector<rep::LotUnit> units;
    for (std::size_t k = 0; k < directories.size(); ++k) {
      const std::string path = directories[k] + "/noise.yaml";
      try {
        units.push_back({names[k], imu_lab::identify::read_noise_report_values(read_text(path, "noise report"))});
      } catch (const imu_lab::InputError& error) {
        const std::string message = error.what();
        throw imu_lab::InputError(message.find(path) != std::string::npos ? message : path + ": " + message);
      }
    }
    rep::LotSummary summary;
    try {
      summary = rep::lot_summary(units, confidence);
    } catch (const std::invalid_argument& error) {
      throw imu_lab::InputError(error.what());
    }
    const std::vector<double> taus = model_taus(directories);

    // Tables, page, model and plot are one set: all new, or all as they were.
    imu_lab::OutputSet outputs;
    const std::string staging = outputs.stage_directory(out_directory);
    std::vector<std::string> written = {"lot.csv", "lot.yaml", "lot.md", "lot_model.csv"};
    imu_lab::write_file_atomically(staging + "/lot.csv", rep::lot_csv(summary));
    imu_lab::write_file_atomically(staging + "/lot.yaml", rep::lot_yaml(summary));
    imu_lab::write_file_atomically(staging + "/lot.md", rep::lot_markdown(summary));
    imu_lab::write_file_atomically(staging + "/lot_model.csv", rep::typical_model_csv(units, taus));
    // An earlier run's plot is not of these units: without a new one it goes.
    outputs.remove_at_commit(out_directory + "/lot_allan.png");
    if (!no_plot) {
      std::vector<std::string> arguments = {staging + "/lot_model.csv", staging + "/lot_allan.png"};
      for (std::size_t k = 0; k < directories.size(); ++k) arguments.push_back(names[k] + "=" + directories[k]);
      const std::string problem = imu_lab::ros_io::run_plot_script("plot_lot.py", arguments);
      if (problem.empty()) {
        written.push_back("lot_allan.png");
      } else {
        std::fprintf(stderr, "lot_report: warning: %s, so no plot; the tables are the result\n", problem.c_str());
      }
    }
    outputs.commit();
    std::printf("lot_report: %zu units; typical (median) and worst (max) per term, in the field's units:\n",
                units.size());
    for (const rep::LotTerm& term : summary.terms) {
      std::string line = term.identified.empty() ? "absent in every unit"
                                                 : "typical " + imu_lab::format_number(term.typical, 4) + ", worst " +
                                                       imu_lab::format_number(term.worst, 4) + " (" +
                                                       std::to_string(term.identified.size()) + " of " +
                                                       std::to_string(units.size()) + " units)";
      if (std::isfinite(term.absent_upper_bound_max)) {
        line += (term.identified.empty() ? " (< " : "; absent ones < ") +
                imu_lab::format_number(term.absent_upper_bound_max, 4) + (term.identified.empty() ? ")" : "");
      }
      std::printf("  %-8s %-18s %-24s %s\n", term.channel.c_str(), term.term.c_str(), term.parameter.c_str(),
                  line.c_str());
    }
    for (const std::string& name : written)
      std::printf("lot_report: wrote %s/%s\n", out_directory.c_str(), name.c_str());
    return 0;
  });
}
