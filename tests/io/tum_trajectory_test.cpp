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

}  // namespace
}  // namespace tessera
