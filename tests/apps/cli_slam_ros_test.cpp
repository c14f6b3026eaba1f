// tessera play into tessera slam --ros, two processes on Cyclone DDS: the first 400 scans of the
// Intel raw log at 10x real time arrive and are mapped, none dropped (issue 14's live SLAM on
// real data; the whole log's figure is in docs/ros2.md).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "cli_run.hpp"
#include "support/data.hpp"
#include "support/dds_isolation.hpp"
#include "support/temp_dir.hpp"

namespace tessera {
namespace {

using ::testing::HasSubstr;

TEST(CliSlamRos, PlayedScansAreAllMappedByTheLiveNode) {
  const auto log = support::data_path("laser/intel/intel-raw-first5505-sot.clf");
  TESSERA_REQUIRE_DATA(log);
  const support::TempDir dir;
  const std::string domain = std::to_string(support::test_dds_domain());
  const std::string out = (dir.path() / "slam").string();
  // The SLAM node in the background finishes 3 s after the last scan (at most 300 s: if the
  // player fails, no scan comes and nothing else would stop it).
  const std::string slam_cmd =
      "timeout 300 " + std::string(TESSERA_CLI) + " slam --ros --quiet --domain " + domain +
      " --idle-exit-s 3 --out " + out + " > " + (dir.path() / "slam.txt").string() + " 2>&1";
  std::thread slam([&] { std::system(slam_cmd.c_str()); });
  const auto play = support::run_cli("play " + log.string() + " --rate 10 --max-scans 400 " +
                                     "--domain " + domain + " --wait-s 60");
  slam.join();
  EXPECT_EQ(play.exit_code, 0) << play.output;
  EXPECT_THAT(play.output, HasSubstr("play: 400 scans published"));
  std::ifstream in(dir.path() / "slam" / "report.json");
  ASSERT_TRUE(in) << "no report; slam said: " << std::ifstream(dir.path() / "slam.txt").rdbuf();
  const nlohmann::json report = nlohmann::json::parse(in);
  EXPECT_EQ(report["ros"]["scans_received"], 400);
  EXPECT_EQ(report["ros"]["scans_added"], 400);
  EXPECT_EQ(report["ros"]["scans_dropped_overflow"], 0);
  EXPECT_GE(report["ros"]["maps_published"].get<int>(), 1);
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "slam" / "map.png"));
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "slam" / "trajectory.txt"));
}

// A ROS 2 bag played as topics: every scan the offline reader finds in it is mapped live.
TEST(CliSlamRos, PlayedBagScansAreAllMappedByTheLiveNode) {
  const auto bag = support::data_path("bags/ros2_neato_obstacle_avoider");
  TESSERA_REQUIRE_DATA(bag);
  const support::TempDir dir;
  const std::string domain = std::to_string(support::test_dds_domain());
  const std::string out = (dir.path() / "slam").string();
  const std::string slam_cmd =
      "timeout 300 " + std::string(TESSERA_CLI) + " slam --ros --quiet --domain " + domain +
      " --idle-exit-s 3 --out " + out + " > " + (dir.path() / "slam.txt").string() + " 2>&1";
  std::thread slam([&] { std::system(slam_cmd.c_str()); });
  const auto play = support::run_cli(
      "play " + bag.string() + " --scan-topic /scan --rate 10 --domain " + domain + " --wait-s 60");
  slam.join();
  EXPECT_EQ(play.exit_code, 0) << play.output;
  EXPECT_THAT(play.output, HasSubstr("play: 153 scans published"));
  std::ifstream in(dir.path() / "slam" / "report.json");
  ASSERT_TRUE(in) << "no report; slam said: " << std::ifstream(dir.path() / "slam.txt").rdbuf();
  const nlohmann::json report = nlohmann::json::parse(in);
  EXPECT_EQ(report["ros"]["scans_received"], 153);
  EXPECT_EQ(report["ros"]["scans_added"], 153);
}

TEST(CliSlamRos, BadCombinationsAndLogsAreErrors) {
  const auto both = support::run_cli("slam --ros --log x.clf");
  EXPECT_EQ(both.exit_code, 2);
  EXPECT_THAT(both.output, HasSubstr("--ros maps the topics"));
  const support::TempDir dir;
  std::ofstream(dir.path() / "bad.clf") << "FLASER 3 1.0 oops\n";
  const auto bad = support::run_cli("play " + (dir.path() / "bad.clf").string());
  EXPECT_EQ(bad.exit_code, 3);
  EXPECT_THAT(bad.output, HasSubstr("bad.clf"));
  const auto topic =
      support::run_cli("play " + (dir.path() / "bad.clf").string() + " --scan-topic /scan");
  EXPECT_EQ(topic.exit_code, 2);
  EXPECT_THAT(topic.output, HasSubstr("choose a bag's topics"));
  const auto nobody = support::run_cli(
      "play " + support::data_path("laser/intel/intel-raw-first5505-sot.clf").string() +
      " --wait-s 0.2 --domain " + std::to_string(support::test_dds_domain()));
  if (std::filesystem::exists(support::data_path("laser/intel/intel-raw-first5505-sot.clf"))) {
    EXPECT_EQ(nobody.exit_code, 4);
    EXPECT_THAT(nobody.output, HasSubstr("no subscriber of the scans appeared"));
  }
}

}  // namespace
}  // namespace tessera
