#pragma once
// A small robot run as bag messages, for the bag reader tests and the bag benchmark: a laser
// scan every 0.1 s, odometry every 0.05 s (the robot drives along x at 0.5 m/s and turns at
// 0.2 rad/s), /tf_static base_footprint -> base_link -> base_laser_link (the laser 0.1 m behind
// the centre, turned by pi, like a Neato's), and /tf odom -> base_footprint.
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "support/bag_writer.hpp"

namespace tessera::support {

struct SyntheticRun {
  std::vector<TopicToWrite> topics;
  std::vector<MessageToWrite> messages;
};

inline constexpr std::int64_t kSyntheticStartNs = 1'700'000'000'000'000'000;
inline constexpr double kSyntheticLaserX = -0.1;

/// Odometry of the synthetic run at t seconds after the start.
inline RosTransform synthetic_odometry(double t_s) {
  const double yaw = 0.2 * t_s;
  return {0.5 * t_s, 0.0, 0.0, 0.0, 0.0, std::sin(yaw / 2), std::cos(yaw / 2)};
}

/// Beam b of scan k: 1 + 0.01 k + 0.001 b metres, except every tenth beam, which is inf (no
/// return).
inline float synthetic_range(std::size_t k, std::size_t b) {
  if (b % 10 == 0) return std::numeric_limits<float>::infinity();
  return 1.0F + 0.01F * static_cast<float>(k) + 0.001F * static_cast<float>(b);
}

/// `scans` scans of `beams` beams. ROS 1 type names when `ros1_types`, ROS 2 ones otherwise.
inline SyntheticRun synthetic_run(RosEncoding encoding, std::size_t scans, std::size_t beams,
                                  bool with_tf = true) {
  const bool ros1 = encoding == RosEncoding::kRos1;
  auto type = [ros1](const std::string& pkg, const std::string& name) {
    return ros1 ? pkg + "/" + name : pkg + "/msg/" + name;
  };
  SyntheticRun run;
  run.topics = {{"/scan", type("sensor_msgs", "LaserScan")},
                {"/odom", type("nav_msgs", "Odometry")},
                {"/tf", type("tf2_msgs", "TFMessage")},
                {"/tf_static", type("tf2_msgs", "TFMessage")}};
  auto ns = [](double t_s) { return kSyntheticStartNs + static_cast<std::int64_t>(t_s * 1e9); };
  if (with_tf) {
    TfMessage statics;
    statics.transforms.push_back({{ns(0), "base_footprint"}, "base_link", {}});
    statics.transforms.push_back({{ns(0), "base_link"},
                                  "base_laser_link",
                                  {kSyntheticLaserX, 0.0, 0.2, 0.0, 0.0, 1.0, 0.0}});
    run.messages.push_back({3, ns(0), encode_tf_message(statics, encoding)});
  }
  for (std::size_t k = 0; k < scans; ++k) {
    for (int half = 0; half < 2; ++half) {
      const double t = 0.1 * static_cast<double>(k) + 0.05 * half;
      OdometryMessage odom{{ns(t), "odom"}, "base_footprint", synthetic_odometry(t)};
      run.messages.push_back({1, ns(t), encode_odometry(odom, encoding)});
      if (with_tf) {
        TfMessage tf;
        tf.transforms.push_back({{ns(t), "odom"}, "base_footprint", synthetic_odometry(t)});
        run.messages.push_back({2, ns(t), encode_tf_message(tf, encoding)});
      }
    }
    LaserScanMessage scan;
    scan.header = {ns(0.1 * static_cast<double>(k) + 0.025), "base_laser_link"};
    scan.angle_min_rad = -static_cast<float>(std::numbers::pi);
    scan.angle_increment_rad =
        static_cast<float>(2 * std::numbers::pi / static_cast<double>(beams));
    scan.angle_max_rad =
        scan.angle_min_rad + scan.angle_increment_rad * static_cast<float>(beams - 1);
    scan.range_min_m = 0.02F;
    scan.range_max_m = 5.0F;
    for (std::size_t b = 0; b < beams; ++b) scan.ranges_m.push_back(synthetic_range(k, b));
    run.messages.push_back({0, scan.header.stamp_ns + 1000, encode_laser_scan(scan, encoding)});
  }
  return run;
}

}  // namespace tessera::support
