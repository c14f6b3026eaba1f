#include "tessera/sim/rgbd_run.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "tessera/core/angle.hpp"
#include "tessera/core/assert.hpp"
#include "tessera/core/rng.hpp"
#include "tessera/sim/differential_drive.hpp"

namespace tessera {
namespace {

/// Rng streams of a run, one per purpose.
constexpr std::uint64_t kOdometryStream = 1;
constexpr std::uint64_t kCameraStream = 2;

constexpr double kMaxFrameRateHz = 1000.0;
constexpr int kMaxStepsPerFrame = 1000;
/// The controller turns in place until the heading error is below kAlignedRad, and goes back to
/// turning in place when it grows beyond kMisalignedRad while driving.
constexpr double kAlignedRad = 0.01;
constexpr double kMisalignedRad = 0.3;
/// Heading correction while driving: w = kHeadingGain * error, off within kNoSteerM of the goal.
constexpr double kHeadingGain = 2.0;
constexpr double kNoSteerM = 0.05;

bool positive(double v) { return v > 0.0 && std::isfinite(v); }

std::string point_text(Vec2 p) {
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "(%.3f, %.3f)", p.x, p.y);
  return buffer;
}

/// Input error when the straight leg a -> b passes closer than clearance_m to a wall.
std::optional<std::string> leg_problem(const World& world, Vec2 a, Vec2 b, double clearance_m) {
  const double length_m = (b - a).norm();
  const double step_m = 0.25 * world.geometry().resolution_m();
  const int n = std::max(1, static_cast<int>(std::ceil(length_m / step_m)));
  for (int i = 0; i <= n; ++i) {
    const Vec2 p = a + (b - a) * (static_cast<double>(i) / n);
    if (world.distance_to_solid(p, clearance_m) < clearance_m) {
      return "the leg from " + point_text(a) + " passes within " + std::to_string(clearance_m) +
             " m of a wall at " + point_text(p);
    }
  }
  return std::nullopt;
}

/// The waypoint driver: turn in place, then drive straight and stop at the waypoint.
class WaypointDriver {
 public:
  WaypointDriver(const std::vector<Vec2>& waypoints, const RgbdRunOptions& o)
      : waypoints_(waypoints), o_(o) {}

  [[nodiscard]] bool done() const { return next_ >= waypoints_.size(); }

  /// The command (v, w) for the next dt_s from the true pose.
  void command(const Pose2& pose, double dt_s, double& v, double& w) {
    v = 0.0;
    w = 0.0;
    while (!done()) {
      const Vec2 delta = waypoints_[next_] - pose.translation();
      const double distance = delta.norm();
      if (distance > o_.waypoint_tolerance_m) break;
      ++next_;
      turning_ = true;
    }
    if (done()) {
      v_ = w_ = 0.0;
      return;
    }
    const Vec2 delta = waypoints_[next_] - pose.translation();
    const double distance = delta.norm();
    const double error = normalize_angle(std::atan2(delta.y, delta.x) - pose.theta);
    if (!turning_ && std::abs(error) > kMisalignedRad && distance > kNoSteerM) turning_ = true;
    if (turning_) {
      // Brake the forward motion first, then turn with a braking-aware rate.
      v_ = std::max(0.0, v_ - o_.max_acceleration_m_per_s2 * dt_s);
      const double alpha = o_.max_angular_acceleration_rad_per_s2;
      const double reachable = std::sqrt(2.0 * alpha * std::abs(error));
      const double target =
          std::copysign(std::min({o_.max_turn_rate_rad_per_s, reachable,
                                  std::abs(error) / dt_s}),
                        error);
      w_ = std::clamp(target, w_ - alpha * dt_s, w_ + alpha * dt_s);
      if (v_ == 0.0 && std::abs(error) < kAlignedRad &&
          std::abs(w_) <= alpha * dt_s + 1e-12) {
        turning_ = false;
        w_ = 0.0;
      }
    } else {
      const double a = o_.max_acceleration_m_per_s2;
      const double brake = std::sqrt(2.0 * a * distance);
      v_ = std::min({v_ + a * dt_s, o_.max_speed_m_per_s, brake, distance / dt_s});
      w_ = distance > kNoSteerM
               ? std::clamp(kHeadingGain * error, -o_.max_turn_rate_rad_per_s,
                            o_.max_turn_rate_rad_per_s)
               : 0.0;
    }
    v = v_;
    w = w_;
  }

 private:
  const std::vector<Vec2>& waypoints_;
  const RgbdRunOptions& o_;
  std::size_t next_ = 0;
  bool turning_ = true;
  double v_ = 0.0;
  double w_ = 0.0;
};

}  // namespace

std::optional<std::string> validate(const RgbdRunOptions& o) {
  if (!std::isfinite(o.start.x) || !std::isfinite(o.start.y) || !std::isfinite(o.start.theta)) {
    return "start must be finite";
  }
  for (std::size_t i = 0; i < o.waypoints_m.size(); ++i) {
    if (!std::isfinite(o.waypoints_m[i].x) || !std::isfinite(o.waypoints_m[i].y)) {
      return "waypoint " + std::to_string(i) + " must be finite";
    }
  }
  if (auto p = validate(o.tour)) return "tour: " + *p;
  if (!positive(o.max_speed_m_per_s)) return "max_speed_m_per_s must be > 0";
  if (!positive(o.max_turn_rate_rad_per_s)) return "max_turn_rate_rad_per_s must be > 0";
  if (!positive(o.max_acceleration_m_per_s2)) return "max_acceleration_m_per_s2 must be > 0";
  if (!positive(o.max_angular_acceleration_rad_per_s2)) {
    return "max_angular_acceleration_rad_per_s2 must be > 0";
  }
  if (!positive(o.waypoint_tolerance_m)) return "waypoint_tolerance_m must be > 0";
  if (!(positive(o.frame_rate_hz) && o.frame_rate_hz <= kMaxFrameRateHz)) {
    return "frame_rate_hz must be in (0, 1000], got " + std::to_string(o.frame_rate_hz);
  }
  if (o.steps_per_frame < 1 || o.steps_per_frame > kMaxStepsPerFrame) {
    return "steps_per_frame must be in [1, 1000], got " + std::to_string(o.steps_per_frame);
  }
  if (!positive(o.max_duration_s)) return "max_duration_s must be > 0";
  if (!std::isfinite(o.neck_pan_rad) || !std::isfinite(o.neck_sweep_amplitude_rad) ||
      std::abs(o.neck_pan_rad) + std::abs(o.neck_sweep_amplitude_rad) >
          0.5 * std::numbers::pi + 1e-9) {
    return "|neck_pan_rad| + |neck_sweep_amplitude_rad| must be <= pi / 2 (a 180-degree neck)";
  }
  if (!positive(o.neck_sweep_period_s)) return "neck_sweep_period_s must be > 0";
  if (auto p = validate(o.odometry)) return "odometry: " + *p;
  return std::nullopt;
}

Result<SimulatedRgbdRun> simulate_rgbd_run(const World& world, const RgbdRunOptions& o,
                                           std::uint64_t seed) {
  if (auto problem = validate(o)) return input_error("rgbd run options: " + *problem);
  SimulatedRgbdRun run;
  run.seed = seed;
  Pose2 start = o.start;
  start.theta = normalize_angle(start.theta);
  if (o.waypoints_m.empty()) {
    Result<Tour> tour = plan_tour(world, start, o.tour);
    if (!tour) return tour.error();
    if (tour->polyline_m.size() > 1) {
      run.waypoints_m.assign(tour->polyline_m.begin() + 1, tour->polyline_m.end());
    }
  } else {
    run.waypoints_m = o.waypoints_m;
    const double clearance = o.tour.clearance_m;
    if (world.distance_to_solid(start.translation(), clearance) < clearance) {
      return input_error("rgbd run: start " + point_text(start.translation()) +
                         " is closer than clearance_m = " + std::to_string(clearance) +
                         " m to a wall");
    }
    Vec2 from = start.translation();
    for (std::size_t i = 0; i < run.waypoints_m.size(); ++i) {
      if (auto p = leg_problem(world, from, run.waypoints_m[i], clearance)) {
        return input_error("rgbd run: waypoint " + std::to_string(i) + " " +
                           point_text(run.waypoints_m[i]) + ": " + *p);
      }
      from = run.waypoints_m[i];
    }
  }

  const Rng root(seed);
  DifferentialDriveRobot robot(start, o.odometry, root.fork(kOdometryStream));
  WaypointDriver driver(run.waypoints_m, o);
  const double dt_s = 1.0 / (o.frame_rate_hz * o.steps_per_frame);
  const auto record = [&](std::int64_t k) {
    const double t_s = static_cast<double>(k) / o.frame_rate_hz;
    const double pan = o.neck_pan_rad + o.neck_sweep_amplitude_rad *
                                            std::sin(2.0 * std::numbers::pi * t_s /
                                                     o.neck_sweep_period_s);
    run.frames.push_back({t_s, robot.true_pose(), robot.odometry_pose(), pan});
    run.duration_s = t_s;
    run.path_length_m = robot.path_length_m();
    run.turned_rad = robot.turned_rad();
  };
  std::int64_t frame = 0;
  record(frame);
  while (!driver.done()) {
    const double next_t_s = static_cast<double>(frame + 1) / o.frame_rate_hz;
    if (next_t_s > o.max_duration_s) break;
    for (int k = 0; k < o.steps_per_frame; ++k) {
      double v = 0.0, w = 0.0;
      driver.command(robot.true_pose(), dt_s, v, w);
      (void)robot.step(v, w, dt_s);
    }
    record(++frame);
  }
  // The last waypoint may be reached within the last interval without the driver noticing yet.
  double v = 0.0, w = 0.0;
  driver.command(robot.true_pose(), dt_s, v, w);
  run.completed = driver.done();
  return run;
}

RgbdFrame render_rgbd_run_frame(const RgbdCamera& camera, const SimulatedRgbdRun& run,
                                std::size_t i) {
  TESSERA_ASSERT(i < run.frames.size());
  Rng rng = Rng(run.seed).fork(kCameraStream).fork(i);
  const RgbdRunFrame& f = run.frames[i];
  return camera.render(f.truth, f.neck_pan_rad, f.t_s, rng);
}

}  // namespace tessera
