#pragma once
// Simulated laser runs with ground truth, for SLAM: a differential-drive robot with a 2D lidar
// drives a tour of a world (sim/tour.hpp) under speed and acceleration limits, and records what a
// real robot's log holds (sensors/laser_log.hpp): scans with range noise at the scan rate, each
// with the odometry pose of the moment, odometry drifting with a realistic error model
// (sensors/odometry_model.hpp). Beside the log it returns the true pose at every scan, so a SLAM
// run on the log can be scored (ATE) and its map compared with the world.
#include <cstdint>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "tessera/core/pose2.hpp"
#include "tessera/core/result.hpp"
#include "tessera/core/stamped_pose2.hpp"
#include "tessera/sensors/laser_log.hpp"
#include "tessera/sensors/lidar.hpp"
#include "tessera/sensors/odometry_model.hpp"
#include "tessera/sim/tour.hpp"
#include "tessera/sim/world.hpp"

namespace tessera {

struct LaserRunOptions {
  /// T_world_robot at the start; empty: random_start_pose (a random cell of the largest part of
  /// the world with room for the robot, random heading), drawn from the run's seed.
  std::optional<Pose2> start;
  TourOptions tour;
  /// Limits of the drive (a small indoor robot, e.g. a TurtleBot 2 drives 0.7 m/s at most).
  double max_speed_m_per_s = 0.5;
  double max_turn_rate_rad_per_s = 1.0;
  double max_acceleration_m_per_s2 = 0.5;
  double max_angular_acceleration_rad_per_s2 = 2.0;
  /// The run ends when the tour is done or at the first limit reached; 0: no limit.
  double max_duration_s = 300.0;
  double max_path_length_m = 0.0;
  /// Scans per second; the stamps are k / scan_rate_hz, the first scan at the start pose at t = 0.
  double scan_rate_hz = 10.0;
  /// Motion and odometry are integrated this many times between two scans.
  int steps_per_scan = 10;
  /// A 360-degree lidar of one beam per degree, 12 m range, 1 cm noise (RPLIDAR-A2 class).
  LidarOptions lidar{.beams = 360,
                     .fov_rad = 2.0 * std::numbers::pi,
                     .min_range_m = 0.0,
                     .max_range_m = 12.0,
                     .range_noise_stddev_m = 0.01};
  /// How long the lidar takes to sweep one scan's beams, one after the other while the robot
  /// moves (a 5 Hz spinning lidar: 0.2 s); at most a scan period. 0: every beam at the scan's
  /// stamp. Each scan then says when its beams were taken, and its robot_velocity comes from the
  /// odometry over its sweep, as a bag reader gives it (io/robot_bag.hpp).
  double lidar_sweep_s = 0.0;
  /// T_robot_laser: where the lidar sits on the robot (inside the robot: |offset| < clearance_m).
  Pose2 laser_in_robot;
  OdometryErrorOptions odometry;
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const LaserRunOptions& o);

struct SimulatedLaserRun {
  /// The log as a robot records it: one StampedScan per scan (stamp, odometry pose, laser_in_robot,
  /// scan in the sensor frame) and one OdometryReading per scan with the same stamp and pose. The
  /// odometry frame is the world frame at the start (odometry starts at the true start pose), so
  /// the odometry poses and `truth` compare directly, without alignment.
  LaserLog log;
  /// T_world_robot at each scan's stamp (same length and stamps as log.scans).
  std::vector<StampedPose2> truth;
  /// The route the robot drove (it stops early when a limit is reached).
  Tour tour;
  double path_length_m = 0.0;   // distance driven until the last scan
  double turned_rad = 0.0;      // sum of |heading change| until the last scan
  double duration_s = 0.0;      // stamp of the last scan
  bool tour_completed = false;  // false when max_duration_s or max_path_length_m cut it short
};

/// Plans the tour from the start and drives it, recording scans and odometry.
///
/// Motion: the robot follows the route's lines, arcs and turns in place exactly (a perfect
/// tracking controller: all the error is in what odometry reports, none in where the robot goes),
/// with trapezoidal speed profiles under the speed, turn-rate and acceleration limits; on an arc
/// the speed is at most max_turn_rate * radius, and it comes to rest before each turn in place.
/// Odometry: each integration step's true motion goes through noisy_odometry_increment and is
/// composed onto the odometry pose. Scans: taken at each stamp from truth * laser_in_robot (beam by
/// beam over lidar_sweep_s from the stamp on, each from where the robot then is); each beam is
/// World::cast_ray plus Gaussian noise truncated at 3 sigma, clamped to [0, max_range_m], and a
/// beam that hits nothing reports exactly max_range_m ("no return"), as Simulator::scan does.
///
/// Deterministic for a seed: the start, the odometry noise and the range noise draw from
/// Rng(seed).fork(0), fork(1) and fork(2).
/// Input errors: invalid options ("laser run options: <what is wrong>"), and whatever
/// random_start_pose and plan_tour report (no room for the robot, a bad start).
/// Cost: the tour (see plan_tour) plus O(scans * beams * max_range / resolution).
[[nodiscard]] Result<SimulatedLaserRun> simulate_laser_run(const World& world,
                                                           const LaserRunOptions& options,
                                                           std::uint64_t seed);

class LaserRunState;  // the drive, the noise streams and the poses (internal)

/// The same run as a step machine: create() plans the tour and records the first scan at the
/// start; each step() drives one scan period and records the next scan, until done() (the tour is
/// driven, or the next scan would pass max_duration_s, or max_path_length_m is driven). The world
/// is outside: it must outlive the object. simulate_laser_run is create() and step() to the end.
class LaserRun {
 public:
  /// Errors: those of simulate_laser_run.
  [[nodiscard]] static Result<LaserRun> create(const World& world, const LaserRunOptions& options,
                                               std::uint64_t seed);
  LaserRun(LaserRun&&) noexcept;
  LaserRun& operator=(LaserRun&&) noexcept;
  ~LaserRun();

  [[nodiscard]] bool done() const;
  /// Drives one scan period and records its scan. Precondition: !done().
  void step();
  /// The log, truth and tour so far (tour_completed is set once done()).
  [[nodiscard]] const SimulatedLaserRun& run() const;
  /// The run, leaving the object empty.
  [[nodiscard]] SimulatedLaserRun take_run() &&;

 private:
  explicit LaserRun(std::unique_ptr<LaserRunState> state);
  std::unique_ptr<LaserRunState> state_;
};

}  // namespace tessera
