#include "tessera/io/carmen_log.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "io_test_util.hpp"
#include "support/data.hpp"

namespace tessera {
namespace {

using io_test::TempDir;
using ::testing::HasSubstr;
using ::testing::StartsWith;

constexpr double kDeg = std::numbers::pi / 180.0;

/// `n` copies of `range_m`, space-separated.
std::string ranges(int n, const std::string& range_m) {
  std::string s;
  for (int i = 0; i < n; ++i) s += (i ? " " : "") + range_m;
  return s;
}

/// An old-format laser line; the laser pose equals the odometry pose unless given.
std::string old_laser(const std::string& tag, int n, const std::string& ranges_text,
                      const std::string& odom = "1 2 0.5", const std::string& laser = "",
                      const std::string& stamps = "10.5 host 0.5") {
  return tag + " " + std::to_string(n) + " " + ranges_text + " " + (laser.empty() ? odom : laser) +
         " " + odom + " " + stamps + "\n";
}

std::string flaser(int n, const std::string& range_m = "2.5") {
  return old_laser("FLASER", n, ranges(n, range_m));
}

Result<LaserLog> read_carmen_text(const TempDir& dir, const std::string& text,
                                  const CarmenReadOptions& options = {}) {
  const auto path = dir / "log.clf";
  io_test::write_bytes(path, text);
  return read_carmen_log(path, options);
}

TEST(CarmenLog, FlaserGivesTheOdometryPoseTheIpcStampAndCarmensBeamGeometry) {
  TempDir dir;
  const Result<LaserLog> log = read_carmen_text(dir, old_laser("FLASER", 180, ranges(180, "3.25")));
  ASSERT_TRUE(log.ok()) << log.error().message;
  ASSERT_EQ(log->scans.size(), 1u);
  const StampedScan& s = log->scans[0];
  EXPECT_DOUBLE_EQ(s.t_s, 10.5);  // the ipc stamp, not the logger's 0.5
  EXPECT_DOUBLE_EQ(s.odometry.x, 1.0);
  EXPECT_DOUBLE_EQ(s.odometry.y, 2.0);
  EXPECT_DOUBLE_EQ(s.odometry.theta, 0.5);
  EXPECT_NEAR(s.laser_in_robot.x, 0.0, 1e-12);
  EXPECT_NEAR(s.laser_in_robot.theta, 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(s.scan.angle_min_rad, -std::numbers::pi / 2.0);
  EXPECT_DOUBLE_EQ(s.scan.angle_increment_rad, kDeg);
  ASSERT_EQ(s.scan.ranges_m.size(), 180u);
  EXPECT_DOUBLE_EQ(s.scan.ranges_m[179], 3.25);
  EXPECT_TRUE(log->odometry.empty());
  EXPECT_EQ(log->backward_stamps, 0);
}

TEST(CarmenLog, OldFormatBeamSpacingFollowsCarmensGuessFromTheBeamCount) {
  const std::vector<std::pair<int, double>> cases = {
      {180, kDeg},        {181, kDeg},        {360, 0.5 * kDeg},           {361, 0.5 * kDeg},
      {400, 0.25 * kDeg}, {401, 0.25 * kDeg}, {5, std::numbers::pi / 4.0}, {1, 0.0}};
  for (const auto& [beams, increment_rad] : cases) {
    TempDir dir;
    const Result<LaserLog> log = read_carmen_text(dir, flaser(beams));
    ASSERT_TRUE(log.ok()) << log.error().message;
    EXPECT_DOUBLE_EQ(log->scans[0].scan.angle_increment_rad, increment_rad) << beams << " beams";
    EXPECT_DOUBLE_EQ(log->scans[0].scan.angle_min_rad, -std::numbers::pi / 2.0)
        << beams << " beams";
  }
}

TEST(CarmenLog, LaserPoseOffsetBecomesLaserInRobot) {
  // FR079's first scan: the laser sits 0.04 m behind the odometry pose (robot_frontlaser_offset).
  TempDir dir;
  const Result<LaserLog> log = read_carmen_text(
      dir, old_laser("FLASER", 3, "1 2 3", "-3.034287 8.291214 -3.120965",
                     "-2.994295 8.292039 -3.120965", "1211.520329 magnum 0.015885"));
  ASSERT_TRUE(log.ok()) << log.error().message;
  const StampedScan& s = log->scans[0];
  EXPECT_NEAR(s.laser_in_robot.x, -0.04, 1e-5);
  EXPECT_NEAR(s.laser_in_robot.y, 0.0, 1e-5);
  EXPECT_NEAR(s.laser_in_robot.theta, 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(s.odometry.x, -3.034287);
  EXPECT_DOUBLE_EQ(s.t_s, 1211.520329);
}

TEST(CarmenLog, RearLaserIsSkippedUnlessAskedFor) {
  TempDir dir;
  const std::string text = flaser(3) + old_laser("RLASER", 2, "4 5");
  const Result<LaserLog> front_only = read_carmen_text(dir, text);
  ASSERT_TRUE(front_only.ok()) << front_only.error().message;
  EXPECT_EQ(front_only->scans.size(), 1u);

  CarmenReadOptions options;
  options.rear_laser = true;
  const Result<LaserLog> both = read_carmen_text(dir, text, options);
  ASSERT_TRUE(both.ok()) << both.error().message;
  ASSERT_EQ(both->scans.size(), 2u);
  EXPECT_EQ(both->scans[1].scan.ranges_m, (std::vector<double>{4.0, 5.0}));
  EXPECT_NEAR(std::abs(both->scans[1].laser_in_robot.theta), std::numbers::pi, 1e-12)
      << "faces backwards";
  EXPECT_NEAR(both->scans[0].laser_in_robot.theta, 0.0, 1e-12);
}

TEST(CarmenLog, RearLaserPoseThatIsAlreadyTurnedIsNotTurnedTwice) {
  TempDir dir;
  CarmenReadOptions options;
  options.rear_laser = true;
  const Result<LaserLog> log =
      read_carmen_text(dir, old_laser("RLASER", 2, "4 5", "0 0 0", "-0.1 0 3.14159"), options);
  ASSERT_TRUE(log.ok()) << log.error().message;
  EXPECT_NEAR(std::abs(log->scans[0].laser_in_robot.theta), std::numbers::pi, 1e-4);
  EXPECT_NEAR(log->scans[0].laser_in_robot.x, -0.1, 1e-12);
}

TEST(CarmenLog, OdomLinesBecomeOdometryReadings) {
  TempDir dir;
  const Result<LaserLog> log = read_carmen_text(
      dir, "ODOM 1 2 0.3 0.1 0.2 0 5.5 host 0.1\nODOM 1.5 2 4 0 0 0 6.5 host 0.2\n" + flaser(3));
  ASSERT_TRUE(log.ok()) << log.error().message;
  ASSERT_EQ(log->odometry.size(), 2u);
  EXPECT_DOUBLE_EQ(log->odometry[0].t_s, 5.5);
  EXPECT_DOUBLE_EQ(log->odometry[0].pose.x, 1.0);
  EXPECT_DOUBLE_EQ(log->odometry[0].pose.theta, 0.3);
  EXPECT_NEAR(log->odometry[1].pose.theta, 4.0 - 2.0 * std::numbers::pi, 1e-12)
      << "wrapped into [-pi, pi)";
}

TEST(CarmenLog, RobotLaserCarriesItsOwnGeometryAndMaximumRange) {
  TempDir dir;
  // start -1.5 rad, 0.01 rad apart, max 30 m; two remissions; laser 0.2 m ahead of the robot.
  const std::string line =
      "ROBOTLASER1 0 -1.5 3.0 0.01 30 0.01 0 4 1 2 30 4 2 0.5 0.6 2.2 0 0 2 0 0 0.1 0.2 0.3 0.4 "
      "0.5 7.25 host 0.1\n";
  const Result<LaserLog> log = read_carmen_text(dir, line);
  ASSERT_TRUE(log.ok()) << log.error().message;
  const StampedScan& s = log->scans[0];
  EXPECT_DOUBLE_EQ(s.scan.angle_min_rad, -1.5);
  EXPECT_DOUBLE_EQ(s.scan.angle_increment_rad, 0.01);
  EXPECT_DOUBLE_EQ(s.scan.max_range_m, 30.0);
  EXPECT_EQ(s.scan.ranges_m, (std::vector<double>{1, 2, 30, 4}));
  EXPECT_GE(s.scan.ranges_m[2], s.scan.max_range_m) << "the 30 m reading means no return";
  EXPECT_DOUBLE_EQ(s.odometry.x, 2.0);
  EXPECT_NEAR(s.laser_in_robot.x, 0.2, 1e-12);
  EXPECT_NEAR(s.laser_in_robot.y, 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(s.t_s, 7.25);
}

TEST(CarmenLog, RawLaserOdometryIsInterpolatedBetweenTheOdomLinesAroundIt) {
  TempDir dir;
  const std::string raw = "RAWLASER1 0 -1.57 3.14 0.0175 80 0.01 0 3 1 2 3 0 ";
  const std::string text = "ODOM 0 0 3.0 0 0 0 10 host 10\n" + raw + "10.25 host 10.25\n" +
                           "ODOM 4 2 -3.0 0 0 0 11 host 11\n" + raw + "12 host 12\n";
  const Result<LaserLog> log = read_carmen_text(dir, text);
  ASSERT_TRUE(log.ok()) << log.error().message;
  ASSERT_EQ(log->scans.size(), 2u);
  const Pose2& a = log->scans[0].odometry;
  EXPECT_NEAR(a.x, 1.0, 1e-12);
  EXPECT_NEAR(a.y, 0.5, 1e-12);
  // Shortest arc from 3.0 to -3.0 crosses pi: a quarter of the 0.283 rad step.
  EXPECT_NEAR(a.theta, 3.0 + 0.25 * (2.0 * std::numbers::pi - 6.0), 1e-12);
  EXPECT_EQ(log->scans[0].laser_in_robot.x, 0.0);
  // After the last ODOM: its pose.
  EXPECT_DOUBLE_EQ(log->scans[1].odometry.x, 4.0);
  EXPECT_DOUBLE_EQ(log->scans[1].scan.max_range_m, 80.0);
}

TEST(CarmenLog, RawLaserBeforeAnyOdomTakesTheFirstOdom) {
  TempDir dir;
  const std::string text =
      "RAWLASER1 0 -1.57 3.14 0.0175 80 0.01 0 2 1 2 0 9 host 9\nODOM 5 6 0 0 0 0 10 host 10\n";
  const Result<LaserLog> log = read_carmen_text(dir, text);
  ASSERT_TRUE(log.ok()) << log.error().message;
  EXPECT_DOUBLE_EQ(log->scans[0].odometry.x, 5.0);
  EXPECT_DOUBLE_EQ(log->scans[0].odometry.y, 6.0);
}

TEST(CarmenLog, SkipsCommentsBlankLinesAndOtherMessages) {
  TempDir dir;
  const std::string text =
      "# CARMEN Logfile\n\n   \nPARAM robot_frontlaser_offset 0.0 nohost 0\nNEFF 29.5\n"
      "TRUEPOS 1 2 3 4 5 6 1 host 1\nSYNC tag 1 host 1\nGPSNMEA whatever\r\n\tFLASER\t2 1 2 0 0 0 "
      "0 0 0 1 host 1\r\n";
  const Result<LaserLog> log = read_carmen_text(dir, text);
  ASSERT_TRUE(log.ok()) << log.error().message;
  ASSERT_EQ(log->scans.size(), 1u);
  EXPECT_EQ(log->scans[0].scan.ranges_m, (std::vector<double>{1.0, 2.0}));
  EXPECT_DOUBLE_EQ(log->scans[0].t_s, 1.0);
}

TEST(CarmenLog, NoReturnThresholdIsJustBelowTheLargestOldFormatReading) {
  TempDir dir;
  const Result<LaserLog> log = read_carmen_text(
      dir, old_laser("FLASER", 3, "1.5 81.83 3") + old_laser("FLASER", 3, "2 81.8 81.5"));
  ASSERT_TRUE(log.ok()) << log.error().message;
  for (const StampedScan& s : log->scans) EXPECT_NEAR(s.scan.max_range_m, 81.73, 1e-9);
  EXPECT_GE(log->scans[0].scan.ranges_m[1], log->scans[0].scan.max_range_m);
  EXPECT_GE(log->scans[1].scan.ranges_m[1], log->scans[1].scan.max_range_m) << "81.8: sentinel";
  EXPECT_LT(log->scans[1].scan.ranges_m[2], log->scans[1].scan.max_range_m) << "81.5: a hit";
}

TEST(CarmenLog, ExplicitNoReturnAppliesToEveryScan) {
  TempDir dir;
  CarmenReadOptions options;
  options.no_return_m = 50.0;
  const std::string robot_laser =
      "ROBOTLASER1 0 -1.5 3.0 0.01 30 0.01 0 1 5 0 0 0 0 0 0 0 0 0 0 0 0 7 host 7\n";
  const Result<LaserLog> log = read_carmen_text(dir, flaser(2, "81.83") + robot_laser, options);
  ASSERT_TRUE(log.ok()) << log.error().message;
  ASSERT_EQ(log->scans.size(), 2u);
  EXPECT_DOUBLE_EQ(log->scans[0].scan.max_range_m, 50.0);
  EXPECT_DOUBLE_EQ(log->scans[1].scan.max_range_m, 50.0);
}

TEST(CarmenLog, BackwardStampsCountsOnlyStrictDecreasesAndKeepsFileOrder) {
  TempDir dir;
  std::string text;
  for (const char* t : {"1", "2", "1.5", "1.5", "3", "0.5"}) {
    text += old_laser("FLASER", 1, "1", "0 0 0", "", std::string(t) + " host 0");
  }
  const Result<LaserLog> log = read_carmen_text(dir, text);
  ASSERT_TRUE(log.ok()) << log.error().message;
  EXPECT_EQ(log->backward_stamps, 2);
  ASSERT_EQ(log->scans.size(), 6u);
  EXPECT_DOUBLE_EQ(log->scans[2].t_s, 1.5);
  EXPECT_DOUBLE_EQ(log->scans[5].t_s, 0.5);
}

TEST(CarmenLog, NegativeNoReturnOptionIsAUsageError) {
  TempDir dir;
  CarmenReadOptions options;
  options.no_return_m = -1.0;
  EXPECT_TRUE(validate(options).has_value());
  const Result<LaserLog> log = read_carmen_text(dir, flaser(2), options);
  ASSERT_FALSE(log.ok());
  EXPECT_EQ(log.error().kind, ErrorKind::kUsage);
  EXPECT_THAT(log.error().message, HasSubstr("no_return_m"));
  EXPECT_FALSE(validate(CarmenReadOptions{}).has_value());
}

TEST(CarmenLog, MissingFileIsAnInputError) {
  TempDir dir;
  const Result<LaserLog> log = read_carmen_log(dir / "nope.clf");
  ASSERT_FALSE(log.ok());
  EXPECT_EQ(log.error().kind, ErrorKind::kInput);
  EXPECT_THAT(log.error().message, HasSubstr("nope.clf: no such file"));
}

TEST(CarmenLog, DirectoryIsAnInputError) {
  TempDir dir;
  const Result<LaserLog> log = read_carmen_log(dir.path());
  ASSERT_FALSE(log.ok());
  EXPECT_EQ(log.error().kind, ErrorKind::kInput);
  EXPECT_THAT(log.error().message, HasSubstr("is a directory"));
}

/// A file that must be rejected: its text, the line named and a phrase of the message.
struct BadLog {
  std::string name;
  std::string text;
  std::string where;  // "log.clf:<line>:" or "log.clf: " for whole-file problems
  std::string phrase;
  bool rear_laser = false;
};

class CarmenLogBadInput : public ::testing::TestWithParam<BadLog> {};

TEST_P(CarmenLogBadInput, IsAnInputErrorNamingFileLineAndProblem) {
  const BadLog& bad = GetParam();
  TempDir dir;
  CarmenReadOptions options;
  options.rear_laser = bad.rear_laser;
  const Result<LaserLog> log = read_carmen_text(dir, bad.text, options);
  ASSERT_FALSE(log.ok());
  EXPECT_EQ(log.error().kind, ErrorKind::kInput);
  EXPECT_THAT(log.error().message, StartsWith((dir / bad.where).string()));
  EXPECT_THAT(log.error().message, HasSubstr(bad.phrase));
  EXPECT_EQ(log.error().message.find('\n'), std::string::npos) << "one line";
}

const std::string kRaw = "RAWLASER1 0 -1.57 3.14 0.0175 80 0.01 0 ";
const std::string kRobot = "ROBOTLASER1 0 -1.57 3.14 0.0175 80 0.01 0 ";
const std::string kRobotTail = " 0 0 0 0 0 0 0 0 0 0 0 7 host 7\n";

INSTANTIATE_TEST_SUITE_P(
    CarmenLog, CarmenLogBadInput,
    ::testing::Values(
        BadLog{"TruncatedFlaser", flaser(2) + "FLASER 3 1 2\n",
               "log.clf:2:", "truncated FLASER line: 4 fields, expected at least 11"},
        BadLog{"FlaserBeamCountDoesNotMatchRanges",
               flaser(2) + old_laser("FLASER", 180, ranges(179, "1")),
               "log.clf:2:", "FLASER says 180 beams but has 179 ranges"},
        BadLog{"FlaserWithMoreRangesThanBeams", old_laser("FLASER", 2, "1 2 3"),
               "log.clf:1:", "FLASER says 2 beams but has 3 ranges"},
        BadLog{"RlaserBeamCountDoesNotMatchRanges", old_laser("RLASER", 3, "1 2"),
               "log.clf:1:", "RLASER says 3 beams but has 2 ranges", true},
        BadLog{"BeamCountIsNotANumber", old_laser("FLASER", 2, "1 2").replace(7, 1, "x"),
               "log.clf:1:", "FLASER beam count is 'x', expected an integer >= 1"},
        BadLog{"BeamCountIsZero", "FLASER 0 0 0 0 0 0 0 1 host 1\n",
               "log.clf:1:", "beam count is '0'"},
        BadLog{"NanRange", old_laser("FLASER", 3, "1 nan 3"),
               "log.clf:1:", "FLASER range of beam 1 is 'nan', expected a finite number >= 0"},
        BadLog{"InfiniteRange", old_laser("FLASER", 3, "1 2 inf"),
               "log.clf:1:", "range of beam 2 is 'inf'"},
        BadLog{"NegativeRange", old_laser("FLASER", 3, "-0.5 2 3"),
               "log.clf:1:", "range of beam 0 is '-0.5'"},
        BadLog{"RangeIsNotANumber", old_laser("FLASER", 3, "1 2 3.0m"),
               "log.clf:1:", "range of beam 2 is '3.0m'"},
        BadLog{"PoseFieldIsNotANumber", old_laser("FLASER", 1, "1", "1 abc 0", "0 0 0"),
               "log.clf:1:", "FLASER odom_y is 'abc', expected a number"},
        BadLog{"StampIsNotANumber", old_laser("FLASER", 1, "1", "0 0 0", "", "t host 1"),
               "log.clf:1:", "FLASER ipc_timestamp is 't'"},
        BadLog{"TruncatedOdom", flaser(1) + "ODOM 1 2 3 0 0 0 5 host\n",
               "log.clf:2:", "truncated ODOM line: 9 fields, expected 10"},
        BadLog{"OdomWithExtraFields", flaser(1) + "ODOM 1 2 3 0 0 0 5 host 5 6\n",
               "log.clf:2:", "ODOM line has 11 fields, expected 10"},
        BadLog{"OdomFieldIsNotANumber", "ODOM 1 2 3 0 x 0 5 host 5\n" + flaser(1),
               "log.clf:1:", "ODOM rv is 'x'"},
        BadLog{"TruncatedRobotLaser", kRobot + "3 1 2\n",
               "log.clf:1:", "truncated ROBOTLASER1 line: 11 fields, expected at least 24"},
        BadLog{"RobotLaserWithExtraFields", kRobot + "1 5 0" + kRobotTail.substr(0, 5) + kRobotTail,
               "log.clf:1:", "ROBOTLASER1 line has 27 fields, expected 25"},
        BadLog{"RobotLaserRemissionCountIsNotAnInteger", kRobot + "1 5 1.5" + kRobotTail,
               "log.clf:1:", "ROBOTLASER1 remission count is '1.5'"},
        BadLog{"RobotLaserResolutionIsNotPositive",
               "ROBOTLASER1 0 -1.57 3.14 0 80 0.01 0 1 5 0" + kRobotTail,
               "log.clf:1:", "resolution must be > 0"},
        BadLog{"RobotLaserMaxRangeIsNotPositive",
               "ROBOTLASER1 0 -1.57 3.14 0.01 -1 0.01 0 1 5 0" + kRobotTail,
               "log.clf:1:", "max_range must be > 0"},
        BadLog{"RobotLaserNanRange", kRobot + "2 5 nan 0" + kRobotTail,
               "log.clf:1:", "ROBOTLASER1 range of beam 1 is 'nan'"},
        BadLog{"TruncatedRawLaser", kRaw + "2 1 2 0 9 host\n",
               "log.clf:1:", "truncated RAWLASER1 line: 14 fields, expected at least 15"},
        BadLog{"RawLaserRemissionIsNotANumber", kRaw + "1 1 1 z 9 host 9\n",
               "log.clf:1:", "RAWLASER1 remission is 'z'"},
        BadLog{"RawLaserWithoutAnyOdom", flaser(1) + kRaw + "1 1 0 9 host 9\n",
               "log.clf:2:", "RAWLASER1 carries no pose and the file has no ODOM line"},
        BadLog{"EmptyFile", "", "log.clf: ", "no laser scans"},
        BadLog{"OnlyOdometryAndParams", "PARAM a b 0 host 0\nODOM 1 2 3 0 0 0 5 host 5\n",
               "log.clf: ", "no laser scans"},
        BadLog{"OnlySkippedRearScans", old_laser("RLASER", 1, "1"),
               "log.clf: ", "1 RLASER lines were skipped"}),
    [](const ::testing::TestParamInfo<BadLog>& p) { return p.param.name; });

// ---- the real logs (../shared/data/laser) ----

TEST(CarmenLogData, IntelRawLogHas5505ScansWith265BackwardStamps) {
  const auto path = support::data_path("laser/intel/intel-raw-first5505-sot.clf");
  TESSERA_REQUIRE_DATA(path);
  const Result<LaserLog> log = read_carmen_log(path);
  ASSERT_TRUE(log.ok()) << log.error().message;
  ASSERT_EQ(log->scans.size(), 5505u);
  EXPECT_TRUE(log->odometry.empty());
  // SOURCES.md: 265 of the 5504 consecutive pairs are non-increasing; all 265 are strict.
  EXPECT_EQ(log->backward_stamps, 265);
  const StampedScan& first = log->scans.front();
  EXPECT_DOUBLE_EQ(first.t_s, 0.000246);
  ASSERT_EQ(first.scan.ranges_m.size(), 180u);
  EXPECT_DOUBLE_EQ(first.scan.ranges_m[0], 1.07);
  EXPECT_DOUBLE_EQ(first.scan.angle_increment_rad, kDeg);
  EXPECT_NEAR(first.scan.max_range_m, 81.73, 1e-9);  // 81.83 = no return
  const StampedScan& last = log->scans.back();
  EXPECT_DOUBLE_EQ(last.t_s, 1088.612556);
  EXPECT_DOUBLE_EQ(last.odometry.x, 7.542);  // raw odometry (SOURCES.md: about (7.544, 1.912))
  EXPECT_DOUBLE_EQ(last.odometry.y, 1.909);
}

TEST(CarmenLogData, IntelCorrectedLogHasCorrectedPosesAndOdometry) {
  const auto path = support::data_path("laser/intel/intel-corrected.log");
  TESSERA_REQUIRE_DATA(path);
  const Result<LaserLog> log = read_carmen_log(path);
  ASSERT_TRUE(log.ok()) << log.error().message;
  ASSERT_EQ(log->scans.size(), 910u);
  EXPECT_EQ(log->odometry.size(), 14541u);
  EXPECT_EQ(log->backward_stamps, 4);
  const StampedScan& first = log->scans.front();
  EXPECT_DOUBLE_EQ(first.t_s, 32.9068);
  EXPECT_DOUBLE_EQ(first.odometry.x, 0.600266);
  EXPECT_DOUBLE_EQ(first.odometry.theta, -0.354665);
  EXPECT_NEAR(first.laser_in_robot.x, 0.0, 1e-12);
  EXPECT_NEAR(first.laser_in_robot.theta, 0.0, 1e-12);
  EXPECT_NEAR(first.scan.max_range_m, 81.73, 1e-9);
}

TEST(CarmenLogData, Fr079CorrectedLogHas4791ScansOf360Beams) {
  const auto path = support::data_path("laser/fr079/freiburg-079-corrected.log");
  TESSERA_REQUIRE_DATA(path);
  const Result<LaserLog> log = read_carmen_log(path);
  ASSERT_TRUE(log.ok()) << log.error().message;
  ASSERT_EQ(log->scans.size(), 4791u);
  EXPECT_EQ(log->odometry.size(), 9725u);
  EXPECT_EQ(log->backward_stamps, 0);
  const StampedScan& first = log->scans.front();
  EXPECT_DOUBLE_EQ(first.t_s, 0.227623);
  ASSERT_EQ(first.scan.ranges_m.size(), 360u);
  EXPECT_DOUBLE_EQ(first.scan.angle_increment_rad, 0.5 * kDeg);
  EXPECT_NEAR(first.scan.max_range_m, 81.81, 1e-9);  // 81.91 = no return
}

TEST(CarmenLogData, Fr079RawHeadCarriesIpcStampsAndTheLaserOffset) {
  const auto path = support::data_path("laser/fr079/fr079-clf-head.clf");
  TESSERA_REQUIRE_DATA(path);
  const Result<LaserLog> log = read_carmen_log(path);
  ASSERT_TRUE(log.ok()) << log.error().message;
  ASSERT_EQ(log->scans.size(), 7u);
  EXPECT_EQ(log->odometry.size(), 15u);
  EXPECT_DOUBLE_EQ(log->scans[0].t_s, 1211.520329);  // ipc, the time base of fr079.relations
  EXPECT_DOUBLE_EQ(log->scans[0].odometry.x, -3.034287);
  for (const StampedScan& s : log->scans) {
    EXPECT_NEAR(s.laser_in_robot.x, -0.04, 1e-4);  // robot_frontlaser_offset -0.04
    EXPECT_NEAR(s.laser_in_robot.y, 0.0, 1e-4);
  }
}

}  // namespace
}  // namespace tessera
