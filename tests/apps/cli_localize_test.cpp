// tessera localize end to end (issue 16): a session of the first two minutes of the real Intel
// log, and the robot found in it again with no initial pose half a minute in, from the log and
// from topics played into the live node; bad input (a session of another laser, a damaged
// session, a window without scans) is one line, exit 2 or 3, and nothing written.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_run.hpp"
#include "live_play.hpp"
#include "support/data.hpp"
#include "tessera/eval/relation_metric.hpp"
#include "tessera/io/tum_trajectory.hpp"

namespace tessera {
namespace {

using support::intel_log;
using support::read_bytes;
using support::run_cli;
using support::TempDir;
using support::write_bytes;
using ::testing::HasSubstr;

// The first 120 s of Intel mapped and saved, shared by the tests.
const std::filesystem::path& intel_session() {
  static const TempDir dir;
  static const bool ran = [] {
    const auto r =
        run_cli("slam --log " + intel_log().string() + " --to-s 120 --quiet --out " +
                (dir.path() / "run").string() + " --save " + (dir.path() / "intel.tsm").string());
    EXPECT_EQ(r.exit_code, 0) << r.output;
    return true;
  }();
  (void)ran;
  return dir.path();
}

TEST(CliLocalize, FindsTheRobotInASavedSessionWithNoInitialPose) {
  TESSERA_REQUIRE_DATA(intel_log());
  const auto& session = intel_session();
  const TempDir out;
  const auto r =
      run_cli("localize --session " + (session / "intel.tsm").string() + " --log " +
              intel_log().string() + " --from-s 30 --to-s 60 --out " + out.path().string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("localize: "));
  const nlohmann::json report = nlohmann::json::parse(read_bytes(out.path() / "report.json"));
  EXPECT_EQ(report["command"], "localize");
  const nlohmann::json& loc = report["localization"];
  EXPECT_LE(loc["first_pose_after_s"].get<double>(), 5.0);
  EXPECT_GE(loc["localized_scans"].get<double>(), 0.8 * loc["scans"].get<double>());
  // Where the session mapped, the scans neither jump nor leave the pose untrusted for metres.
  EXPECT_EQ(loc["jumps"], 0);
  EXPECT_EQ(loc["strays"], 0);
  EXPECT_TRUE(std::filesystem::exists(out.path() / "localization.png"));

  // Every localized pose is where the session's own SLAM put the robot at that stamp.
  const Result<std::vector<StampedPose2>> mapped =
      read_tum_trajectory(session / "run" / "trajectory.txt");
  const Result<std::vector<StampedPose2>> localized =
      read_tum_trajectory(out.path() / "trajectory.txt");
  ASSERT_TRUE(mapped.ok() && localized.ok());
  ASSERT_FALSE(localized->empty());
  std::vector<StampedPose2> sorted = *mapped;
  std::sort(sorted.begin(), sorted.end(),
            [](const StampedPose2& a, const StampedPose2& b) { return a.t_s < b.t_s; });
  double worst_m = 0.0;
  for (const StampedPose2& p : *localized) {
    const std::optional<Pose2> there = interpolate_pose(sorted, p.t_s);
    if (there) worst_m = std::max(worst_m, (there->translation() - p.pose.translation()).norm());
  }
  EXPECT_LT(worst_m, 0.1);

  // poses.csv: a header and one line per scan of the window.
  const std::string csv = read_bytes(out.path() / "poses.csv");
  EXPECT_THAT(csv, HasSubstr("t_s,state,confident,x_m,y_m,theta_rad,score,map_share,map_fit,"));
  EXPECT_EQ(static_cast<int>(std::count(csv.begin(), csv.end(), '\n')),
            loc["scans"].get<int>() + 1);
}

// The live node's trajectory (dir/node) against the offline run's (dir/offline): all but a few
// scans (a global search may accept 0.5 s later live) at the same stamps, each within 3 cm.
void expect_live_follows_offline(const TempDir& dir) {
  const Result<std::vector<StampedPose2>> expected =
      read_tum_trajectory(dir.path() / "offline" / "trajectory.txt");
  const Result<std::vector<StampedPose2>> got =
      read_tum_trajectory(dir.path() / "node" / "trajectory.txt");
  ASSERT_TRUE(expected.ok() && got.ok());
  EXPECT_GE(got->size() + 10, expected->size());
  std::size_t compared = 0;
  for (const StampedPose2& p : *got) {
    const auto same = std::find_if(expected->begin(), expected->end(),
                                   [&](const StampedPose2& e) { return e.t_s == p.t_s; });
    if (same == expected->end()) continue;
    EXPECT_LT((same->pose.translation() - p.pose.translation()).norm(), 0.03) << p.t_s;
    ++compared;
  }
  EXPECT_GE(compared + 10, expected->size());
}

// The same window played at 10x real time over DDS into `localize --ros`: every scan arrives,
// and the robot is found and tracked as the offline run finds and tracks it. Not bit for bit: the
// topics carry ranges as float32 and headings as quaternions, and the global search's accept
// decision may then fall one search (0.5 s) later; tracking then agrees within centimetres.
TEST(CliLocalize, TheLiveNodeLocalizesPlayedScansAsTheOfflineRunDoes) {
  TESSERA_REQUIRE_DATA(intel_log());
  const std::string session = (intel_session() / "intel.tsm").string();
  const TempDir dir;
  const auto offline =
      run_cli("localize --session " + session + " --log " + intel_log().string() +
              " --from-s 30 --to-s 60 --quiet --out " + (dir.path() / "offline").string());
  ASSERT_EQ(offline.exit_code, 0) << offline.output;
  const support::LivePlay live =
      support::play_into_node(dir, "localize --ros --session " + session,
                              intel_log().string() + " --from-s 30 --to-s 60 --rate 10");
  ASSERT_EQ(live.play.exit_code, 0) << live.play.output;
  ASSERT_FALSE(live.report.is_null()) << "no report; localize said: " << live.node_said;
  const nlohmann::json offline_report =
      nlohmann::json::parse(read_bytes(dir.path() / "offline" / "report.json"));
  const nlohmann::json& ros = live.report["ros"];
  EXPECT_EQ(ros["scans_received"], offline_report["localization"]["scans"]);
  EXPECT_EQ(ros["scans_dropped_overflow"], 0);
  EXPECT_EQ(ros["scans_localized"].get<int>() + ros["scans_lost"].get<int>(),
            ros["scans_received"].get<int>());
  EXPECT_LE(live.report["localization"]["first_pose_after_s"].get<double>(),
            offline_report["localization"]["first_pose_after_s"].get<double>() + 1.0);
  expect_live_follows_offline(dir);
  const auto both = run_cli("localize --ros --session " + session + " --log x.clf");
  EXPECT_EQ(both.exit_code, 2);
  EXPECT_THAT(both.output, HasSubstr("--ros localizes the topics"));
}

// The same window with the robot's odometry set aside (a robot without one): `localize --ros
// --no-odometry` reads the scans and the tf alone and follows the robot between scans by odometry
// made from its scans, as `localize --no-odometry` does offline; map -> base_link on /tf.
TEST(CliLocalize, WithoutOdometryTheLiveNodeFollowsTheRobotByItsScans) {
  TESSERA_REQUIRE_DATA(intel_log());
  const std::string session = (intel_session() / "intel.tsm").string();
  const TempDir dir;
  const auto offline = run_cli("localize --session " + session + " --log " + intel_log().string() +
                               " --from-s 30 --to-s 60 --no-odometry " + "--quiet --out " +
                               (dir.path() / "offline").string());
  ASSERT_EQ(offline.exit_code, 0) << offline.output;
  const nlohmann::json offline_report =
      nlohmann::json::parse(read_bytes(dir.path() / "offline" / "report.json"));
  EXPECT_EQ(offline_report["options"]["odometry"], "scan matching (--no-odometry)");
  const support::LivePlay live = support::play_into_node(
      dir, "localize --ros --no-odometry --base-frame base_link --session " + session,
      intel_log().string() + " --from-s 30 --to-s 60 --rate 10");
  ASSERT_EQ(live.play.exit_code, 0) << live.play.output;
  ASSERT_FALSE(live.report.is_null()) << "no report; localize said: " << live.node_said;
  EXPECT_EQ(live.report["options"]["odometry"], "scan matching (--no-odometry)");
  const nlohmann::json& ros = live.report["ros"];
  EXPECT_EQ(ros["scans_received"], offline_report["localization"]["scans"]);
  EXPECT_EQ(ros["odometry_received"], 0);
  EXPECT_GT(ros["scans_localized"].get<int>(), ros["scans_received"].get<int>() / 2);
  expect_live_follows_offline(dir);
  const auto base_alone = run_cli("localize --ros --session " + session + " --base-frame b");
  EXPECT_EQ(base_alone.exit_code, 2);
  EXPECT_THAT(base_alone.output, HasSubstr("--ros takes --base-frame with --no-odometry"));
}

TEST(CliLocalize, BadInputIsOneLineAndWritesNothing) {
  TESSERA_REQUIRE_DATA(intel_log());
  const auto& session = intel_session();
  const TempDir dir;
  const auto out = dir.path() / "out";
  // A session of a simulated 360-beam lidar, and the Intel log's 180-beam laser.
  const auto sim =
      run_cli("slam --builtin office --duration-s 5 --quiet --out " +
              (dir.path() / "sim").string() + " --save " + (dir.path() / "sim.tsm").string());
  ASSERT_EQ(sim.exit_code, 0) << sim.output;
  const auto other_laser =
      run_cli("localize --session " + (dir.path() / "sim.tsm").string() + " --log " +
              intel_log().string() + " --to-s 10 --out " + out.string());
  EXPECT_EQ(other_laser.exit_code, 3) << other_laser.output;
  EXPECT_THAT(other_laser.output, HasSubstr("is not the session's"));
  EXPECT_THAT(other_laser.output, HasSubstr(intel_log().string()));

  std::string damaged = read_bytes(session / "intel.tsm");
  damaged[damaged.size() / 2] = static_cast<char>(damaged[damaged.size() / 2] ^ 0x01);
  write_bytes(dir.path() / "damaged.tsm", damaged);
  const auto bad_session = run_cli("localize --session " + (dir.path() / "damaged.tsm").string() +
                                   " --log " + intel_log().string() + " --out " + out.string());
  EXPECT_EQ(bad_session.exit_code, 3);
  EXPECT_THAT(bad_session.output, HasSubstr("damaged.tsm: checksum mismatch"));
  EXPECT_EQ(read_bytes(dir.path() / "damaged.tsm"), damaged);

  const std::string good = "localize --session " + (session / "intel.tsm").string() + " --log " +
                           intel_log().string() + " --out " + out.string();
  const auto empty_window = run_cli(good + " --from-s 5000");
  EXPECT_EQ(empty_window.exit_code, 3);
  EXPECT_THAT(empty_window.output, HasSubstr("no scan from 5000 s"));
  const auto backwards = run_cli(good + " --from-s 50 --to-s 40");
  EXPECT_EQ(backwards.exit_code, 2);
  const auto no_log = run_cli("localize --session " + (session / "intel.tsm").string());
  EXPECT_EQ(no_log.exit_code, 2);
  EXPECT_THAT(no_log.output, HasSubstr("localize needs --log, --bag or --ros"));
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace tessera
