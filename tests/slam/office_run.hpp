#pragma once
// The simulated office run the laser SLAM tests share (laser_slam_test,
// scan_matched_odometry_test).
#include <gtest/gtest.h>

#include <cstdint>
#include <utility>

#include "tessera/sim/builtin_world.hpp"
#include "tessera/sim/laser_run.hpp"

namespace tessera::slam::testing {

/// A short simulated run through the built-in office (0.1 m cells) that comes back to its start:
/// 180-beam lidar, 5 scans per second, odometry drifting 0.01 rad per metre. Kept small: the
/// suite also runs under AddressSanitizer. The run starts next to a wall with beams 2 degrees
/// apart: without joining neighbouring returns in the submaps (RangeInsertOptions) its first
/// matches snapped to the beam spacing and the whole map came out turned by 1.5 degrees.
inline LaserRunOptions office_run_options(double scan_rate_hz) {
  LaserRunOptions o;
  o.lidar.beams = 180;
  o.lidar.max_range_m = 10.0;
  o.scan_rate_hz = scan_rate_hz;
  o.max_duration_s = 70.0;
  return o;
}

/// That run with these options (office_run_options, changed as a test needs).
inline SimulatedLaserRun simulate_office(const LaserRunOptions& o, std::uint64_t seed = 7) {
  Result<SimulatedLaserRun> r = simulate_laser_run(builtin_world("office", 0.1), o, seed);
  EXPECT_TRUE(r.ok()) << r.error().message;
  return std::move(r).value();
}

inline SimulatedLaserRun simulate_office(double scan_rate_hz, const OdometryErrorOptions& odometry,
                                         std::uint64_t seed = 7) {
  LaserRunOptions o = office_run_options(scan_rate_hz);
  o.odometry = odometry;
  return simulate_office(o, seed);
}

inline const SimulatedLaserRun& office_run() {
  static const SimulatedLaserRun run = [] {
    OdometryErrorOptions odometry;
    odometry.heading_drift_rad_per_m = 0.01;
    return simulate_office(5.0, odometry);
  }();
  return run;
}

}  // namespace tessera::slam::testing
