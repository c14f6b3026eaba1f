#include "tessera/sim/ir_layout.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace tessera {
namespace {

TEST(IrLayout, SnowplowLayoutMatchesThePapersRanges) {
  const std::array<IrMount, 5> m = snowplow_layout(SnowplowLayoutOptions{});
  EXPECT_EQ(m[0].id, IrSensorId::kI);
  EXPECT_EQ(m[4].id, IrSensorId::kJ);
  // BOBMapping 4.3: lateral cells need 25 cm, beams k and m need 48 cm.
  EXPECT_NEAR(m[0].needed_range_m, 0.255, 1e-12);
  EXPECT_NEAR(m[1].needed_range_m, 0.4827, 1e-4);
  EXPECT_NEAR(m[3].needed_range_m, 0.4827, 1e-4);
  EXPECT_FALSE(m[0].front);
  EXPECT_TRUE(m[2].front);
}

TEST(IrLayout, KAndMPointAtTheFarVerticesOfTheSecondCellAhead) {
  const SnowplowLayoutOptions o;
  const std::array<IrMount, 5> m = snowplow_layout(o);
  for (const int idx : {1, 3}) {
    const Pose2& s = m[static_cast<std::size_t>(idx)].T_robot_sensor;
    const double r = m[static_cast<std::size_t>(idx)].needed_range_m;
    const Vec2 tip = s * Vec2{r, 0.0};
    EXPECT_NEAR(tip.x, 2.5 * o.cell_m, 1e-12);
    EXPECT_NEAR(std::abs(tip.y), 0.5 * o.cell_m, 1e-12);
  }
  EXPECT_GT(m[1].T_robot_sensor.theta, 0.0);  // k to the left, m to the right
  EXPECT_LT(m[3].T_robot_sensor.theta, 0.0);
  EXPECT_NEAR(m[1].T_robot_sensor.theta, 0.2299, 1e-4);
  EXPECT_DOUBLE_EQ(m[2].T_robot_sensor.theta, 0.0);
}

TEST(IrLayout, LateralSensorsFaceSidewaysFromTheFrontCorners) {
  const std::array<IrMount, 5> m = snowplow_layout(SnowplowLayoutOptions{});
  EXPECT_NEAR(m[0].T_robot_sensor.theta, 0.5 * std::numbers::pi, 1e-12);
  EXPECT_NEAR(m[4].T_robot_sensor.theta, -0.5 * std::numbers::pi, 1e-12);
  EXPECT_DOUBLE_EQ(m[0].T_robot_sensor.x, 0.08);
  EXPECT_DOUBLE_EQ(m[0].T_robot_sensor.y, 0.075);
}

TEST(IrLayout, ARobotLargerThanTheCellIsRejected) {
  SnowplowLayoutOptions o;
  o.cell_m = 0.15;
  EXPECT_TRUE(validate(o).has_value());
  EXPECT_FALSE(validate(SnowplowLayoutOptions{}).has_value());
}

}  // namespace
}  // namespace tessera
