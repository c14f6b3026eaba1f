#pragma once
// Simulated RGB-D runs with ground truth, for the fusion SLAM (issue 5): a differential-drive robot
// (sim/differential_drive.hpp) drives a list of waypoints, or a tour of the world (sim/tour.hpp),
// and records at a frame rate what the thesis' robot records: an RGB-D frame from the Kinect on
// its neck (sim/rgbd_camera.hpp), the wheel-odometry pose (drifting like the thesis' robot by
// default, sensors/thesis_odometry.hpp), the neck angle, and beside them the true pose.
//
// Frames are not kept in memory (a 640 x 480 frame is 2.1 MB; a run has thousands): the run holds
// the poses and angles, and render_rgbd_run_frame renders frame i on demand, the same every time.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tessera/core/pose2.hpp"
#include "tessera/core/result.hpp"
#include "tessera/core/vec2.hpp"
#include "tessera/sensors/odometry_model.hpp"
#include "tessera/sensors/rgbd_frame.hpp"
#include "tessera/sensors/thesis_odometry.hpp"
#include "tessera/sim/rgbd_camera.hpp"
#include "tessera/sim/tour.hpp"
#include "tessera/sim/world.hpp"

namespace tessera {

struct RgbdRunOptions {
  /// T_world_robot at the start.
  Pose2 start;
  /// Where to drive, in order, in straight lines (turning in place towards each). Empty: the
  /// corners of plan_tour(world, start, tour) (its string-pulled polyline).
  std::vector<Vec2> waypoints_m;
  /// The tour when waypoints_m is empty; its clearance_m also bounds how close the straight legs
  /// between waypoints may pass a wall.
  TourOptions tour;
  /// A cautious indoor drive (the P3-DX of the thesis reaches 1.6 m/s, section 3.1.1).
  double max_speed_m_per_s = 0.3;
  double max_turn_rate_rad_per_s = 0.5;
  double max_acceleration_m_per_s2 = 0.3;
  double max_angular_acceleration_rad_per_s2 = 1.0;
  /// A waypoint is reached within this distance.
  double waypoint_tolerance_m = 0.02;
  /// Frames per second; the stamps are k / frame_rate_hz, frame 0 at the start at t = 0.
  double frame_rate_hz = 5.0;
  /// The controller and odometry run this many times between two frames.
  int steps_per_frame = 20;
  /// The run ends when the last waypoint is reached or at this time.
  double max_duration_s = 600.0;
  /// The neck: pan(t) = neck_pan_rad + neck_sweep_amplitude_rad * sin(2 pi t / neck_sweep_period_s)
  /// (thesis section 3.1.3: a 180-degree servo, so |pan| <= pi / 2).
  double neck_pan_rad = 0.0;
  double neck_sweep_amplitude_rad = 0.0;
  double neck_sweep_period_s = 10.0;
  /// The thesis' drift by default.
  OdometryErrorOptions odometry = thesis_fusion_odometry();
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const RgbdRunOptions& o);

/// One recorded frame's poses: T_world_robot true and as odometry reports it (the odometry frame
/// is the world frame at the start), and the neck's pan angle.
struct RgbdRunFrame {
  double t_s = 0.0;
  Pose2 truth;
  Pose2 odometry;
  double neck_pan_rad = 0.0;
};

struct SimulatedRgbdRun {
  std::vector<RgbdRunFrame> frames;
  /// The waypoints driven to (given, or the tour's corners).
  std::vector<Vec2> waypoints_m;
  double path_length_m = 0.0;  // distance driven until the last frame
  double turned_rad = 0.0;     // angle turned until the last frame
  double duration_s = 0.0;     // stamp of the last frame
  bool completed = false;      // false when max_duration_s cut the run short
  /// The run's seed; frame rendering draws its depth noise from it.
  std::uint64_t seed = 0;
};

/// Drives the waypoints and records the frames' poses.
///
/// Controller (on the true pose, a perfect tracker as in sim/laser_run.hpp): turn in place towards
/// the next waypoint until the heading error is below 0.01 rad, then drive straight with a small
/// heading correction, speeding up and braking within the acceleration limits so that it stops at
/// the waypoint. Input errors: invalid options ("rgbd run options: <what>"), a start or a leg that
/// comes closer than tour.clearance_m to a wall ("rgbd run: waypoint 3 (x, y): the leg from (x, y)
/// passes within 0.25 m of a wall"), and plan_tour's errors. Deterministic for a seed (odometry
/// noise from Rng(seed).fork(1)). Cost: O(duration * frame_rate * steps_per_frame).
[[nodiscard]] Result<SimulatedRgbdRun> simulate_rgbd_run(const World& world,
                                                         const RgbdRunOptions& options,
                                                         std::uint64_t seed);

/// Frame i of the run, rendered at the true pose and neck angle; its depth noise comes from
/// Rng(run.seed).fork(2).fork(i), so frame i is the same whenever and in whatever order it is
/// rendered. Precondition: i < run.frames.size(). Cost: one RgbdCamera::render.
[[nodiscard]] RgbdFrame render_rgbd_run_frame(const RgbdCamera& camera, const SimulatedRgbdRun& run,
                                              std::size_t i);

}  // namespace tessera
