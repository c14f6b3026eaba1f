#include "tessera/io/tum_trajectory.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <numbers>

namespace tessera {
namespace {

std::filesystem::path temp_file(const std::string& name) {
  return std::filesystem::temp_directory_path() /
         ("tessera_tum_" + std::to_string(::getpid()) + "_" + name);
}

TEST(TumTrajectory, WritesOneLinePerPoseWithAUnitQuaternionAboutZ) {
  const std::string text = encode_tum_trajectory({{1.5, {2.0, -3.0, std::numbers::pi / 2.0}}});
  EXPECT_THAT(text,
              ::testing::HasSubstr("1.500000 2.000000 -3.000000 0 0 0 0.707106781 0.707106781"));
}

TEST(TumTrajectory, RoundTripKeepsTimesPositionsAndHeadings) {
  const std::vector<StampedPose2> poses = {
      {0.0, {0.0, 0.0, 0.0}}, {1.0, {1.25, -0.5, 3.0}}, {2.0, {-4.0, 2.0, -2.5}}};
  const auto path = temp_file("roundtrip.txt");
  ASSERT_TRUE(write_tum_trajectory(path, poses).ok());
  const Result<std::vector<StampedPose2>> back = read_tum_trajectory(path);
  std::filesystem::remove(path);
  ASSERT_TRUE(back.ok()) << back.error().message;
  ASSERT_EQ(back->size(), poses.size());
  for (std::size_t i = 0; i < poses.size(); ++i) {
    EXPECT_NEAR((*back)[i].t_s, poses[i].t_s, 1e-6);
    EXPECT_NEAR((*back)[i].pose.x, poses[i].pose.x, 1e-6);
    EXPECT_NEAR((*back)[i].pose.y, poses[i].pose.y, 1e-6);
    EXPECT_NEAR(normalize_angle((*back)[i].pose.theta - poses[i].pose.theta), 0.0, 1e-8);
  }
}

TEST(TumTrajectory, MalformedLineNamesFileAndLine) {
  const auto path = temp_file("bad.txt");
  std::ofstream(path) << "# header\n0 0 0 0 0 0 0 1\n1 2 three\n";
  const Result<std::vector<StampedPose2>> r = read_tum_trajectory(path);
  std::filesystem::remove(path);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().kind, ErrorKind::kInput);
  EXPECT_THAT(r.error().message, ::testing::HasSubstr("bad.txt:3:"));
}

TEST(TumTrajectory, MissingFileIsAnInputError) {
  const Result<std::vector<StampedPose2>> r = read_tum_trajectory(temp_file("nope.txt"));
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().kind, ErrorKind::kInput);
}

TEST(TumTrajectory3, ReadsPositionsAndNormalisedQuaternionsInFileOrder) {
  const auto path = temp_file("three_d.txt");
  // TUM ground truth prints 4 decimals, so its quaternions are unit only to about 1e-4; commas and
  // tabs separate fields as the TUM tools accept.
  std::ofstream(path) << "# timestamp tx ty tz qx qy qz qw\n"
                         "1305031098.6659 1.3563 0.6305 1.6380 0.6132 0.5962 -0.3311 -0.3986\n"
                         "\n"
                         "2.5,1,2,3,0,0,0,1\n"
                         "2.0\t-1 -2 -3\t0 0 0.7071068 0.7071068\n";
  const Result<std::vector<StampedPose3>> r = read_tum_trajectory3(path);
  std::filesystem::remove(path);
  ASSERT_TRUE(r.ok()) << r.error().message;
  ASSERT_EQ(r->size(), 3u);
  EXPECT_DOUBLE_EQ((*r)[0].t_s, 1305031098.6659);
  EXPECT_DOUBLE_EQ((*r)[0].position_m.z(), 1.6380);
  EXPECT_NEAR((*r)[0].orientation.norm(), 1.0, 1e-15);
  EXPECT_NEAR((*r)[0].orientation.x(), 0.6132, 1e-4);
  EXPECT_NEAR((*r)[0].orientation.w(), -0.3986, 1e-4);
  EXPECT_DOUBLE_EQ((*r)[1].t_s, 2.5);  // file order, not sorted
  EXPECT_DOUBLE_EQ((*r)[2].position_m.y(), -2.0);
  EXPECT_NEAR((*r)[2].orientation.angularDistance(Eigen::Quaterniond(
                  Eigen::AngleAxisd(std::numbers::pi / 2.0, Eigen::Vector3d::UnitZ()))),
              0.0, 1e-6);
}

/// Writes `body` to a temporary file, reads it with read_tum_trajectory3 and returns the error.
std::string error_reading(const std::string& name, const std::string& body) {
  const auto path = temp_file(name);
  std::ofstream(path) << body;
  const Result<std::vector<StampedPose3>> r = read_tum_trajectory3(path);
  std::filesystem::remove(path);
  if (r.ok()) return "no error";
  EXPECT_EQ(r.error().kind, ErrorKind::kInput);
  return r.error().message;
}

TEST(TumTrajectory3, WrongFieldCountNamesFileLineAndCount) {
  EXPECT_THAT(error_reading("seven.txt", "0 0 0 0 0 0 0 1\n1 0 0 0 0 0 1\n"),
              ::testing::HasSubstr("seven.txt:2: expected 8 fields 't x y z qx qy qz qw', got 7"));
  EXPECT_THAT(error_reading("nine.txt", "# c\n0 0 0 0 0 0 0 1 5\n"),
              ::testing::HasSubstr("nine.txt:2: expected 8 fields"));
}

TEST(TumTrajectory3, NonNumericOrNonFiniteFieldIsNamed) {
  EXPECT_THAT(error_reading("word.txt", "0 0 0 0 zero 0 0 1\n"),
              ::testing::HasSubstr("word.txt:1: field qx must be a finite number, got 'zero'"));
  EXPECT_THAT(error_reading("trail.txt", "0 0 0 0 0 0 0 1x\n"),
              ::testing::HasSubstr("trail.txt:1: field qw"));
  EXPECT_THAT(error_reading("nan.txt", "0 nan 0 0 0 0 0 1\n"),
              ::testing::HasSubstr("nan.txt:1: field x must be a finite number"));
}

TEST(TumTrajectory3, NonUnitQuaternionIsRejected) {
  EXPECT_THAT(error_reading("zero_q.txt", "0 0 0 0 0 0 0 0\n"),
              ::testing::HasSubstr("zero_q.txt:1: quaternion (qx qy qz qw) must have norm 1"));
  EXPECT_THAT(error_reading("half_q.txt", "0 0 0 0 0 0 0 0.5\n"), ::testing::HasSubstr("got 0.5"));
}

TEST(TumTrajectory3, MissingFileIsAnInputError) {
  const Result<std::vector<StampedPose3>> r = read_tum_trajectory3(temp_file("nope3.txt"));
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().kind, ErrorKind::kInput);
  EXPECT_THAT(r.error().message, ::testing::HasSubstr("nope3.txt: no such file"));
}

TEST(TumTrajectory, PlanarReaderRejectsWhatTheFullReaderRejects) {
  const auto path = temp_file("planar_bad_q.txt");
  std::ofstream(path) << "0 0 0 0 0 0 0 0\n";
  const Result<std::vector<StampedPose2>> r = read_tum_trajectory(path);
  std::filesystem::remove(path);
  ASSERT_FALSE(r.ok());
  EXPECT_THAT(r.error().message, ::testing::HasSubstr("planar_bad_q.txt:1: quaternion"));
}

}  // namespace
}  // namespace tessera
