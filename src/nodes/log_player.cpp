// Plays a LaserLog as ROS 2 topics (nodes/log_player.hpp).
#include "tessera/nodes/log_player.hpp"

#include "tessera/io/ros_message_encoders.hpp"
#include "tessera/net/ros_names.hpp"
#include "tessera/record/ros_conversions.hpp"

namespace tessera::nodes {

using net::Qos;
using net::Transport;

struct LogPlayer::State {
  const LaserLog& log;
  Transport& transport;
  std::string frame_prefix;  // "r1/" or ""
  Transport::WriterId scan = 0, odom = 0, clock = 0, tf_static = 0;
  std::size_t next = 0;

  State(const LaserLog& l, Transport& t) : log(l), transport(t) {}
};

LogPlayer::LogPlayer(std::unique_ptr<State> state) : state_(std::move(state)) {}
LogPlayer::~LogPlayer() = default;

Result<std::unique_ptr<LogPlayer>> LogPlayer::create(const LaserLog& log,
                                                     const LogPlayerOptions& options,
                                                     Transport& transport) {
  if (log.scans.empty()) return input_error("play: the log has no scans");
  Result<std::string> scan_topic = net::resolve_topic_name("scan", options.ns);
  if (!scan_topic.ok()) return scan_topic.error();
  auto state = std::make_unique<State>(log, transport);
  if (!options.ns.empty() && options.ns != "/") {
    state->frame_prefix = options.ns.substr(options.ns.front() == '/' ? 1 : 0) + "/";
  }
  const Qos sensors = Qos::reliable(options.depth);
  State& s = *state;
  const std::string odom_topic = *net::resolve_topic_name("odom", options.ns);
  for (Status st :
       {transport.advertise({*scan_topic, std::string(kRos2LaserScan), sensors}, s.scan),
        transport.advertise({"/clock", std::string(kRos2Clock), Qos::clock()}, s.clock),
        transport.advertise({"/tf_static", std::string(kRos2TfMessage), Qos::tf_static()},
                            s.tf_static)}) {
    if (!st.ok()) return st.error();
  }
  if (log.has_odometry) {
    if (Status st = transport.advertise({odom_topic, std::string(kRos2Odometry), sensors}, s.odom);
        !st.ok()) {
      return st.error();
    }
  }
  // A log of scans alone whose laser is the robot has no base_link to place it on.
  const Pose2& laser_in_robot = log.scans.front().laser_in_robot;
  if (!log.has_odometry && laser_in_robot.x == 0.0 && laser_in_robot.y == 0.0 &&
      laser_in_robot.theta == 0.0) {
    return std::unique_ptr<LogPlayer>(new LogPlayer(std::move(state)));
  }
  TfMessage statics;
  statics.transforms.push_back(
      planar_transform_stamped(log.scans.front().laser_in_robot, to_ns(log.scans.front().t_s),
                               s.frame_prefix + "base_link", s.frame_prefix + "laser"));
  if (Status st = transport.publish(s.tf_static, encode_cdr(statics)); !st.ok()) return st.error();
  return std::unique_ptr<LogPlayer>(new LogPlayer(std::move(state)));
}

bool LogPlayer::done() const { return state_->next >= state_->log.scans.size(); }
double LogPlayer::next_stamp_s() const { return state_->log.scans[state_->next].t_s; }
std::size_t LogPlayer::published() const { return state_->next; }
std::size_t LogPlayer::scan_subscribers() const {
  return state_->transport.matched_readers(state_->scan);
}

Status LogPlayer::publish_next() {
  State& s = *state_;
  const StampedScan& scan = s.log.scans[s.next];
  const std::int64_t stamp = to_ns(scan.t_s);
  if (s.log.has_odometry) {
    OdometryMessage odom;
    odom.header = {stamp, s.frame_prefix + "odom"};
    odom.child_frame_id = s.frame_prefix + "base_link";
    odom.pose = planar_transform(scan.odometry.x, scan.odometry.y, scan.odometry.theta);
    if (Status st = s.transport.publish(s.odom, encode_cdr(odom)); !st.ok()) return st;
  }
  if (Status st = s.transport.publish(
          s.scan, encode_cdr(laser_scan_message(scan.scan, stamp, s.frame_prefix + "laser")));
      !st.ok()) {
    return st;
  }
  if (Status st = s.transport.publish(s.clock, encode_cdr(ClockMessage{stamp})); !st.ok()) {
    return st;
  }
  ++s.next;
  return Ok{};
}

}  // namespace tessera::nodes
