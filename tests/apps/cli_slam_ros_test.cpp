// tessera play into tessera slam --ros, two processes on Cyclone DDS: the first 400 scans of the
// Intel raw log at 10x real time arrive and are mapped, none dropped (issue 14's live SLAM on
// real data; the whole log's figure is in docs/ros2.md).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "cli_run.hpp"
#include "live_play.hpp"
#include "support/data.hpp"
#include "support/dds_isolation.hpp"

namespace tessera {
namespace {

using support::LivePlay;
using ::testing::HasSubstr;

LivePlay play_into_live_slam(const support::TempDir& dir, const std::string& play_args) {
  return support::play_into_node(dir, "slam --ros", play_args);
}

TEST(CliSlamRos, PlayedScansAreAllMappedByTheLiveNode) {
  const auto log = support::intel_log();
  TESSERA_REQUIRE_DATA(log);
  const support::TempDir dir;
  const LivePlay run = play_into_live_slam(dir, log.string() + " --rate 10 --max-scans 400");
  EXPECT_EQ(run.play.exit_code, 0) << run.play.output;
  EXPECT_THAT(run.play.output, HasSubstr("play: 400 scans published"));
  ASSERT_FALSE(run.report.is_null()) << "no report; slam said: " << run.node_said;
  EXPECT_EQ(run.report["ros"]["scans_received"], 400);
  EXPECT_EQ(run.report["ros"]["scans_added"], 400);
  EXPECT_EQ(run.report["ros"]["scans_dropped_overflow"], 0);
  EXPECT_GE(run.report["ros"]["maps_published"].get<int>(), 1);
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "node" / "map.png"));
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "node" / "trajectory.txt"));
}

// A ROS 2 bag played as topics: every scan the offline reader finds in it is mapped live.
TEST(CliSlamRos, PlayedBagScansAreAllMappedByTheLiveNode) {
  const auto bag = support::data_path("bags/ros2_neato_obstacle_avoider");
  TESSERA_REQUIRE_DATA(bag);
  const support::TempDir dir;
  const LivePlay run = play_into_live_slam(dir, bag.string() + " --scan-topic /scan --rate 10");
  EXPECT_EQ(run.play.exit_code, 0) << run.play.output;
  EXPECT_THAT(run.play.output, HasSubstr("play: 153 scans published"));
  ASSERT_FALSE(run.report.is_null()) << "no report; slam said: " << run.node_said;
  EXPECT_EQ(run.report["ros"]["scans_received"], 153);
  EXPECT_EQ(run.report["ros"]["scans_added"], 153);
}

// A hand-held laser's bag (scans alone), its first 14 s (141 scans): played without odometry,
// mapped by the node from its scans alone (the whole bag as `slam --bag` maps it offline,
// trajectory for trajectory, when this was written: 360 scans, 221 nodes, 85 loop closures).
TEST(CliSlamRos, ABagOfScansAloneIsMappedLiveWithoutOdometry) {
  const auto bag = support::data_path("bags/laser_scan_matcher_demo.bag");
  TESSERA_REQUIRE_DATA(bag);
  const support::TempDir dir;
  const LivePlay run = support::play_into_node(dir, "slam --ros --no-odometry",
                                               bag.string() + " --to-s 14 --rate 10");
  EXPECT_EQ(run.play.exit_code, 0) << run.play.output;
  EXPECT_THAT(run.play.output, HasSubstr("play: 141 scans published"));
  ASSERT_FALSE(run.report.is_null()) << "no report; slam said: " << run.node_said;
  EXPECT_EQ(run.report["options"]["use_odometry"], false);
  EXPECT_EQ(run.report["options"]["base_frame"], "laser");
  EXPECT_EQ(run.report["ros"]["scans_added"], 141);
  EXPECT_EQ(run.report["ros"]["odometry_received"], 0);
  EXPECT_GT(run.report["slam"]["loop_closures"].get<int>(), 0);
}

TEST(CliSlamRos, BadCombinationsAndLogsAreErrors) {
  const auto both = support::run_cli("slam --ros --log x.clf");
  EXPECT_EQ(both.exit_code, 2);
  EXPECT_THAT(both.output, HasSubstr("--ros maps the topics"));
  const auto base = support::run_cli("slam --ros --base-frame base_link");
  EXPECT_EQ(base.exit_code, 2);
  EXPECT_THAT(base.output, HasSubstr("--ros takes --base-frame with --no-odometry"));
  const auto topic_live = support::run_cli("slam --ros --scan-topic /front");
  EXPECT_EQ(topic_live.exit_code, 2);
  EXPECT_THAT(topic_live.output, HasSubstr("--ros reads <ns>/scan and <ns>/odom"));
  const support::TempDir dir;
  std::ofstream(dir.path() / "bad.clf") << "FLASER 3 1.0 oops\n";
  const auto bad = support::run_cli("play " + (dir.path() / "bad.clf").string());
  EXPECT_EQ(bad.exit_code, 3);
  EXPECT_THAT(bad.output, HasSubstr("bad.clf"));
  const auto topic =
      support::run_cli("play " + (dir.path() / "bad.clf").string() + " --scan-topic /scan");
  EXPECT_EQ(topic.exit_code, 2);
  EXPECT_THAT(topic.output, HasSubstr("choose a bag's topics"));
  const std::string intel = support::intel_log().string();
  const auto backwards = support::run_cli("play " + intel + " --from-s 50 --to-s 40");
  EXPECT_EQ(backwards.exit_code, 2);
  EXPECT_THAT(backwards.output, HasSubstr("--from-s 50 must be before --to-s 40"));
  if (std::filesystem::exists(intel)) {
    const auto empty = support::run_cli("play " + intel + " --from-s 5000");
    EXPECT_EQ(empty.exit_code, 3);
    EXPECT_THAT(empty.output, HasSubstr("no scan from 5000 s"));
  }
  const auto nobody =
      support::run_cli("play " + support::intel_log().string() + " --wait-s 0.2 --domain " +
                       std::to_string(support::test_dds_domain()));
  if (std::filesystem::exists(support::intel_log())) {
    EXPECT_EQ(nobody.exit_code, 4);
    EXPECT_THAT(nobody.output, HasSubstr("no subscriber of the scans appeared"));
  }
}

}  // namespace
}  // namespace tessera
