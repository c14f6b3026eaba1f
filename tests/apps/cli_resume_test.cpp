// tessera slam --resume end to end (issue 16): the first 90 s of the real Intel log mapped and
// saved, then continued with 90-180 s as a new trajectory, found in the saved map with no initial
// pose; the result agrees with one uninterrupted run, is saved with both trajectories and can be
// resumed again, under the session's settings. Autosave survives a kill. Bad input is one line,
// exit 2 or 3 (4 for a log that cannot be placed), and writes nothing.
#include <fcntl.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "cli_run.hpp"
#include "support/data.hpp"
#include "tessera/eval/relation_metric.hpp"
#include "tessera/io/tum_trajectory.hpp"

extern char** environ;

namespace tessera {
namespace {

using support::intel_log;
using support::read_bytes;
using support::run_cli;
using support::TempDir;
using support::write_bytes;
using ::testing::HasSubstr;

// The first 90 s of Intel mapped and saved (first.tsm, first/), shared by the tests.
const std::filesystem::path& first_session() {
  static const TempDir dir;
  static const bool ran = [] {
    const auto r =
        run_cli("slam --quiet --log " + intel_log().string() + " --to-s 90 --out " +
                (dir.path() / "first").string() + " --save " + (dir.path() / "first.tsm").string());
    EXPECT_EQ(r.exit_code, 0) << r.output;
    return true;
  }();
  (void)ran;
  return dir.path();
}

// 0-180 s of Intel in one run: what a resumed session should agree with.
const std::filesystem::path& whole_run() {
  static const TempDir dir;
  static const bool ran = [] {
    const auto r = run_cli("slam --quiet --log " + intel_log().string() + " --to-s 180 --out " +
                           dir.path().string());
    EXPECT_EQ(r.exit_code, 0) << r.output;
    return true;
  }();
  (void)ran;
  return dir.path();
}

std::vector<StampedPose2> sorted_trajectory(const std::filesystem::path& file) {
  Result<std::vector<StampedPose2>> read = read_tum_trajectory(file);
  EXPECT_TRUE(read.ok()) << file;
  if (!read) return {};
  std::vector<StampedPose2> sorted = *read;
  std::stable_sort(sorted.begin(), sorted.end(),
                   [](const StampedPose2& a, const StampedPose2& b) { return a.t_s < b.t_s; });
  return sorted;
}

// The largest distance between two trajectories at the stamps of `a` that `b` covers.
double worst_distance_m(const std::vector<StampedPose2>& a, const std::vector<StampedPose2>& b) {
  double worst = 0.0;
  for (const StampedPose2& p : a) {
    if (const std::optional<Pose2> q = interpolate_pose(b, p.t_s, 1.0)) {
      worst = std::max(worst, (q->translation() - p.pose.translation()).norm());
    }
  }
  return worst;
}

TEST(CliResume, ContinuesASavedSessionAsANewTrajectoryFoundInItsMap) {
  TESSERA_REQUIRE_DATA(intel_log());
  const auto& dir = first_session();
  const TempDir out;
  const auto r =
      run_cli("slam --log " + intel_log().string() + " --from-s 90 --to-s 180 " + "--resume " +
              (dir / "first.tsm").string() + " --out " + (out.path() / "run").string() +
              " --save " + (out.path() / "second.tsm").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json report =
      nlohmann::json::parse(read_bytes(out.path() / "run" / "report.json"));
  const nlohmann::json& resume = report["resume"];
  EXPECT_EQ(resume["start_from"], "relocalization");
  EXPECT_LE(resume["relocalized_after_s"].get<double>(), 5.0);
  EXPECT_EQ(resume["trajectories"], 2);

  // One pose per scan of both logs, and where one uninterrupted run over 0-180 s puts the robot.
  const std::vector<StampedPose2> resumed =
      sorted_trajectory(out.path() / "run" / "trajectory.txt");
  const std::vector<StampedPose2> whole = sorted_trajectory(whole_run() / "trajectory.txt");
  EXPECT_EQ(resumed.size(), whole.size());
  EXPECT_LT(worst_distance_m(resumed, whole), 0.1);

  const auto info = run_cli("info --json " + (out.path() / "second.tsm").string());
  ASSERT_EQ(info.exit_code, 0) << info.output;
  EXPECT_THAT(info.output, HasSubstr("\"trajectories\": 2"));
  EXPECT_THAT(info.output, HasSubstr("\"format_version\": 3"));

  // Resumed again (the two trajectories replayed from their saved starts), from a given pose.
  const Pose2 last = whole.back().pose;
  std::ostringstream pose;
  pose << std::setprecision(17) << last.x << ',' << last.y << ',' << last.theta;
  const auto again =
      run_cli("slam --quiet --log " + intel_log().string() + " --from-s 180 --to-s 200 --resume " +
              (out.path() / "second.tsm").string() + " --initial-pose " + pose.str() + " --out " +
              (out.path() / "third").string() + " --save " + (out.path() / "third.tsm").string());
  ASSERT_EQ(again.exit_code, 0) << again.output;
  const nlohmann::json third =
      nlohmann::json::parse(read_bytes(out.path() / "third" / "report.json"));
  EXPECT_EQ(third["resume"]["start_from"], "--initial-pose");
  EXPECT_EQ(third["resume"]["trajectories"], 3);
  // The replayed trajectories are the saved ones.
  EXPECT_LT(worst_distance_m(resumed, sorted_trajectory(out.path() / "third" / "trajectory.txt")),
            0.05);
}

// A session mapped without loop closure stays so through every resume, though the resumed runs'
// command lines do not repeat --no-loop-closure: a replay must run under the session's settings.
TEST(CliResume, TheSessionsSettingsCarryOverEveryResume) {
  TESSERA_REQUIRE_DATA(intel_log());
  const TempDir dir;
  const std::string slam = "slam --quiet --log " + intel_log().string();
  const auto path = [&](const char* name) { return (dir.path() / name).string(); };
  ASSERT_EQ(
      run_cli(slam + " --to-s 60 --no-loop-closure --out " + path("a") + " --save " + path("a.tsm"))
          .exit_code,
      0);
  ASSERT_EQ(run_cli(slam + " --from-s 60 --to-s 90 --resume " + path("a.tsm") + " --out " +
                    path("b") + " --save " + path("b.tsm"))
                .exit_code,
            0);
  ASSERT_EQ(
      run_cli(slam + " --from-s 90 --to-s 100 --resume " + path("b.tsm") + " --out " + path("c"))
          .exit_code,
      0);
  const nlohmann::json report = nlohmann::json::parse(read_bytes(dir.path() / "c" / "report.json"));
  EXPECT_EQ(report["options"]["loop_closure"], false);
  EXPECT_EQ(report["slam"]["loop_closures"], 0);
  EXPECT_EQ(report["resume"]["trajectories"], 3);
}

// --autosave-s: a run killed part way leaves the session as it was at the last autosave, complete
// and resumable.
TEST(CliResume, AKilledRunLeavesItsLastAutosavedSession) {
  TESSERA_REQUIRE_DATA(intel_log());
  const TempDir dir;
  const auto saved = dir.path() / "run.tsm";
  std::string program = TESSERA_CLI;
  std::vector<std::string> args = {program,
                                   "slam",
                                   "--quiet",
                                   "--log",
                                   intel_log().string(),
                                   "--to-s",
                                   "600",
                                   "--autosave-s",
                                   "20",
                                   "--save",
                                   saved.string(),
                                   "--out",
                                   (dir.path() / "out").string()};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  ASSERT_EQ(posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&actions);
  // Killed as soon as the first autosave is there: 600 s of data take seconds more to map.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(5);
  while (!std::filesystem::exists(saved) && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the run ended before it was killed";

  const auto info = run_cli("info --json " + saved.string());
  ASSERT_EQ(info.exit_code, 0) << info.output;
  const nlohmann::json j = nlohmann::json::parse(info.output);
  EXPECT_GE(j["duration_s"].get<double>(), 19.0);
  EXPECT_LT(j["duration_s"].get<double>(), 400.0);
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "out"));
  // Resumed with the same log from where the robot was at that moment.
  const double at_s = j["duration_s"].get<double>();
  const auto resumed =
      run_cli("slam --quiet --log " + intel_log().string() + " --from-s " + std::to_string(at_s) +
              " --to-s " + std::to_string(at_s + 30.0) + " --resume " + saved.string() + " --out " +
              (dir.path() / "resumed").string());
  EXPECT_EQ(resumed.exit_code, 0) << resumed.output;
}

// Bounded lifelong mapping: the same 90 s resumed twice over the session of them. Each save
// trims the earlier pass where the newer one saw the same rooms, so the session stays the size
// of one pass, its trajectory stays where one run puts the robot, and the saved state is what
// the next resume rebuilds. --keep-all-passes keeps both passes.
TEST(CliResume, ASessionResumedAgainAndAgainStaysBounded) {
  TESSERA_REQUIRE_DATA(intel_log());
  const auto& dir = first_session();
  const TempDir out;
  const auto session = out.path() / "s.tsm";
  std::filesystem::copy_file(dir / "first.tsm", session);
  const nlohmann::json first = nlohmann::json::parse(read_bytes(dir / "first" / "report.json"));
  const int first_nodes = first["slam"]["nodes"].get<int>();
  // The same log starts where the session did: given, not searched for (finding a resumed log's
  // start is ContinuesASavedSession's and apps.lifelong_smoke's; here it would be most of the
  // test's time, the robot standing 29 s in a corridor that looks alike both ways).
  const std::string start = " --initial-pose 0,0,0";
  const std::string resume = "slam --quiet --log " + intel_log().string() + " --to-s 90 --resume " +
                             session.string() + start + " --save " + session.string();
  for (int pass = 1; pass <= 2; ++pass) {
    const auto run = out.path() / ("pass" + std::to_string(pass));
    const auto r = run_cli(resume + " --out " + run.string());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const nlohmann::json trim =
        nlohmann::json::parse(read_bytes(run / "report.json"))["resume"]["trim"];
    EXPECT_GT(trim["submaps_trimmed"].get<int>(), 0) << pass;
    EXPECT_GT(trim["nodes_trimmed"].get<int>(), first_nodes / 2) << pass;
    EXPECT_LE(trim["nodes_after"].get<int>(), first_nodes * 12 / 10) << pass;
    // The pass itself went where the first run did (its scans are the newest: scored whole).
    const std::vector<StampedPose2> mine = sorted_trajectory(run / "trajectory.txt");
    const std::vector<StampedPose2> theirs = sorted_trajectory(dir / "first" / "trajectory.txt");
    EXPECT_LT(worst_distance_m(theirs, mine), 0.1) << pass;
  }
  const auto info = run_cli("info --json " + session.string());
  ASSERT_EQ(info.exit_code, 0) << info.output;
  const nlohmann::json saved = nlohmann::json::parse(info.output);
  EXPECT_LE(saved["scans"].get<int>(), first["slam"]["scans"].get<int>() * 12 / 10);

  const auto kept = out.path() / "kept.tsm";
  const auto keep_all =
      run_cli("slam --quiet --log " + intel_log().string() +
              " --to-s 90 --keep-all-passes --resume " + (dir / "first.tsm").string() + start +
              " --save " + kept.string() + " --out " + (out.path() / "kept").string());
  ASSERT_EQ(keep_all.exit_code, 0) << keep_all.output;
  const nlohmann::json both = nlohmann::json::parse(run_cli("info --json " + kept.string()).output);
  EXPECT_EQ(both["scans"].get<int>(), 2 * first["slam"]["scans"].get<int>());
}

TEST(CliResume, BadInputIsOneLineAndWritesNothing) {
  TESSERA_REQUIRE_DATA(intel_log());
  const auto& dir = first_session();
  const TempDir scratch;
  const auto out = scratch.path() / "out";
  const auto saved = scratch.path() / "saved.tsm";
  const std::string tail = " --out " + out.string() + " --save " + saved.string();
  // A session of a simulated 360-beam lidar, resumed with the Intel log's 180-beam laser.
  const auto sim = run_cli("slam --builtin office --duration-s 5 --quiet --out " +
                           (scratch.path() / "sim").string() + " --save " +
                           (scratch.path() / "sim.tsm").string());
  ASSERT_EQ(sim.exit_code, 0) << sim.output;
  const auto other_laser = run_cli("slam --log " + intel_log().string() + " --to-s 10 --resume " +
                                   (scratch.path() / "sim.tsm").string() + tail);
  EXPECT_EQ(other_laser.exit_code, 3) << other_laser.output;
  EXPECT_THAT(other_laser.output, HasSubstr("is not the session's"));

  std::string damaged = read_bytes(dir / "first.tsm");
  damaged[damaged.size() / 3] = static_cast<char>(damaged[damaged.size() / 3] ^ 0x04);
  write_bytes(scratch.path() / "damaged.tsm", damaged);
  const auto bad_session = run_cli("slam --log " + intel_log().string() + " --resume " +
                                   (scratch.path() / "damaged.tsm").string() + tail);
  EXPECT_EQ(bad_session.exit_code, 3);
  EXPECT_THAT(bad_session.output, HasSubstr("damaged.tsm: checksum mismatch"));
  EXPECT_EQ(read_bytes(scratch.path() / "damaged.tsm"), damaged);

  const std::string resume =
      "slam --log " + intel_log().string() + " --resume " + (dir / "first.tsm").string();
  const auto other_cell = run_cli(resume + " --cell-m 0.1" + tail);
  EXPECT_EQ(other_cell.exit_code, 2);
  EXPECT_THAT(other_cell.output, HasSubstr("with its own settings"));
  const auto bad_pose = run_cli(resume + " --initial-pose 1,north" + tail);
  EXPECT_EQ(bad_pose.exit_code, 2) << bad_pose.output;
  const auto no_log = run_cli("slam --resume " + (dir / "first.tsm").string() + tail);
  EXPECT_EQ(no_log.exit_code, 2);
  EXPECT_THAT(no_log.output, HasSubstr("--resume needs --log or --bag"));
  const auto pose_alone =
      run_cli("slam --log " + intel_log().string() + " --initial-pose 0,0,0" + tail);
  EXPECT_EQ(pose_alone.exit_code, 2);
  EXPECT_THAT(pose_alone.output, HasSubstr("it needs --resume"));
  const auto autosave_alone =
      run_cli("slam --log " + intel_log().string() + " --autosave-s 10 --out " + out.string());
  EXPECT_EQ(autosave_alone.exit_code, 2);
  EXPECT_THAT(autosave_alone.output, HasSubstr("--autosave-s saves to --save"));
  const auto keep_alone = run_cli(resume + " --keep-all-passes --out " + out.string());
  EXPECT_EQ(keep_alone.exit_code, 2);
  EXPECT_THAT(keep_alone.output, HasSubstr("--keep-all-passes is about what --resume saves"));
  // A log that never comes into the session's map (the robot standing at the start for 10 s,
  // then the log 400 s later, far away): no guess, exit 4.
  const auto small = run_cli("slam --quiet --log " + intel_log().string() + " --to-s 10 --out " +
                             (scratch.path() / "small").string() + " --save " +
                             (scratch.path() / "small.tsm").string());
  ASSERT_EQ(small.exit_code, 0) << small.output;
  const auto elsewhere =
      run_cli("slam --log " + intel_log().string() + " --from-s 400 --to-s 420 --resume " +
              (scratch.path() / "small.tsm").string() + tail);
  EXPECT_EQ(elsewhere.exit_code, 4) << elsewhere.output;
  EXPECT_THAT(elsewhere.output, HasSubstr("could be placed in the map of"));
  EXPECT_FALSE(std::filesystem::exists(out));
  EXPECT_FALSE(std::filesystem::exists(saved));
}

}  // namespace
}  // namespace tessera
