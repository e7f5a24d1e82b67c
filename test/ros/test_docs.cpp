// The documentation against the package: each tool's reference page lists exactly the options the
// tool's --help prints (scripts/tool_reference --check), and every relative link and anchor of
// README.md, CHANGELOG.md and doc/ resolves, with the README kept a quick start
// (scripts/check_doc_links). Both fail with the stale page or broken link named.
#include <gtest/gtest.h>

#include <string>

#include "ros_test_support.h"

namespace {

using imu_lab::test_support::read_file;
using imu_lab::test_support::run_command;
using imu_lab::test_support::scratch_directory;
using imu_lab::test_support::tool_path;

const std::string kRoot = std::string(IMU_LAB_CONFIG_DIR) + "/..";

std::string tool_directory() {
  const std::string path = tool_path("emulate");
  return path.substr(0, path.rfind('/'));
}

TEST(ToolReference, EveryToolsPageListsTheOptionsItsHelpPrints) {
  const auto check = run_command(kRoot + "/scripts/tool_reference --check --bin-dir " + tool_directory());
  EXPECT_EQ(check.exit_code, 0) << check.output;
}

TEST(ToolReference, ACheckOfAPageThatDiffersFromTheToolFailsNamingIt) {
  // A copy of the package's pages with one table row changed: the check must catch it.
  const std::string copy = scratch_directory() + "/package";
  ASSERT_EQ(run_command("mkdir -p " + copy + "/doc/reference && cp -r " + kRoot + "/scripts " + kRoot + "/src " + copy +
                        "/ && cp -r " + kRoot + "/doc/reference/tools " + copy + "/doc/reference/")
                .exit_code,
            0);
  const std::string page = copy + "/doc/reference/tools/emulate.md";
  ASSERT_EQ(run_command("sed -i 's/| random seed |/| seed of the noise |/' " + page).exit_code, 0);
  ASSERT_NE(read_file(page).find("seed of the noise"), std::string::npos);
  const auto check = run_command(copy + "/scripts/tool_reference --check --bin-dir " + tool_directory());
  EXPECT_EQ(check.exit_code, 1) << check.output;
  EXPECT_NE(check.output.find("emulate.md"), std::string::npos) << check.output;
}

TEST(DocLinks, EveryRelativeLinkAndAnchorResolvesAndTheReadmeStaysShort) {
  const auto check = run_command(kRoot + "/scripts/check_doc_links");
  EXPECT_EQ(check.exit_code, 0) << check.output;
}

TEST(DocLinks, ABrokenLinkOrAnchorIsNamedWithItsLine) {
  const std::string copy = scratch_directory() + "/package";
  ASSERT_EQ(run_command("mkdir -p " + copy + " && cp -r " + kRoot + "/scripts " + kRoot + "/doc " + kRoot +
                        "/README.md " + kRoot + "/CHANGELOG.md " + kRoot + "/config " + copy + "/")
                .exit_code,
            0);
  ASSERT_EQ(run_command("echo '[gone](doc/no_such_page.md) [bad anchor](doc/testing.md#no-such-heading)' >> " + copy +
                        "/README.md")
                .exit_code,
            0);
  const auto check = run_command(copy + "/scripts/check_doc_links");
  EXPECT_EQ(check.exit_code, 1) << check.output;
  EXPECT_NE(check.output.find("README.md:"), std::string::npos) << check.output;
  EXPECT_NE(check.output.find("no_such_page.md: no such file"), std::string::npos) << check.output;
  EXPECT_NE(check.output.find("no-such-heading: no heading with that anchor"), std::string::npos) << check.output;
}

}  // namespace
