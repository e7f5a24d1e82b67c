// scripts/plot_allan.py as the allan tool runs it, on a report made by hand: a term that never
// carries 10 % of the AVAR is not drawn, the numbered terms of one family share one look that no
// other family has, and the point at the longest tau that the fitted total misses elevenfold is
// circled and named with the factor and its band. The plot is written as SVG (the extension
// picks the format) so that its text and the curves' ids can be read back.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <regex>
#include <set>

#include "ros_test_support.h"

namespace {

using imu_lab::test_support::read_file;
using imu_lab::test_support::run_command;
using imu_lab::test_support::scratch_directory;

const std::string kScripts = std::string(IMU_LAB_CONFIG_DIR) + "/../scripts/";

// accel_x over 0.01-2000 s: white noise, two sinusoids, a Markov hump, a term at 5 % of the AVAR
// everywhere, and at 2000 s a measured point 11x below the total, inside its wide band.
void write_report(const std::string& directory) {
  std::ofstream curves(directory + "/oadev.csv");
  std::ofstream partial(directory + "/noise_partial_accel_x.csv");
  curves << "tau_s,m,accel_x_dev_m_s2,accel_x_lo_m_s2,accel_x_hi_m_s2\n";
  partial << "tau_s,measured_dev_m_s2,fit_total_dev_m_s2,white_rate_dev_m_s2,sinusoid_1_dev_m_s2,"
             "sinusoid_2_dev_m_s2,markov_1_dev_m_s2,small_dev_m_s2,band95_low_m_s2,band95_high_m_s2\n";
  const double taus[] = {0.01, 0.1, 1.0, 10.0, 100.0, 1000.0, 2000.0};
  for (const double tau : taus) {
    const double white = 0.03 * std::sqrt(0.01 / tau);
    const double line_1 = tau < 5.0 ? 0.8 * white : 0.0;
    const double line_2 = tau < 0.5 ? 0.9 * white : 0.0;
    const double markov = tau > 5.0 ? 2.0 * white : 0.0;
    const double main = std::sqrt(white * white + line_1 * line_1 + line_2 * line_2 + markov * markov);
    const double small = std::sqrt(0.05 / 0.95) * main;  // 5 % of the total's AVAR
    const double total = std::sqrt(main * main + small * small);
    const double measured = tau == 2000.0 ? total / 11.0 : total;
    const double low = tau == 2000.0 ? measured / 4.0 : 0.9 * measured;
    const double high = tau == 2000.0 ? measured * 30.0 : 1.1 * measured;
    curves << tau << "," << static_cast<long long>(tau * 100) << "," << measured << "," << 0.95 * measured << ","
           << 1.05 * measured << "\n";
    partial << tau << "," << measured << "," << total << "," << white << "," << line_1 << "," << line_2 << "," << markov
            << "," << small << "," << low << "," << high << "\n";
  }
}

// The value of one attribute of every <g> element whose id starts with `prefix`, by id.
std::map<std::string, std::string> group_styles(const std::string& svg, const std::string& prefix) {
  std::map<std::string, std::string> styles;
  const std::regex group("<g id=\"(" + prefix + "[^\"]*)\">\\s*<path[^>]*style=\"([^\"]*)\"");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), group); it != std::sregex_iterator(); ++it) {
    styles[(*it)[1]] = (*it)[2];
  }
  return styles;
}

TEST(PlotAllan, PartialCurvesOnePerFamilyLookAndTheFarPointNamed) {
  const std::string directory = scratch_directory();
  write_report(directory);
  const std::string svg_path = directory + "/allan.svg";
  const auto run = run_command("/usr/bin/python3 " + kScripts + "plot_allan.py " + directory + " --out " + svg_path);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_EQ(run.output, "") << "the caller names the files it wrote";
  const std::string svg = read_file(svg_path);

  const auto partials = group_styles(svg, "partial:accel_x:");
  EXPECT_EQ(partials.count("partial:accel_x:small"), 0u) << "5 % of the AVAR is drawn";
  for (const char* term : {"white_rate", "sinusoid_1", "sinusoid_2", "markov_1"}) {
    EXPECT_EQ(partials.count(std::string("partial:accel_x:") + term), 1u) << term;
  }
  ASSERT_EQ(partials.size(), 4u);
  // One family, one look; another family, another (the dash pattern is in the style).
  EXPECT_EQ(partials.at("partial:accel_x:sinusoid_1"), partials.at("partial:accel_x:sinusoid_2"));
  EXPECT_NE(partials.at("partial:accel_x:white_rate"), partials.at("partial:accel_x:sinusoid_1"));
  // The markers tell Markov from sinusoid (both thin solid lines).
  const std::regex marker_ref("<g id=\"partial:accel_x:(markov_1|sinusoid_1)\">[\\s\\S]*?xlink:href=\"#([^\"]+)\"");
  std::set<std::string> markers;
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), marker_ref); it != std::sregex_iterator(); ++it) {
    markers.insert((*it)[2]);
  }
  EXPECT_EQ(markers.size(), 2u) << "each marked family has its own marker";

  EXPECT_NE(svg.find("id=\"miss:accel_x\""), std::string::npos) << "the far point is circled";
  EXPECT_NE(svg.find("accel_x: fit 11x above this point at 2000 s,"), std::string::npos);
  EXPECT_NE(svg.find("inside its 95 % band (few degrees of freedom)"), std::string::npos);
  EXPECT_NE(svg.find("partial curves (where &gt;= 10 % of the AVAR)"), std::string::npos);
}

}  // namespace
