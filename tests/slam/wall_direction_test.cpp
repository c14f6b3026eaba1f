// The dominant wall direction of a scan (slam/wall_direction.hpp): a rectangular room's walls at
// any turn, folded modulo 90 degrees; nothing for a round room or broken runs.
#include "tessera/slam/wall_direction.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "tessera/core/rng.hpp"

namespace tessera::slam {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

struct Scan {
  std::vector<Vec2> points;
  std::vector<int> beams;
};

/// A 360-beam scan from the centre of a 6 x 4 m room turned by turn_rad, with range noise.
Scan room_scan(double turn_rad, double noise_m, std::uint64_t seed) {
  Rng rng(seed);
  Scan s;
  for (int b = 0; b < 360; ++b) {
    const double a = b * kDeg;
    // Ray in the room's frame, then the hit rotated into the sensor's.
    const double local = a - turn_rad;
    const double c = std::cos(local), sn = std::sin(local);
    const double tx = std::abs(c) > 1e-9 ? 3.0 / std::abs(c) : 1e9;
    const double ty = std::abs(sn) > 1e-9 ? 2.0 / std::abs(sn) : 1e9;
    const double r = std::min(tx, ty) + rng.gaussian(noise_m);
    s.points.push_back({r * std::cos(a), r * std::sin(a)});
    s.beams.push_back(b);
  }
  return s;
}

TEST(WallDirection, ARoomsWallsGiveItsTurnFoldedIntoAQuarterTurn) {
  for (const double turn_deg : {0.0, 20.0, -35.0, 60.0}) {
    const Scan s = room_scan(turn_deg * kDeg, 0.005, 1);
    const std::optional<WallDirection> d = dominant_wall_direction(s.points, s.beams, {});
    ASSERT_TRUE(d) << turn_deg;
    const double folded = turn_deg > 45.0 ? turn_deg - 90.0 : turn_deg;  // 60 -> -30
    EXPECT_NEAR(d->angle_rad, folded * kDeg, 0.5 * kDeg) << turn_deg;
    EXPECT_GT(d->strength, 0.8);
    EXPECT_GT(d->runs, 100);
  }
}

TEST(WallDirection, ARoundRoomHasNoDirection) {
  Scan s;
  for (int b = 0; b < 360; ++b) {
    s.points.push_back({2.0 * std::cos(b * kDeg), 2.0 * std::sin(b * kDeg)});
    s.beams.push_back(b);
  }
  // Runs of 7 beams on a 2 m circle are 24 cm arcs, straight to 2 mm: they vote, but for
  // every direction alike, so no peak holds 30 % of the votes.
  EXPECT_FALSE(dominant_wall_direction(s.points, s.beams, {}));
}

TEST(WallDirection, RunsNeverSpanADroppedBeam) {
  Scan s = room_scan(10.0 * kDeg, 0.0, 1);
  for (std::size_t i = 0; i < s.beams.size(); ++i) s.beams[i] = static_cast<int>(2 * i);
  EXPECT_FALSE(dominant_wall_direction(s.points, s.beams, {}));
  s.beams.pop_back();  // lengths differ
  EXPECT_FALSE(dominant_wall_direction(s.points, s.beams, {}));
}

TEST(WallDirection, ValidateNamesTheBrokenField) {
  EXPECT_FALSE(validate(WallDirectionOptions{}));
  WallDirectionOptions o;
  o.half_window = 0;
  EXPECT_NE(validate(o)->find("half_window"), std::string::npos);
  o = {};
  o.min_strength = 2.0;
  EXPECT_NE(validate(o)->find("min_strength"), std::string::npos);
}

}  // namespace
}  // namespace tessera::slam
