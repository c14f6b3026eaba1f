#include "laser_input.hpp"

#include <fmt/format.h>

#include <cmath>

#include "slam_report.hpp"
#include "tessera/io/carmen_log.hpp"
#include "tessera/io/robot_bag.hpp"

namespace tessera::cli {

void LaserInput::add_options(CLI::App& command) {
  command.add_option("--log", log, "Laser log: CARMEN .clf/.log (FLASER, ROBOTLASER1, RAWLASER1)");
  command.add_option("--bag", bag,
                     "ROS bag: a ROS 1 .bag, a rosbag2 folder, a .db3 or an .mcap file (LaserScan, "
                     "Odometry, the laser pose from /tf_static and /tf)");
  command.add_option("--scan-topic", scan_topic,
                     "--bag: the sensor_msgs/LaserScan topic (needed when there are several)");
  command.add_option("--odom-topic", odom_topic,
                     "--bag: the nav_msgs/Odometry topic (needed when there are several; without "
                     "one, /tf's odom -> base is the odometry)");
  command.add_option("--base-frame", base_frame,
                     "--bag: the robot frame (default: the odometry's child_frame_id); "
                     "--ros --no-odometry: the robot frame (default: the laser's)");
  command.add_flag("--no-odometry", no_odometry,
                   "Ignore the log's odometry: use the scans alone (for odometry that cannot be "
                   "trusted; a bag without odometry is read so anyway; with --ros, a robot that "
                   "publishes no <ns>/odom)");
  command
      .add_option("--from-s", from_s,
                  "Use the scans from this many seconds after the first one (--log, --bag)")
      ->check(CLI::NonNegativeNumber);
  command
      .add_option("--to-s", to_s,
                  "Use the scans up to this many seconds after the first one (--log, --bag)")
      ->check(CLI::NonNegativeNumber);
}

std::string LaserInput::name() const {
  return log ? log->string() : bag ? bag->string() : std::string{};
}

Status LaserInput::check(bool live) const {
  if (live) {
    if (!scan_topic.empty() || !odom_topic.empty()) {
      return usage_error(
          "--scan-topic and --odom-topic choose a bag's topics; --ros reads "
          "<ns>/scan and <ns>/odom");
    }
    if (!base_frame.empty() && !no_odometry) {
      return usage_error(
          "--ros takes --base-frame with --no-odometry; with odometry the robot frame is the "
          "odometry's child frame");
    }
    if (from_s || to_s) return usage_error("--from-s and --to-s cut a --log or --bag");
    return Ok{};
  }
  if (log && bag) return usage_error("give --log or --bag, not both");
  if (!bag && (!scan_topic.empty() || !odom_topic.empty() || !base_frame.empty())) {
    return usage_error("--scan-topic, --odom-topic and --base-frame need --bag");
  }
  if (!given() && (from_s || to_s)) return usage_error("--from-s and --to-s cut a --log or --bag");
  if (!given() && no_odometry) return usage_error("--no-odometry is about a --log or --bag");
  return check_window(from_s, to_s);
}

Result<LaserLog> LaserInput::read(nlohmann::json* bag_report) const {
  LaserLog out;
  if (log) {
    Result<LaserLog> read = read_carmen_log(*log);
    if (!read) return read.error();
    out = std::move(read).value();
  } else {
    Result<RobotBag> read = read_robot_bag(*bag, {scan_topic, odom_topic, base_frame});
    if (!read) return read.error();
    if (bag_report) *bag_report = bag_json(*read);
    out = std::move(read->log);
  }
  if (Status s = cut_to_window(out, from_s, to_s, name()); !s) return s.error();
  if (no_odometry) without_odometry(out);
  return out;
}

Status check_window(std::optional<double> from_s, std::optional<double> to_s) {
  if (from_s && to_s && !(*from_s < *to_s)) {
    return usage_error(fmt::format("--from-s {} must be before --to-s {}", *from_s, *to_s));
  }
  return Ok{};
}

Status cut_to_window(LaserLog& log, std::optional<double> from_s, std::optional<double> to_s,
                     const std::string& name) {
  if ((!from_s && !to_s) || log.scans.empty()) return Ok{};
  // In file order, by each scan's time since the first scan (CARMEN stamps may step back).
  const double t0 = log.scans.front().t_s;
  const double from = from_s.value_or(-INFINITY), to = to_s.value_or(INFINITY);
  const auto outside = [&](double t_s) { return !(t_s - t0 >= from && t_s - t0 <= to); };
  std::erase_if(log.scans, [&](const StampedScan& s) { return outside(s.t_s); });
  std::erase_if(log.odometry, [&](const OdometryReading& o) { return outside(o.t_s); });
  if (log.scans.empty()) {
    return input_error(fmt::format("{}: no scan from {} s to {} s after its first scan", name,
                                   from_s.value_or(0.0), to));
  }
  return Ok{};
}

}  // namespace tessera::cli
