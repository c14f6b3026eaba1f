// tessera eval: the relation metric and the TUM ATE/RPE from the command line. Bad input gives exit
// code 3, one line naming the file and the problem, and no output folder.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_run.hpp"
#include "support/data.hpp"

namespace tessera {
namespace {

using support::count_lines;
using support::read_json;
using support::run_cli;
using support::TempDir;
using ::testing::HasSubstr;

/// A planar TUM trajectory: straight ahead at 1 m/s, one pose a second, stamps 0..4 s.
constexpr const char* kStraight =
    "# t x y z qx qy qz qw\n"
    "0 0 0 0 0 0 0 1\n1 1 0 0 0 0 0 1\n2 2 0 0 0 0 0 1\n3 3 0 0 0 0 0 1\n4 4 0 0 0 0 0 1\n";

TEST(CliEval, RelationsPrintsTheMetricAndWritesTheReport) {
  TempDir dir;
  support::write_bytes(dir / "traj.txt", kStraight);
  // Shortfalls of 0.1, 0.2 and 0.3 m; the last relation is outside the trajectory (skipped).
  support::write_bytes(dir / "rel.txt",
                       "100 101 1.1 0 0 0 0 0\n101 102 1.2 0 0 0 0 0\n102 103 1.3 0 0 0 0 0\n"
                       "103 105 2 0 0 0 0 0\n");
  const auto out = dir.path() / "out";
  const support::CliRun run =
      run_cli("eval relations --trajectory " + (dir / "traj.txt").string() + " --relations " +
              (dir / "rel.txt").string() + " --time-offset 100 --out " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_THAT(run.output, HasSubstr("3 scored, 1 skipped"));
  EXPECT_THAT(run.output, HasSubstr("translation 0.2000 +/- 0.1000 m"));
  const nlohmann::json report = read_json(out / "report.json");
  EXPECT_EQ(report["command"], "eval relations");
  EXPECT_EQ(report["relations"]["count"], 3);
  EXPECT_EQ(report["relations"]["skipped"], 1);
  EXPECT_NEAR(report["relations"]["trans_mean_m"].get<double>(), 0.2, 1e-9);
  EXPECT_NEAR(report["relations"]["trans_std_m"].get<double>(), 0.1, 1e-9);
  EXPECT_NEAR(report["relations"]["rot_mean_deg"].get<double>(), 0.0, 1e-9);
  EXPECT_EQ(report["trajectory"]["poses"], 5);
  EXPECT_EQ(report["options"]["time_offset_s"], 100.0);
}

TEST(CliEval, RelationsThatMatchNoTrajectoryStampAreAnInputError) {
  TempDir dir;
  support::write_bytes(dir / "traj.txt", kStraight);
  support::write_bytes(dir / "rel.txt", "976052896.78 976052905.17 1 0 0 0 0 0\n");
  const auto out = dir.path() / "out";
  const support::CliRun run =
      run_cli("eval relations --trajectory " + (dir / "traj.txt").string() + " --relations " +
              (dir / "rel.txt").string() + " --out " + out.string());
  EXPECT_EQ(run.exit_code, 3) << run.output;
  EXPECT_EQ(count_lines(run.output), 1) << run.output;
  EXPECT_THAT(run.output, HasSubstr("rel.txt against"));
  EXPECT_THAT(run.output, HasSubstr("no relation falls within the trajectory's time span "
                                    "[0.000000, 4.000000] s (time offset 0.000000 s)"));
  EXPECT_FALSE(std::filesystem::exists(out)) << "output folder left behind";
}

TEST(CliEval, MalformedTrajectoryIsAnInputErrorNamingFileAndLine) {
  TempDir dir;
  support::write_bytes(dir / "traj.txt", "0 0 0 0 0 0 0 1\n1 1 0 zero 0 0 0 1\n");
  support::write_bytes(dir / "rel.txt", "0 1 1 0 0 0 0 0\n");
  const auto out = dir.path() / "out";
  for (const std::string& command : {"eval relations --relations " + (dir / "rel.txt").string(),
                                     "eval ate --reference " + (dir / "traj.txt").string()}) {
    const support::CliRun run = run_cli(command + " --trajectory " + (dir / "traj.txt").string() +
                                        " --out " + out.string());
    EXPECT_EQ(run.exit_code, 3) << command << "\n" << run.output;
    EXPECT_EQ(count_lines(run.output), 1) << run.output;
    EXPECT_THAT(run.output, HasSubstr("traj.txt:2: field z must be a finite number"));
    EXPECT_FALSE(std::filesystem::exists(out));
  }
}

TEST(CliEval, UnreadableTrajectoryIsAnInputError) {
  TempDir dir;
  support::write_bytes(dir / "rel.txt", "0 1 1 0 0 0 0 0\n");
  const support::CliRun run =
      run_cli("eval relations --trajectory " + (dir / "missing.txt").string() + " --relations " +
              (dir / "rel.txt").string());
  EXPECT_EQ(run.exit_code, 3) << run.output;
  EXPECT_EQ(count_lines(run.output), 1) << run.output;
  EXPECT_THAT(run.output, HasSubstr("missing.txt: no such file"));
}

TEST(CliEval, MalformedRelationsFileIsAnInputError) {
  TempDir dir;
  support::write_bytes(dir / "traj.txt", kStraight);
  support::write_bytes(dir / "rel.txt", "0 1 1 0 0 0 0\n");
  const support::CliRun run = run_cli("eval relations --trajectory " + (dir / "traj.txt").string() +
                                      " --relations " + (dir / "rel.txt").string());
  EXPECT_EQ(run.exit_code, 3) << run.output;
  EXPECT_THAT(run.output, HasSubstr("rel.txt:1"));
}

TEST(CliEval, AteOfARigidlyMovedCopyIsZeroAndTheReportHasTheTrajectorySection) {
  TempDir dir;
  support::write_bytes(dir / "truth.txt", kStraight);
  // The same path turned by 90 degrees about z and shifted by (5, 5, 1): ATE 0 after alignment.
  support::write_bytes(dir / "est.txt",
                       "0 5 5 1 0 0 0.7071068 0.7071068\n1 5 6 1 0 0 0.7071068 0.7071068\n"
                       "2 5 7 1 0 0 0.7071068 0.7071068\n3 5 8 1 0 0 0.7071068 0.7071068\n"
                       "4 5 9 1 0 0 0.7071068 0.7071068\n");
  const auto out = dir.path() / "out";
  const support::CliRun run =
      run_cli("eval ate --trajectory " + (dir / "est.txt").string() + " --reference " +
              (dir / "truth.txt").string() + " --out " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_THAT(run.output, HasSubstr("ATE: 5 pairs, RMSE 0.0000 m"));
  const nlohmann::json report = read_json(out / "report.json");
  EXPECT_EQ(report["command"], "eval ate");
  EXPECT_EQ(report["trajectory"]["pairs"], 5);
  EXPECT_NEAR(report["trajectory"]["ate_rmse_m"].get<double>(), 0.0, 1e-6);
  // Poses 1 s apart, 5 poses: pairs (0,1), (1,2), (2,3); (3,4) ends at the last pose.
  EXPECT_EQ(report["trajectory"]["rpe_pairs"], 3);
  EXPECT_NEAR(report["trajectory"]["rpe_trans_m_per_s"].get<double>(), 0.0, 1e-6);
}

TEST(CliEval, AteWithoutMatchingStampsIsAnInputError) {
  TempDir dir;
  support::write_bytes(dir / "truth.txt", kStraight);
  support::write_bytes(dir / "est.txt", "100 0 0 0 0 0 0 1\n101 1 0 0 0 0 0 1\n");
  const auto out = dir.path() / "out";
  const support::CliRun run =
      run_cli("eval ate --trajectory " + (dir / "est.txt").string() + " --reference " +
              (dir / "truth.txt").string() + " --out " + out.string());
  EXPECT_EQ(run.exit_code, 3) << run.output;
  EXPECT_EQ(count_lines(run.output), 1) << run.output;
  EXPECT_THAT(run.output, HasSubstr("est.txt against"));
  EXPECT_THAT(run.output, HasSubstr("0 of 2 estimate stamps are within 0.02 s"));
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(CliEval, NonPositiveMaxDifferenceIsAUsageError) {
  const support::CliRun run =
      run_cli("eval ate --trajectory a.txt --reference b.txt --max-difference -1");
  EXPECT_EQ(run.exit_code, 2) << run.output;
}

TEST(CliEval, EvalNeedsASubcommandAndEachHasHelp) {
  EXPECT_EQ(run_cli("eval").exit_code, 2);
  for (const char* sub : {"relations", "ate"}) {
    const support::CliRun run = run_cli(std::string("eval ") + sub + " --help");
    EXPECT_EQ(run.exit_code, 0) << sub;
    EXPECT_THAT(run.output, HasSubstr("--trajectory")) << sub;
  }
}

// End to end on real data: TUM fr1/xyz, the figures of rgbd/tum_trajectories/SOURCES.md.
TEST(CliEval, Fr1XyzAteMatchesTheTumBenchmark) {
  const auto data = support::data_path("rgbd/tum_trajectories");
  TESSERA_REQUIRE_DATA(data / "fr1_xyz_groundtruth.txt");
  TempDir dir;
  const auto out = dir.path() / "out";
  const support::CliRun run = run_cli(
      "eval ate --trajectory " + (data / "fr1_xyz_rgbdslam_estimate.txt").string() +
      " --reference " + (data / "fr1_xyz_groundtruth.txt").string() + " --out " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const nlohmann::json t = read_json(out / "report.json")["trajectory"];
  EXPECT_EQ(t["pairs"], 786);
  EXPECT_NEAR(t["ate_rmse_m"].get<double>(), 0.0135, 0.0005);
  EXPECT_NEAR(t["rpe_trans_m_per_s"].get<double>(), 0.0212, 0.0001);  // evaluate_rpe.py's order
  EXPECT_NEAR(t["rpe_rot_deg_per_s"].get<double>(), 0.934, 0.01);
}

// The Intel Research Lab against the Kummerle relations (laser/intel/SOURCES.md "Time bases"):
// logger stamps + 976052857.337284 s reach the relations' time base.
TEST(CliEval, IntelLogsScoreAgainstTheKummerleRelations) {
  const auto intel = support::data_path("laser/intel");
  TESSERA_REQUIRE_DATA(intel / "intel-raw-first5505-sot.clf");
  const std::string relations =
      " --relations " + (intel / "intel.relations").string() + " --time-offset 976052857.337284";
  // The raw log covers the first 1,088 s: 1,033 of the 2,984 relations have both ends inside.
  const support::CliRun raw = run_cli("eval relations --trajectory " +
                                      (intel / "intel-raw-first5505-sot.clf").string() + relations);
  ASSERT_EQ(raw.exit_code, 0) << raw.output;
  EXPECT_THAT(raw.output, HasSubstr("1033 scored, 1951 skipped"));

  // GMapping's corrected keyframes (910 scans over 2,651 s) score at the published GMapping level
  // (0.070 +/- 0.083 m), far below raw odometry (metres).
  TempDir dir;
  const support::CliRun corrected =
      run_cli("eval relations --trajectory " + (intel / "intel-corrected.log").string() +
              relations + " --out " + (dir.path() / "out").string());
  ASSERT_EQ(corrected.exit_code, 0) << corrected.output;
  const nlohmann::json r = read_json(dir.path() / "out" / "report.json")["relations"];
  EXPECT_EQ(r["count"].get<int>() + r["skipped"].get<int>(), 2984);
  EXPECT_GT(r["count"].get<int>(), 2900);
  EXPECT_LT(r["trans_mean_m"].get<double>(), 0.2);
  EXPECT_LT(r["rot_mean_deg"].get<double>(), 6.0);
}

// FR079's corrected log carries the logger's stamps, which run 1211.43-1211.50 s behind the IPC
// stamps of Kummerle's relations (laser/fr079/SOURCES.md: the seven scans that carry both).
// Snapped to the nearest scan, GMapping's corrected poses score what their scans' motions are
// off; interpolated at the offset stamps, the clock's jitter times the robot's motion is added.
TEST(CliEval, SnappedStampsScoreFr079sCorrectedPosesOnTheirOwnScans) {
  const auto fr079 = support::data_path("laser/fr079");
  TESSERA_REQUIRE_DATA(fr079 / "freiburg-079-corrected.log");
  const std::string args = "eval relations --trajectory " +
                           (fr079 / "freiburg-079-corrected.log").string() + " --relations " +
                           (fr079 / "fr079.relations").string() + " --time-offset 1211.467";
  TempDir dir;
  const support::CliRun interpolated = run_cli(args + " --out " + (dir / "i").string());
  const support::CliRun snapped = run_cli(args + " --snap-s 0.07 --out " + (dir / "s").string());
  ASSERT_EQ(interpolated.exit_code, 0) << interpolated.output;
  ASSERT_EQ(snapped.exit_code, 0) << snapped.output;
  const nlohmann::json i = read_json(dir.path() / "i" / "report.json");
  const nlohmann::json s = read_json(dir.path() / "s" / "report.json");
  EXPECT_EQ(s["options"]["snap_s"], 0.07);
  EXPECT_EQ(i["relations"]["count"], 1685);
  // 4,791 of the run's 4,934 scans are in the log: relations on a missing scan are skipped.
  EXPECT_GT(s["relations"]["count"].get<int>(), 1200);
  EXPECT_NEAR(s["relations"]["trans_mean_m"].get<double>(), 0.061, 0.002);
  EXPECT_NEAR(s["relations"]["rot_mean_deg"].get<double>(), 0.71, 0.02);
  EXPECT_GT(i["relations"]["rot_mean_deg"].get<double>(),
            1.3 * s["relations"]["rot_mean_deg"].get<double>());
}

}  // namespace
}  // namespace tessera
