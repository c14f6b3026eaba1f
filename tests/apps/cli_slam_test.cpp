// tessera slam end to end: outputs and report fields on a slice of the real Intel log and on a
// simulated run scored against its ground truth, and bad input (exit 2 or 3, one line, nothing
// written).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>

#include "cli_run.hpp"
#include "support/data.hpp"

namespace tessera {
namespace {

using support::read_bytes;
using support::run_cli;
using support::TempDir;
using ::testing::HasSubstr;

/// The first `scans` FLASER lines of the Intel raw log, as a log of their own.
std::filesystem::path intel_slice(const TempDir& dir, int scans) {
  std::ifstream in(support::intel_log());
  std::string text, line;
  int n = 0;
  while (n < scans && std::getline(in, line)) {
    if (line.rfind("FLASER", 0) != 0) continue;
    text += line + "\n";
    ++n;
  }
  const auto path = dir.path() / "intel-slice.clf";
  support::write_bytes(path, text);
  return path;
}

/// `slam --quiet --log LOG EXTRA` into dir/name: its report and its trajectory file.
std::pair<nlohmann::json, std::string> slam_run(const TempDir& dir,
                                                const std::filesystem::path& log,
                                                const std::string& extra, const std::string& name) {
  const auto out = dir.path() / name;
  const support::CliRun run =
      run_cli("slam --quiet --log " + log.string() + extra + " --out " + out.string());
  EXPECT_EQ(run.exit_code, 0) << run.output;
  return {nlohmann::json::parse(read_bytes(out / "report.json")),
          read_bytes(out / "trajectory.txt")};
}

TEST(CliSlam, WritesMapTrajectoryGraphAndReport) {
  TESSERA_REQUIRE_DATA(support::intel_log());
  TempDir dir;
  const auto log = intel_slice(dir, 150);
  const auto out = dir.path() / "out";
  const support::CliRun run = run_cli("slam --log " + log.string() + " --out " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_THAT(run.output, HasSubstr("slam: 150 scans"));
  for (const char* f :
       {"map.yaml", "map.pgm", "map.png", "trajectory.txt", "graph.g2o", "report.json"}) {
    EXPECT_TRUE(std::filesystem::exists(out / f)) << f;
  }
  const std::string trajectory = read_bytes(out / "trajectory.txt");
  std::size_t poses = 0;
  for (std::size_t i = 0; i < trajectory.size(); ++i) {
    if (trajectory[i] == '\n' && (i == 0 || trajectory[i - 1] != '\n')) ++poses;
  }
  EXPECT_GE(poses, 150u);  // one line per scan (plus any header comment)
  const nlohmann::json report = nlohmann::json::parse(read_bytes(out / "report.json"));
  EXPECT_EQ(report["command"], "slam");
  EXPECT_EQ(report["slam"]["scans"], 150);
  EXPECT_GT(report["slam"]["nodes"].get<int>(), 0);
  EXPECT_GT(report["timing"]["realtime_factor"].get<double>(), 0.0);
  EXPECT_GT(report["timing"]["data_duration_s"].get<double>(), 20.0);
  EXPECT_FALSE(report.contains("relations"));
}

// The last step, every scan against the whole map (decision 0037), runs by default and is
// listed in the report; --no-whole-map skips it and leaves a different trajectory.
TEST(CliSlam, TheWholeMapPassRunsUnlessTurnedOff) {
  TESSERA_REQUIRE_DATA(support::intel_log());
  TempDir dir;
  const auto log = intel_slice(dir, 150);
  const auto [with, with_trajectory] = slam_run(dir, log, "", "with");
  const auto [without, without_trajectory] = slam_run(dir, log, " --no-whole-map", "without");
  EXPECT_EQ(with["options"]["final_map_passes"], 1);
  EXPECT_GT(with["slam"]["whole_map_s"].get<double>(), 0.0);
  EXPECT_EQ(without["options"]["final_map_passes"], 0);
  EXPECT_EQ(without["slam"]["whole_map_s"].get<double>(), 0.0);
  EXPECT_NE(with_trajectory, without_trajectory);
}

// The odometry's scales and drift are estimated from the matches by default (decisions 0039,
// 0040) and listed in the report; --no-odometry-calibration takes the odometry as it reads.
TEST(CliSlam, TheOdometryIsCalibratedUnlessTurnedOff) {
  TESSERA_REQUIRE_DATA(support::intel_log());
  TempDir dir;
  const auto log = intel_slice(dir, 600);
  const auto [with, with_trajectory] = slam_run(dir, log, "", "with");
  const auto [without, without_trajectory] =
      slam_run(dir, log, " --no-odometry-calibration", "without");
  EXPECT_EQ(with["options"]["odometry_calibration"], true);
  EXPECT_NE(with["slam"]["odometry_translation_scale"].get<double>(), 1.0);
  EXPECT_NE(with["slam"]["odometry_drift_rad_per_m"].get<double>(), 0.0);
  EXPECT_EQ(without["options"]["odometry_calibration"], false);
  EXPECT_EQ(without["slam"]["odometry_translation_scale"].get<double>(), 1.0);
  EXPECT_EQ(without["slam"]["odometry_rotation_scale"].get<double>(), 1.0);
  EXPECT_EQ(without["slam"]["odometry_drift_rad_per_m"].get<double>(), 0.0);
  EXPECT_NE(with_trajectory, without_trajectory);
}

TEST(CliSlam, BadLogIsAnInputErrorAndWritesNothing) {
  TempDir dir;
  support::write_bytes(dir / "bad.clf", "FLASER 3 1.0 2.0\n");
  const auto out = dir.path() / "out";
  const support::CliRun run =
      run_cli("slam --log " + (dir / "bad.clf").string() + " --out " + out.string());
  EXPECT_EQ(run.exit_code, 3) << run.output;
  EXPECT_THAT(run.output, HasSubstr("bad.clf:1:"));
  EXPECT_FALSE(std::filesystem::exists(out));
}

// Relations that the log's stamps do not reach are an input error, found before anything is
// written.
TEST(CliSlam, RelationsOutsideTheLogAreAnInputErrorAndWriteNothing) {
  TESSERA_REQUIRE_DATA(support::intel_log());
  TempDir dir;
  const auto log = intel_slice(dir, 40);
  support::write_bytes(dir / "r.relations", "5000 5001 0.1 0 0 0 0 0\n");
  const auto out = dir.path() / "out";
  const support::CliRun run = run_cli("slam --quiet --log " + log.string() + " --relations " +
                                      (dir / "r.relations").string() + " --out " + out.string());
  EXPECT_EQ(run.exit_code, 3) << run.output;
  EXPECT_FALSE(std::filesystem::exists(out));
}

// A simulated run in the built-in office: SLAM must beat odometry by far, and the map must not
// show free space where the world is solid (the bars: 5x, 0.5 %).
TEST(CliSlam, SimulatedRunIsScoredAgainstItsGroundTruth) {
  TempDir dir;
  const auto out = dir.path() / "out";
  const support::CliRun run =
      run_cli("slam --builtin office --duration-s 90 --seed 3 --out " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_THAT(run.output, HasSubstr("ground truth: ATE"));
  for (const char* f : {"map.png", "trajectory.txt", "truth.txt", "odometry.txt", "report.json"}) {
    EXPECT_TRUE(std::filesystem::exists(out / f)) << f;
  }
  const nlohmann::json report = nlohmann::json::parse(read_bytes(out / "report.json"));
  EXPECT_EQ(report["seed"], 3);
  EXPECT_NEAR(report["simulation"]["duration_s"].get<double>(), 90.0, 0.2);
  const nlohmann::json& ate = report["ate"];
  EXPECT_LT(ate["slam_rmse_m"].get<double>(), 0.05);
  EXPECT_GE(ate["odometry_rmse_m"].get<double>(), 5.0 * ate["slam_rmse_m"].get<double>());
  const nlohmann::json& map = report["map_accuracy"];
  EXPECT_GT(map["occupied_compared"].get<int>(), 500);
  EXPECT_LT(map["occupied_as_empty_share"].get<double>(), 0.005);
  EXPECT_DOUBLE_EQ(report["options"]["map_resolution_m"].get<double>(), 0.05);  // the world's cell
  // The final map's free space: no miss within 3 cm of a surface or 5 mm of a cell's edge.
  EXPECT_DOUBLE_EQ(report["options"]["map_miss_margin_m"].get<double>(), 0.03);
  EXPECT_DOUBLE_EQ(report["options"]["map_miss_inset_m"].get<double>(), 0.005);
  // The effective evidence of a hit, and how it grows when the scans are far apart.
  EXPECT_DOUBLE_EQ(report["options"]["submap_hit_probability"].get<double>(), 0.55);
  EXPECT_DOUBLE_EQ(report["options"]["hit_evidence_step_m"].get<double>(), 0.35);
  EXPECT_DOUBLE_EQ(report["options"]["max_hit_evidence_scale"].get<double>(), 2.0);
}

// A simulated spinning lidar (each scan swept over 0.2 s while the robot moves): its scans are
// placed beam by beam, and the run keeps to the truth. A sweep longer than a scan period is a
// usage error.
TEST(CliSlam, ASimulatedSpinningLidarsRunIsScored) {
  TempDir dir;
  const auto out = dir.path() / "out";
  const std::string swept = "slam --builtin office --lidar-sweep-s 0.2 --out ";
  const support::CliRun run =
      run_cli(swept + out.string() + " --seed 2 --duration-s 60 --scan-rate-hz 5 --quiet");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const nlohmann::json report = nlohmann::json::parse(read_bytes(out / "report.json"));
  EXPECT_DOUBLE_EQ(report["simulation"]["scan_rate_hz"].get<double>(), 5.0);
  EXPECT_DOUBLE_EQ(report["simulation"]["lidar_sweep_s"].get<double>(), 0.2);
  EXPECT_LT(report["ate"]["slam_rmse_m"].get<double>(), 0.05);
  const auto bad = dir.path() / "bad";
  const support::CliRun too_long = run_cli(swept + bad.string() + " --scan-rate-hz 10");
  EXPECT_EQ(too_long.exit_code, 2) << too_long.output;
  EXPECT_THAT(too_long.output, HasSubstr("--lidar-sweep-s must be at most one scan period"));
  EXPECT_FALSE(std::filesystem::exists(bad));
}

TEST(CliSlam, LogAndWorldTogetherIsAUsageError) {
  TempDir dir;
  support::write_bytes(dir / "a.clf", "");
  const auto out = dir.path() / "out";
  const support::CliRun run = run_cli("slam --log " + (dir / "a.clf").string() + " --world " +
                                      (dir / "a.clf").string() + " --out " + out.string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_THAT(run.output, HasSubstr("not both"));
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(CliSlam, UnreadableWorldIsAnInputErrorAndWritesNothing) {
  TempDir dir;
  support::write_bytes(dir / "w.yaml", "image: missing.pgm\nresolution: 0.05\n");
  const auto out = dir.path() / "out";
  const support::CliRun run =
      run_cli("slam --world " + (dir / "w.yaml").string() + " --out " + out.string());
  EXPECT_EQ(run.exit_code, 3) << run.output;
  EXPECT_THAT(run.output, HasSubstr("w.yaml"));
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace tessera
