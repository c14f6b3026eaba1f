// RangeScan: mirrored() (the scan of an upside-down sensor as seen from above, io/tf_tree.hpp's
// PlanarLaser), its beams' times, and sweep_velocity (sensors/scan_sweep.hpp).
#include "tessera/sensors/range_scan.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tessera/sensors/scan_sweep.hpp"

namespace tessera {
namespace {

TEST(RangeScan, AMirroredScanHasItsBeamAnglesNegated) {
  const RangeScan scan{-0.5, 0.25, 0.1, 10.0, {1.0, 2.0, 3.0, 4.0, 5.0}};
  const RangeScan m = mirrored(scan);
  ASSERT_EQ(m.ranges_m.size(), 5u);
  for (std::size_t i = 0; i < 5; ++i) {
    const double angle = m.angle_min_rad + m.angle_increment_rad * static_cast<double>(i);
    const double original =
        scan.angle_min_rad + scan.angle_increment_rad * static_cast<double>(4 - i);
    EXPECT_NEAR(angle, -original, 1e-12);
    EXPECT_EQ(m.ranges_m[i], scan.ranges_m[4 - i]);
  }
  const RangeScan back = mirrored(m);
  EXPECT_NEAR(back.angle_min_rad, scan.angle_min_rad, 1e-12);
  EXPECT_EQ(back.ranges_m, scan.ranges_m);
  EXPECT_TRUE(mirrored(RangeScan{}).ranges_m.empty());
}

// A swept scan's beams keep their own times when the scan is mirrored (or put in the other
// order), and mirroring twice gives the times back.
TEST(RangeScan, MirroringKeepsEachBeamsTime) {
  RangeScan scan{-0.5, 0.25, 0.1, 10.0, {1.0, 2.0, 3.0, 4.0, 5.0}};
  scan.time_increment_s = 0.01;
  const RangeScan m = mirrored(scan);
  for (std::size_t i = 0; i < 5; ++i) {
    EXPECT_NEAR(beam_time_s(m, i), beam_time_s(scan, 4 - i), 1e-15);
  }
  EXPECT_NEAR(m.first_beam_s, 0.04, 1e-15);
  const RangeScan back = mirrored(m);
  EXPECT_NEAR(back.first_beam_s, 0.0, 1e-15);
  EXPECT_NEAR(back.time_increment_s, 0.01, 1e-15);
  // A scan taken at once stays so (and without a negative zero).
  const RangeScan at_once = mirrored(RangeScan{-0.5, 0.25, 0.1, 10.0, {1.0, 2.0}});
  EXPECT_FALSE(std::signbit(at_once.time_increment_s));
  EXPECT_EQ(beam_time_s(at_once, 1), 0.0);
}

// sweep_velocity: the odometry's motion over the sweep, from the first beam in time to the last,
// whichever order the beams are in; nothing without beam times.
TEST(ScanSweep, TheVelocityIsTheOdometrysMotionOverTheSweep) {
  RangeScan scan{0.0, 0.1, 0.1, 10.0, std::vector<double>(11, 1.0)};
  scan.time_increment_s = 0.02;  // a 0.2 s sweep
  // Odometry driving 0.5 m/s and turning 1 rad/s, read at its own instants: the pose dt after
  // the stamp (the stamp 10 s into the drive).
  const Twist2 truth{0.5, 0.0, 1.0};
  const auto odometry = [&](double dt_s) { return displacement(truth, 10.0 + dt_s); };
  const Twist2 v = sweep_velocity(scan, odometry);
  EXPECT_NEAR(v.vx_m_per_s, 0.5, 1e-9);
  EXPECT_NEAR(v.vy_m_per_s, 0.0, 1e-9);
  EXPECT_NEAR(v.omega_rad_per_s, 1.0, 1e-9);
  const Twist2 reversed = sweep_velocity(mirrored(scan), odometry);
  EXPECT_NEAR(reversed.omega_rad_per_s, 1.0, 1e-9);
  scan.time_increment_s = 0.0;
  EXPECT_TRUE(sweep_velocity(scan, odometry).is_zero());
}

}  // namespace
}  // namespace tessera
