#include "tessera/sim/laser_run.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "tessera/core/angle.hpp"
#include "tessera/core/assert.hpp"
#include "tessera/core/pose_interpolation.hpp"
#include "tessera/core/rng.hpp"
#include "tessera/sensors/scan_sweep.hpp"
#include "tessera/sim/lidar_scan.hpp"

namespace tessera {
namespace {

/// Rng streams of a run, one per purpose (adding a draw to one does not change the others).
constexpr std::uint64_t kStartStream = 0;
constexpr std::uint64_t kOdometryStream = 1;
constexpr std::uint64_t kLidarStream = 2;

/// Upper bounds that catch unit mistakes (a rate in Hz given in ms, a speed in cm/s).
constexpr double kMaxScanRateHz = 1000.0;
constexpr int kMaxStepsPerScan = 1000;

bool positive(double v) { return v > 0.0 && std::isfinite(v); }
bool non_negative(double v) { return v >= 0.0 && std::isfinite(v); }

/// Where the robot is along the route, and how fast it goes.
struct DriveState {
  std::size_t piece = 0;
  double progress = 0.0;  // metres (line, arc) or radians (turn) into the piece
  double speed = 0.0;     // m/s on a line or arc, rad/s in a turn
};

/// Trapezoidal speed profiles along the route. Each piece has a top speed (v_max on a line,
/// min(v_max, w_max * radius) on an arc, w_max in a turn) and a speed it may leave with: 0 before
/// and after a turn in place and at the end; between two driving pieces the lower of their top
/// speeds, lowered further so the robot can still brake for what follows (a backward pass).
class SpeedProfile {
 public:
  SpeedProfile(const std::vector<RoutePiece>& pieces, const LaserRunOptions& o)
      : pieces_(pieces), top_(pieces.size()), exit_(pieces.size()), o_(o) {
    for (std::size_t k = 0; k < pieces.size(); ++k) {
      const RoutePiece& p = pieces[k];
      if (p.kind == RoutePiece::Kind::kTurn) {
        top_[k] = o.max_turn_rate_rad_per_s;
      } else if (p.kind == RoutePiece::Kind::kArc) {
        top_[k] = std::min(o.max_speed_m_per_s,
                           o.max_turn_rate_rad_per_s / std::abs(p.curvature_1_per_m));
      } else {
        top_[k] = o.max_speed_m_per_s;
      }
    }
    double next_entry = 0.0;  // the fastest the next piece may be entered; 0 after the last
    for (std::size_t k = pieces.size(); k-- > 0;) {
      const bool turn = pieces[k].kind == RoutePiece::Kind::kTurn;
      const bool next_turn =
          k + 1 == pieces.size() || pieces[k + 1].kind == RoutePiece::Kind::kTurn;
      exit_[k] = turn || next_turn ? 0.0 : std::min({top_[k], top_[k + 1], next_entry});
      next_entry = turn ? 0.0
                        : std::min(top_[k], std::sqrt(exit_[k] * exit_[k] +
                                                      2.0 * o.max_acceleration_m_per_s2 *
                                                          pieces[k].extent()));
    }
  }

  [[nodiscard]] bool done(const DriveState& s) const { return s.piece >= pieces_.size(); }

  /// Advances the state by dt_s: speed up by at most the acceleration limit, never faster than
  /// the piece's top speed or than allows braking to its exit speed, then move along the route.
  /// A step that reaches a piece's end goes on into the next piece for the rest of its time, at
  /// no more than that piece's top speed; a turn in place starts and ends at rest (the little left
  /// of such a step is not used).
  void step(DriveState& s, double dt_s) const {
    if (done(s)) return;
    const RoutePiece& p = pieces_[s.piece];
    const double accel = p.kind == RoutePiece::Kind::kTurn ? o_.max_angular_acceleration_rad_per_s2
                                                           : o_.max_acceleration_m_per_s2;
    const double left = p.extent() - s.progress;
    const double brake = std::sqrt(exit_[s.piece] * exit_[s.piece] + 2.0 * accel * left);
    s.speed = std::min({s.speed + accel * dt_s, top_[s.piece], brake});
    double time_s = dt_s;
    while (!done(s)) {
      const RoutePiece& q = pieces_[s.piece];
      const double rest = q.extent() - s.progress;
      if (s.speed * time_s < rest) {
        s.progress += s.speed * time_s;
        return;
      }
      if (s.speed > 0.0) time_s = std::max(0.0, time_s - rest / s.speed);
      const bool was_turn = q.kind == RoutePiece::Kind::kTurn;
      ++s.piece;
      s.progress = 0.0;
      if (done(s)) return;
      if (was_turn || pieces_[s.piece].kind == RoutePiece::Kind::kTurn) {
        s.speed = 0.0;
        return;
      }
      s.speed = std::min(s.speed, top_[s.piece]);
    }
  }

  [[nodiscard]] Pose2 pose(const DriveState& s, const Pose2& start) const {
    if (pieces_.empty()) return start;
    if (done(s)) return pieces_.back().end();
    return pieces_[s.piece].pose_at(s.progress);
  }

 private:
  const std::vector<RoutePiece>& pieces_;
  std::vector<double> top_;
  std::vector<double> exit_;
  const LaserRunOptions& o_;
};

}  // namespace

std::optional<std::string> validate(const LaserRunOptions& o) {
  if (auto p = validate(o.tour)) return "tour: " + *p;
  if (!positive(o.max_speed_m_per_s)) {
    return "max_speed_m_per_s must be > 0, got " + std::to_string(o.max_speed_m_per_s);
  }
  if (!positive(o.max_turn_rate_rad_per_s)) {
    return "max_turn_rate_rad_per_s must be > 0, got " + std::to_string(o.max_turn_rate_rad_per_s);
  }
  if (!positive(o.max_acceleration_m_per_s2)) {
    return "max_acceleration_m_per_s2 must be > 0, got " +
           std::to_string(o.max_acceleration_m_per_s2);
  }
  if (!positive(o.max_angular_acceleration_rad_per_s2)) {
    return "max_angular_acceleration_rad_per_s2 must be > 0, got " +
           std::to_string(o.max_angular_acceleration_rad_per_s2);
  }
  if (!non_negative(o.max_duration_s)) {
    return "max_duration_s must be >= 0 (0: no limit), got " + std::to_string(o.max_duration_s);
  }
  if (!non_negative(o.max_path_length_m)) {
    return "max_path_length_m must be >= 0 (0: no limit), got " +
           std::to_string(o.max_path_length_m);
  }
  if (!(positive(o.scan_rate_hz) && o.scan_rate_hz <= kMaxScanRateHz)) {
    return "scan_rate_hz must be in (0, 1000], got " + std::to_string(o.scan_rate_hz);
  }
  if (o.steps_per_scan < 1 || o.steps_per_scan > kMaxStepsPerScan) {
    return "steps_per_scan must be in [1, 1000], got " + std::to_string(o.steps_per_scan);
  }
  if (!(o.lidar_sweep_s >= 0.0 && o.lidar_sweep_s <= 1.0 / o.scan_rate_hz)) {
    return "lidar_sweep_s must be in [0, 1 / scan_rate_hz], got " + std::to_string(o.lidar_sweep_s);
  }
  if (auto p = validate(o.lidar)) return "lidar: " + *p;
  const Pose2& l = o.laser_in_robot;
  if (!std::isfinite(l.x) || !std::isfinite(l.y) || !std::isfinite(l.theta)) {
    return "laser_in_robot must be finite";
  }
  const double offset_m = l.translation().norm();
  if (offset_m > 0.0 && !(offset_m < o.tour.clearance_m)) {
    return "laser_in_robot must lie within tour.clearance_m of the robot's centre, got " +
           std::to_string(offset_m) + " m";
  }
  if (auto p = validate(o.odometry)) return "odometry: " + *p;
  return std::nullopt;
}

/// What a LaserRun holds; on the heap, so that the profile's references into it survive a move.
class LaserRunState {
 public:
  LaserRunState(const World& world, const LaserRunOptions& o, std::uint64_t seed, Tour tour,
                const Pose2& start)
      : world_(world),
        o_(o),
        start_(start),
        truth_(start),
        odometry_(start),
        odometry_rng_(Rng(seed).fork(kOdometryStream)),
        lidar_rng_(Rng(seed).fork(kLidarStream)),
        dt_s_(1.0 / (o.scan_rate_hz * o.steps_per_scan)) {
    run_.tour = std::move(tour);
    profile_.emplace(run_.tour.pieces, o_);
    record();
  }

  [[nodiscard]] bool done() const {
    if (profile_->done(state_)) return true;
    const double next_t_s = static_cast<double>(scan_index_ + 1) / o_.scan_rate_hz;
    if (o_.max_duration_s > 0.0 && next_t_s > o_.max_duration_s) return true;
    return o_.max_path_length_m > 0.0 && run_.path_length_m >= o_.max_path_length_m;
  }

  void step() {
    TESSERA_ASSERT(!done());
    for (int k = 0; k < o_.steps_per_scan; ++k) {
      profile_->step(state_, dt_s_);
      const Pose2 next = profile_->pose(state_, start_);
      const Pose2 T_prev_cur = between(truth_, next);
      run_.path_length_m += std::hypot(T_prev_cur.x, T_prev_cur.y);
      run_.turned_rad += std::abs(T_prev_cur.theta);
      odometry_ = odometry_ * noisy_odometry_increment(T_prev_cur, o_.odometry, odometry_rng_);
      truth_ = next;
    }
    // The last scan's velocity over its sweep, now that the odometry after it is known.
    const OdometryReading& before = run_.log.odometry.back();
    const double period_s = 1.0 / o_.scan_rate_hz;
    run_.log.scans.back().robot_velocity = sweep_velocity(
        run_.log.scans.back().scan,
        [&](double dt_s) { return interpolate(before.pose, odometry_, dt_s / period_s); });
    // When the tour ends within the interval, this last scan is taken at rest.
    ++scan_index_;
    record();
  }

  [[nodiscard]] const SimulatedLaserRun& run() const { return run_; }
  SimulatedLaserRun& run() { return run_; }
  [[nodiscard]] bool tour_done() const { return profile_->done(state_); }

 private:
  void record() {
    const double t_s = static_cast<double>(scan_index_) / o_.scan_rate_hz;
    StampedScan s;
    s.t_s = t_s;
    s.odometry = odometry_;
    s.laser_in_robot = o_.laser_in_robot;
    if (o_.lidar_sweep_s > 0.0) {
      // Beam by beam from where the robot will be: the drive is a plan, so a copy of its state
      // drives the sweep ahead.
      const double increment_s = o_.lidar_sweep_s / static_cast<double>(o_.lidar.beams);
      std::vector<Pose2> T_world_laser(static_cast<std::size_t>(o_.lidar.beams));
      DriveState ahead = state_;
      for (std::size_t i = 0; i < T_world_laser.size(); ++i) {
        if (i > 0) profile_->step(ahead, increment_s);
        T_world_laser[i] = (i == 0 ? truth_ : profile_->pose(ahead, start_)) * o_.laser_in_robot;
      }
      s.scan = simulate_lidar_scan(world_, T_world_laser, o_.lidar, lidar_rng_);
      s.scan.time_increment_s = increment_s;
    } else {
      s.scan = simulate_lidar_scan(world_, truth_ * o_.laser_in_robot, o_.lidar, lidar_rng_);
    }
    run_.log.scans.push_back(std::move(s));
    run_.log.odometry.push_back({t_s, odometry_});
    run_.truth.push_back({t_s, truth_});
    run_.duration_s = t_s;
    run_.tour_completed = profile_->done(state_);
  }

  const World& world_;
  LaserRunOptions o_;
  Pose2 start_;
  Pose2 truth_;
  Pose2 odometry_;
  Rng odometry_rng_;
  Rng lidar_rng_;
  double dt_s_;
  SimulatedLaserRun run_;
  std::optional<SpeedProfile> profile_;
  DriveState state_;
  std::int64_t scan_index_ = 0;
};

Result<LaserRun> LaserRun::create(const World& world, const LaserRunOptions& o,
                                  std::uint64_t seed) {
  if (auto problem = validate(o)) return input_error("laser run options: " + *problem);
  const Rng root(seed);
  Pose2 start;
  if (o.start.has_value()) {
    start = *o.start;
    start.theta = normalize_angle(start.theta);
  } else {
    Rng start_rng = root.fork(kStartStream);
    Result<Pose2> drawn = random_start_pose(world, o.tour.clearance_m, start_rng);
    if (!drawn) return drawn.error();
    start = *drawn;
  }
  Result<Tour> tour = plan_tour(world, start, o.tour);
  if (!tour) return tour.error();
  return LaserRun(std::make_unique<LaserRunState>(world, o, seed, std::move(*tour), start));
}

LaserRun::LaserRun(std::unique_ptr<LaserRunState> state) : state_(std::move(state)) {}
LaserRun::LaserRun(LaserRun&&) noexcept = default;
LaserRun& LaserRun::operator=(LaserRun&&) noexcept = default;
LaserRun::~LaserRun() = default;

bool LaserRun::done() const { return state_->done(); }
void LaserRun::step() { state_->step(); }
const SimulatedLaserRun& LaserRun::run() const { return state_->run(); }
SimulatedLaserRun LaserRun::take_run() && { return std::move(state_->run()); }

Result<SimulatedLaserRun> simulate_laser_run(const World& world, const LaserRunOptions& o,
                                             std::uint64_t seed) {
  Result<LaserRun> run = LaserRun::create(world, o, seed);
  if (!run) return run.error();
  while (!run->done()) run->step();
  return std::move(*run).take_run();
}

}  // namespace tessera
