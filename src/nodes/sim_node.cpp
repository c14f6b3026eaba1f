// The simulator node (nodes/sim_node.hpp): DifferentialDriveRobot for motion and odometry drift,
// simulate_lidar_scan for the lidar, record/ros_conversions for the ROS 2 messages.
#include "tessera/nodes/sim_node.hpp"

#include <algorithm>
#include <cmath>

#include "tessera/core/rng.hpp"
#include "tessera/io/ros_message_encoders.hpp"
#include "tessera/record/ros_conversions.hpp"
#include "tessera/sim/differential_drive.hpp"
#include "tessera/sim/lidar_scan.hpp"

namespace tessera::nodes {
namespace {

using net::Qos;
using net::TopicSpec;
using net::Transport;

bool positive(double v) { return std::isfinite(v) && v > 0.0; }

// Steps between two publications at `rate_hz`.
std::int64_t ticks_per(double rate_hz, double step_s) {
  return std::max<std::int64_t>(1, std::llround(1.0 / (rate_hz * step_s)));
}

// True when a disc of `radius_m` at `centre_m` overlaps a solid cell (or leaves the grid).
bool disc_hits_wall(const World& world, Vec2 centre_m, double radius_m) {
  const GridGeometry& g = world.geometry();
  const double r = g.resolution_m();
  const Cell lo = g.cell_at_unchecked({centre_m.x - radius_m, centre_m.y - radius_m});
  const Cell hi = g.cell_at_unchecked({centre_m.x + radius_m, centre_m.y + radius_m});
  for (int y = lo.y; y <= hi.y; ++y) {
    for (int x = lo.x; x <= hi.x; ++x) {
      if (!world.solid({x, y})) continue;
      // The cell's point nearest the centre.
      const Vec2 c = g.center_of({x, y});
      const double dx = std::max(std::abs(centre_m.x - c.x) - 0.5 * r, 0.0);
      const double dy = std::max(std::abs(centre_m.y - c.y) - 0.5 * r, 0.0);
      if (dx * dx + dy * dy < radius_m * radius_m) return true;
    }
  }
  return false;
}

}  // namespace

std::optional<std::string> validate(const SimNodeOptions& o) {
  if (o.starts.empty()) return "starts: at least one robot is needed";
  for (const auto& [name, v] : {std::pair{"physics_step_s", o.physics_step_s},
                                {"scan_rate_hz", o.scan_rate_hz},
                                {"odom_rate_hz", o.odom_rate_hz},
                                {"clock_rate_hz", o.clock_rate_hz},
                                {"cmd_timeout_s", o.cmd_timeout_s},
                                {"max_speed_m_per_s", o.max_speed_m_per_s},
                                {"max_turn_rate_rad_per_s", o.max_turn_rate_rad_per_s},
                                {"robot_radius_m", o.robot_radius_m}}) {
    if (!positive(v)) return std::string(name) + " must be > 0, got " + std::to_string(v);
  }
  if (auto p = validate(o.lidar)) return "lidar: " + *p;
  if (auto p = validate(o.odometry)) return "odometry: " + *p;
  return std::nullopt;
}

std::string robot_name(int robot) { return "r" + std::to_string(robot + 1); }

struct SimNode::State {
  struct Robot {
    std::string name;
    Pose2 start;  // T_world_odom: the odometry frame is the robot's pose at time 0 (REP-105)
    DifferentialDriveRobot drive;
    Rng lidar_rng;
    double v_m_per_s = 0.0;
    double w_rad_per_s = 0.0;
    std::int64_t command_tick = -1;  // when the last command arrived; -1: none yet
    std::uint64_t stalls = 0;
    RosTwist moving{};  // the velocity of the last step (zero when stopped or stalled)
    Transport::WriterId scan = 0, odom = 0, truth = 0;
  };

  const World& world;
  SimNodeOptions options;
  Transport& transport;
  std::vector<Robot> robots;
  Transport::WriterId tf = 0, tf_static = 0, clock = 0;
  std::int64_t tick = 0;
  std::int64_t scan_every, odom_every, clock_every, timeout_ticks;
  std::uint64_t dropped_commands = 0;

  State(const World& w, const SimNodeOptions& o, Transport& t)
      : world(w),
        options(o),
        transport(t),
        scan_every(ticks_per(o.scan_rate_hz, o.physics_step_s)),
        odom_every(ticks_per(o.odom_rate_hz, o.physics_step_s)),
        clock_every(ticks_per(o.clock_rate_hz, o.physics_step_s)),
        timeout_ticks(std::llround(o.cmd_timeout_s / o.physics_step_s)) {}

  [[nodiscard]] std::int64_t now_ns() const {
    return to_ns(static_cast<double>(tick) * options.physics_step_s);
  }

  template <typename Message>
  Status send(Transport::WriterId w, const Message& m) {
    return transport.publish(w, encode_cdr(m));
  }

  Status advertise(Transport::WriterId& id, const std::string& topic, std::string_view type,
                   const Qos& qos) {
    return transport.advertise({topic, std::string(type), qos}, id);
  }

  Status connect() {
    if (Status s = advertise(tf, "/tf", kRos2TfMessage, Qos::tf()); !s.ok()) return s;
    if (Status s = advertise(tf_static, "/tf_static", kRos2TfMessage, Qos::tf_static()); !s.ok()) {
      return s;
    }
    if (Status s = advertise(clock, "/clock", kRos2Clock, Qos::clock()); !s.ok()) return s;
    for (std::size_t i = 0; i < robots.size(); ++i) {
      Robot& r = robots[i];
      const std::string ns = "/" + r.name;
      if (Status s = advertise(r.scan, ns + "/scan", kRos2LaserScan, Qos::sensor_data()); !s.ok()) {
        return s;
      }
      if (Status s = advertise(r.odom, ns + "/odom", kRos2Odometry, Qos::sensor_data()); !s.ok()) {
        return s;
      }
      if (Status s =
              advertise(r.truth, "/sim" + ns + "/ground_truth", kRos2Odometry, Qos::reliable(100));
          !s.ok()) {
        return s;
      }
      // Best effort matches any publisher (a reliable reader would ignore a best-effort teleop).
      const Qos command_qos{Qos::Reliability::kBestEffort, Qos::Durability::kVolatile, 10};
      Result<Transport::ReaderId> sub =
          transport.subscribe({ns + "/cmd_vel", std::string(kRos2Twist), command_qos},
                              [this, i](std::span<const std::uint8_t> cdr) { on_command(i, cdr); });
      if (!sub.ok()) return sub.error();
    }
    // The lidar sits at the robot's centre: an identity static transform per robot.
    TfMessage statics;
    for (const Robot& r : robots) {
      statics.transforms.push_back(
          planar_transform_stamped(Pose2{}, 0, r.name + "/base_link", r.name + "/laser"));
    }
    return send(tf_static, statics);
  }

  void on_command(std::size_t robot, std::span<const std::uint8_t> cdr) {
    Result<TwistMessage> twist = decode_cdr_twist(cdr);
    if (!twist.ok() || !std::isfinite(twist->linear_x_mps) ||
        !std::isfinite(twist->angular_z_radps)) {
      ++dropped_commands;
      return;
    }
    Robot& r = robots[robot];
    r.v_m_per_s =
        std::clamp(twist->linear_x_mps, -options.max_speed_m_per_s, options.max_speed_m_per_s);
    r.w_rad_per_s = std::clamp(twist->angular_z_radps, -options.max_turn_rate_rad_per_s,
                               options.max_turn_rate_rad_per_s);
    r.command_tick = tick;
  }

  void move(Robot& r) {
    const bool fresh = r.command_tick >= 0 && tick - r.command_tick <= timeout_ticks;
    const double v = fresh ? r.v_m_per_s : 0.0;
    const double w = fresh ? r.w_rad_per_s : 0.0;
    r.moving = RosTwist{};
    if (v == 0.0 && w == 0.0) return;
    const double dt = options.physics_step_s;
    const Pose2 next = r.drive.true_pose() * arc_motion(v, w, dt);
    if (disc_hits_wall(world, next.translation(), options.robot_radius_m)) {
      ++r.stalls;
      return;
    }
    r.drive.step(v, w, dt);
    r.moving.linear_x_mps = v;
    r.moving.angular_z_radps = w;
  }

  Status publish_due() {
    const std::int64_t stamp = now_ns();
    if (tick % clock_every == 0) {
      if (Status s = send(clock, ClockMessage{stamp}); !s.ok()) return s;
    }
    const bool odom_due = tick % odom_every == 0;
    TfMessage transforms;
    for (Robot& r : robots) {
      if (tick % scan_every == 0) {
        const Pose2& truth = r.drive.true_pose();  // the lidar is at the robot's centre
        const RangeScan scan = simulate_lidar_scan(world, truth, options.lidar, r.lidar_rng);
        if (Status s = send(r.scan, laser_scan_message(scan, stamp, r.name + "/laser")); !s.ok()) {
          return s;
        }
      }
      if (!odom_due) continue;
      const RosTwist& twist = r.moving;
      const Pose2 T_odom_robot = r.start.inverse() * r.drive.odometry_pose();
      OdometryMessage odom;
      odom.header = {stamp, r.name + "/odom"};
      odom.child_frame_id = r.name + "/base_link";
      odom.pose = planar_transform(T_odom_robot.x, T_odom_robot.y, T_odom_robot.theta);
      odom.twist = twist;
      if (Status s = send(r.odom, odom); !s.ok()) return s;
      const Pose2& truth = r.drive.true_pose();
      OdometryMessage ground;
      ground.header = {stamp, "world"};
      ground.child_frame_id = odom.child_frame_id;
      ground.pose = planar_transform(truth.x, truth.y, truth.theta);
      ground.twist = twist;
      if (Status s = send(r.truth, ground); !s.ok()) return s;
      transforms.transforms.push_back(
          planar_transform_stamped(T_odom_robot, stamp, odom.header.frame_id, odom.child_frame_id));
    }
    if (!transforms.transforms.empty()) return send(tf, transforms);
    return Ok{};
  }
};

SimNode::SimNode(std::unique_ptr<State> state) : state_(std::move(state)) {}
SimNode::~SimNode() = default;

Result<std::unique_ptr<SimNode>> SimNode::create(const World& world, const SimNodeOptions& options,
                                                 std::uint64_t seed, Transport& transport) {
  if (auto problem = validate(options)) return input_error("sim node: " + *problem);
  auto state = std::make_unique<State>(world, options, transport);
  const Rng root(seed);
  for (std::size_t i = 0; i < options.starts.size(); ++i) {
    const Pose2& start = options.starts[i];
    const std::string name = robot_name(static_cast<int>(i));
    if (disc_hits_wall(world, start.translation(), options.robot_radius_m)) {
      return input_error("sim node: start of " + name + " at (" + std::to_string(start.x) + ", " +
                         std::to_string(start.y) + ") m is in a wall");
    }
    state->robots.push_back({name, start,
                             DifferentialDriveRobot(start, options.odometry, root.fork(2 * i)),
                             root.fork(2 * i + 1)});
  }
  if (Status s = state->connect(); !s.ok()) return s.error();
  return std::unique_ptr<SimNode>(new SimNode(std::move(state)));
}

Status SimNode::step() {
  State& s = *state_;
  s.transport.poll();
  if (Status published = s.publish_due(); !published.ok()) return published;
  for (State::Robot& r : s.robots) s.move(r);
  ++s.tick;
  return Ok{};
}

double SimNode::time_s() const {
  return static_cast<double>(state_->tick) * state_->options.physics_step_s;
}
int SimNode::robot_count() const { return static_cast<int>(state_->robots.size()); }
Pose2 SimNode::true_pose(int robot) const {
  return state_->robots.at(static_cast<std::size_t>(robot)).drive.true_pose();
}
Pose2 SimNode::odometry_pose(int robot) const {
  const State::Robot& r = state_->robots.at(static_cast<std::size_t>(robot));
  return r.start.inverse() * r.drive.odometry_pose();
}
std::uint64_t SimNode::stalls(int robot) const {
  return state_->robots.at(static_cast<std::size_t>(robot)).stalls;
}
std::uint64_t SimNode::dropped_commands() const { return state_->dropped_commands; }

}  // namespace tessera::nodes
