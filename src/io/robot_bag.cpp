// Bag -> LaserLog: topic choice, tf tree, odometry interpolation and the no-return rule of
// robot_bag.hpp.
#include "tessera/io/robot_bag.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "tessera/core/pose_interpolation.hpp"
#include "tessera/core/time_ns.hpp"
#include "tessera/io/ros_messages.hpp"
#include "tessera/io/tf_tree.hpp"
#include "tessera/sensors/range_scan.hpp"
#include "tessera/sensors/scan_sweep.hpp"

namespace tessera {
namespace {

bool is_tf_topic(std::string_view name, bool& is_static) {
  name = tf_frame_name(name);  // "/tf" and "tf" alike
  is_static = name == "tf_static";
  return name == "tf" || name == "tf_static";
}

std::string join_names(const std::vector<const BagTopic*>& topics) {
  std::string out;
  for (const BagTopic* t : topics) out += (out.empty() ? "" : ", ") + t->name;
  return out;
}

bool is_odometry_type(std::string_view type) { return ros_type_is(type, kOdometryType); }

/// The topic `wanted` names, or the only topic whose type `is_type` accepts (`type` names it in
/// messages).
Result<std::size_t> choose_topic(const RosBag& bag, const std::string& file, std::string_view type,
                                 bool (*is_type)(std::string_view), const std::string& wanted,
                                 std::string_view option) {
  std::vector<const BagTopic*> candidates;
  for (const BagTopic& t : bag.topics) {
    if (is_type(t.type)) candidates.push_back(&t);
  }
  if (!wanted.empty()) {
    for (std::size_t i = 0; i < bag.topics.size(); ++i) {
      const BagTopic& t = bag.topics[i];
      if (t.name != wanted) continue;
      if (!is_type(t.type)) {
        return usage_error(file + ": " + std::string(option) + " " + wanted + " is a " + t.type +
                           " topic, expected " + std::string(type));
      }
      return i;
    }
    return usage_error(file + ": " + std::string(option) + " " + wanted + ": no such topic; " +
                       std::string(type) +
                       " topics: " + (candidates.empty() ? "none" : join_names(candidates)));
  }
  if (candidates.empty()) {
    return input_error(file + ": no " + std::string(type) + " topic in the bag");
  }
  if (candidates.size() > 1) {
    return usage_error(file + ": " + std::to_string(candidates.size()) + " " + std::string(type) +
                       " topics (" + join_names(candidates) + "): choose one with " +
                       std::string(option));
  }
  return static_cast<std::size_t>(candidates.front() - bag.topics.data());
}

RosEncoding encoding_of(const BagTopic& t, bool& known) {
  known = t.serialization == "ros1" || t.serialization == "cdr";
  return t.serialization == "ros1" ? RosEncoding::kRos1 : RosEncoding::kCdr;
}

/// Where a message is, for errors: "<file>: /scan message 12".
std::string at(const std::string& file, const BagTopic& t, std::size_t n) {
  return file + ": " + t.name + " message " + std::to_string(n);
}

double seconds(std::int64_t ns) { return 1e-9 * static_cast<double>(ns); }

/// The tf tree's frames, comma-separated ("none" when empty), for error messages.
std::string frame_list(const TfTree& tf) {
  std::string known;
  for (const std::string& f : tf.frames()) known += (known.empty() ? "" : ", ") + f;
  return known.empty() ? "none" : known;
}

}  // namespace

Result<RangeScan> range_scan_of(const LaserScanMessage& msg, int& no_return_readings) {
  if (!std::isfinite(msg.angle_increment_rad) || msg.angle_increment_rad == 0.0F ||
      !std::isfinite(msg.angle_min_rad) || !std::isfinite(msg.range_max_m) ||
      !(msg.range_max_m > 0.0F)) {
    return input_error(
        "angle_increment must be finite and non-zero, angle_min finite and range_max > 0");
  }
  RangeScan scan;
  scan.angle_min_rad = msg.angle_min_rad;
  scan.angle_increment_rad = msg.angle_increment_rad;
  scan.min_range_m = std::isfinite(msg.range_min_m) ? std::max(0.0F, msg.range_min_m) : 0.0;
  scan.max_range_m = msg.range_max_m;
  scan.ranges_m.reserve(msg.ranges_m.size());
  for (const float r : msg.ranges_m) {
    const bool valid = std::isfinite(r) && r > 0.0F && r >= msg.range_min_m && r <= msg.range_max_m;
    if (!valid) ++no_return_readings;
    scan.ranges_m.push_back(valid ? static_cast<double>(r) : scan.max_range_m);
  }
  // The beams' times: time_increment as the message gives it, when the sweep it makes lasts at
  // most kMaxSweep_s (a driver that sets it in other units, or to nonsense, is not believed).
  constexpr double kMaxSweep_s = 1.0;
  const double sweep_s = std::abs(static_cast<double>(msg.time_increment_s)) *
                         static_cast<double>(msg.ranges_m.size());
  if (std::isfinite(sweep_s) && sweep_s <= kMaxSweep_s) {
    scan.time_increment_s = msg.time_increment_s;
  }
  // A driver that sweeps clockwise sends a negative angle_increment; tessera's scans turn
  // counter-clockwise, so the same beams are put in that order (each keeping its time).
  if (scan.angle_increment_rad < 0.0) return reversed(std::move(scan));
  return scan;
}

bool robot_bag_needs(const BagTopic& topic) {
  bool is_static = false;
  return is_laser_scan_type(topic.type) || ros_type_is(topic.type, kOdometryType) ||
         (ros_type_is(topic.type, kTfMessageType) && is_tf_topic(topic.name, is_static));
}

Result<RobotBag> robot_bag_from(const RosBag& bag, const std::string& file,
                                const RobotBagOptions& options) {
  // A bag without scans is bad input whatever the options say.
  if (std::none_of(bag.topics.begin(), bag.topics.end(),
                   [](const BagTopic& t) { return is_laser_scan_type(t.type); })) {
    return input_error(file + ": no " + std::string(kLaserScanType) + " (or " +
                       std::string(kMultiEchoLaserScanType) + ") topic in the bag");
  }
  Result<std::size_t> scan_topic = choose_topic(bag, file, kLaserScanType, is_laser_scan_type,
                                                options.scan_topic, "--scan-topic");
  if (!scan_topic) return scan_topic.error();
  // The odometry: the Odometry topic, or in a bag that records none (and no --odom-topic names
  // one) the moving tf edge above the laser, odom -> base as the base's driver publishes it on /tf.
  std::optional<std::size_t> odom_topic;
  if (!options.odom_topic.empty() ||
      std::any_of(bag.topics.begin(), bag.topics.end(),
                  [](const BagTopic& t) { return ros_type_is(t.type, kOdometryType); })) {
    Result<std::size_t> chosen = choose_topic(bag, file, kOdometryType, is_odometry_type,
                                              options.odom_topic, "--odom-topic");
    if (!chosen) return chosen.error();
    odom_topic = *chosen;
  }

  RobotBag out;
  out.format = bag.format;
  const BagTopic& scans_t = bag.topics[*scan_topic];
  const bool multi_echo = ros_type_is(scans_t.type, kMultiEchoLaserScanType);
  out.scan_topic = scans_t.name;
  out.odom_topic = odom_topic ? bag.topics[*odom_topic].name : "/tf";
  std::vector<const BagTopic*> decoded = {&scans_t};
  if (odom_topic) decoded.push_back(&bag.topics[*odom_topic]);
  for (const BagTopic* t : decoded) {
    bool known = false;
    (void)encoding_of(*t, known);
    if (!known) {
      return input_error(file + ": topic " + t->name + " has serialization '" + t->serialization +
                         "', expected ros1 or cdr");
    }
  }

  // One pass: tf into the tree, odometry and scans decoded in storage order.
  TfTree tf;
  std::vector<PoseAtNs> odom;                                    // T_odom_child by stamp
  std::vector<std::pair<std::int64_t, LaserScanMessage>> scans;  // with log time
  std::vector<std::size_t> seen(bag.topics.size(), 0);
  std::string child_frame;
  for (const BagMessage& m : bag.messages) {
    const BagTopic& t = bag.topics[m.topic];
    const std::size_t n = seen[m.topic]++;
    bool known = false;
    const RosEncoding encoding = encoding_of(t, known);
    bool is_static = false;
    if (m.topic == *scan_topic) {
      Result<LaserScanMessage> s = multi_echo ? decode_multi_echo_laser_scan(bag.bytes(m), encoding)
                                              : decode_laser_scan(bag.bytes(m), encoding);
      if (!s) return input_error(at(file, t, n) + ": " + s.error().message);
      scans.emplace_back(m.log_time_ns, std::move(s).value());
    } else if (odom_topic && m.topic == *odom_topic) {
      Result<OdometryMessage> o = decode_odometry(bag.bytes(m), encoding);
      if (!o) return input_error(at(file, t, n) + ": " + o.error().message);
      if (odom.empty()) {
        out.odom_frame = std::string(tf_frame_name(o->header.frame_id));
        child_frame = std::string(tf_frame_name(o->child_frame_id));
      }
      const std::int64_t stamp = o->header.stamp_ns != 0 ? o->header.stamp_ns : m.log_time_ns;
      odom.push_back({stamp, planar_pose(o->pose)});
    } else if (known && ros_type_is(t.type, kTfMessageType) && is_tf_topic(t.name, is_static)) {
      Result<TfMessage> tfm = decode_tf_message(bag.bytes(m), encoding);
      if (!tfm) return input_error(at(file, t, n) + ": " + tfm.error().message);
      for (const TransformStampedMessage& ts : tfm->transforms) tf.add(ts, is_static);
    }
  }
  if (scans.empty()) return input_error(file + ": topic " + scans_t.name + " has no messages");
  out.laser_frame = std::string(tf_frame_name(scans.front().second.header.frame_id));
  if (!odom_topic) {
    std::optional<TfTree::MovingEdge> edge = tf.lowest_moving_edge(out.laser_frame);
    if (edge) {
      out.odom_frame = edge->parent;
      child_frame = edge->child;
      for (const auto& [t_ns, T] : edge->T_parent_child) odom.push_back({t_ns, planar_pose(T)});
    } else {
      // Scans alone: no odometry, and the robot is the laser unless the options name a base.
      out.odom_topic.clear();
      out.log.has_odometry = false;
      child_frame = out.laser_frame;
    }
  }
  if (out.log.has_odometry && odom.empty()) {
    return input_error(file + ": topic " + out.odom_topic + " has no messages");
  }
  std::stable_sort(odom.begin(), odom.end(),
                   [](const PoseAtNs& a, const PoseAtNs& b) { return a.t_ns < b.t_ns; });
  out.base_frame =
      options.base_frame.empty() ? child_frame : std::string(tf_frame_name(options.base_frame));

  if (out.log.has_odometry) {
    for (const PoseAtNs& o : odom) out.log.odometry.push_back({seconds(o.t_ns), o.pose});
  }
  const bool base_is_child = out.base_frame == child_frame;
  out.log.scans.reserve(scans.size());
  for (std::size_t i = 0; i < scans.size(); ++i) {
    const auto& [log_time_ns, msg] = scans[i];
    const std::int64_t stamp = msg.header.stamp_ns != 0 ? msg.header.stamp_ns : log_time_ns;
    Result<RangeScan> scan = range_scan_of(msg, out.no_return_readings);
    if (!scan.ok()) return input_error(at(file, scans_t, i) + ": " + scan.error().message);
    StampedScan s;
    s.t_s = seconds(stamp);
    if (out.log.has_odometry) {  // without, every scan's odometry is the identity
      Pose2 T_child_base;
      if (!base_is_child) {
        Result<RosTransform> T = tf.lookup(child_frame, out.base_frame, stamp);
        if (!T) {
          return input_error(file + ": base frame '" + out.base_frame + "': " + T.error().message +
                             " (the odometry's child frame)");
        }
        T_child_base = planar_pose(*T);
      }
      s.odometry = pose_at(odom, stamp);
      if (!base_is_child) s.odometry = s.odometry * T_child_base;
      s.robot_velocity = sweep_velocity(*scan, [&](double dt_s) {
        return pose_at(odom, stamp + std::llround(dt_s * 1e9)) * T_child_base;
      });
    }
    const std::string_view laser = tf_frame_name(msg.header.frame_id);
    if (laser != out.base_frame) {
      Result<RosTransform> T_base_laser = tf.lookup(out.base_frame, laser, stamp);
      if (!T_base_laser) {
        return input_error(at(file, scans_t, i) + ": laser pose: " + T_base_laser.error().message +
                           " (tf frames: " + frame_list(tf) + ")");
      }
      const PlanarLaser placed = planar_laser(*T_base_laser);
      s.laser_in_robot = placed.T_base_laser;
      if (placed.upside_down) *scan = mirrored(std::move(*scan));
    }
    s.scan = std::move(*scan);
    out.log.scans.push_back(std::move(s));
  }
  for (std::size_t i = 1; i < out.log.scans.size(); ++i) {
    if (out.log.scans[i].t_s < out.log.scans[i - 1].t_s) ++out.log.backward_stamps;
  }
  return out;
}

Result<RobotBag> read_robot_bag(const std::filesystem::path& path, const RobotBagOptions& options) {
  BagReadOptions read;
  read.keep = robot_bag_needs;
  Result<RosBag> bag = read_ros_bag(path, read);
  if (!bag) return bag.error();
  return robot_bag_from(*bag, path.string(), options);
}

}  // namespace tessera
