#include "tessera/slam/motion_filter.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace tessera::slam {
namespace {

TEST(MotionFilter, KeepsTheFirstPoseAndThenOnlyEnoughMotionOrTime) {
  MotionFilter filter(MotionFilterOptions{5.0, 0.2, 0.02});
  EXPECT_FALSE(filter.is_similar(0.0, {}));
  EXPECT_TRUE(filter.is_similar(1.0, {0.1, 0.0, 0.01}));
  EXPECT_FALSE(filter.is_similar(2.0, {0.25, 0.0, 0.0}));   // moved 0.25 m
  EXPECT_FALSE(filter.is_similar(3.0, {0.25, 0.0, 0.05}));  // turned 0.05 rad
  EXPECT_FALSE(filter.is_similar(9.0, {0.25, 0.0, 0.05}));  // 6 s later
  EXPECT_TRUE(filter.is_similar(8.5, {0.25, 0.0, 0.05})) << "stamps may go backwards a little";
}

TEST(MotionFilterOptions, BrokenFieldsAreNamed) {
  EXPECT_FALSE(validate(MotionFilterOptions{}).has_value());
  EXPECT_THAT(validate(MotionFilterOptions{-1.0, 0.2, 0.01}).value_or(""),
              ::testing::HasSubstr("max_time_s"));
}

}  // namespace
}  // namespace tessera::slam
