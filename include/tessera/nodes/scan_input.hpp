#pragma once
// A robot's laser and odometry as they arrive over ROS 2 topics, paired into the StampedScan the
// offline pipelines take (laser_slam.hpp, localizer.hpp). Shared by the live SLAM node and the
// live localization node. In namespace `ns` ("/r1", or "" for none):
//   subscribes <ns>/scan sensor_msgs/LaserScan, <ns>/odom nav_msgs/Odometry (best effort, so any
//              driver's sensor-data publisher matches; a deep queue holds scans while the caller
//              works), /tf_static and /tf (the laser's place on the robot: base frame -> scan
//              frame)
// A scan is ready once an odometry message with its stamp is in, or one stamped after it has
// arrived after it; its odometry is then interpolated between the two messages around its stamp,
// as the bag reader does. So a scan and an odometry message with the same stamp, as `tessera
// play` sends them, give the offline pipeline's input exactly, in whatever order DDS delivers
// the two topics and even where a log's stamps go backwards.
// Without odometry (ScanInputOptions::use_odometry off: a robot that has none, mapped from its
// scans alone, decision 0034) <ns>/odom is not subscribed and a scan is ready once the laser's
// place on the robot is known.
#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "tessera/core/pose_interpolation.hpp"
#include "tessera/core/result.hpp"
#include "tessera/net/transport.hpp"
#include "tessera/sensors/laser_log.hpp"

namespace tessera::nodes {

/// What came in and what became of it; "dropped" counts are messages refused as invalid.
struct ScanInputStats {
  std::uint64_t scans_received = 0;
  std::uint64_t scans_dropped_invalid = 0;     // did not decode, unusable angles, no valid range
  std::uint64_t readings_dropped_invalid = 0;  // NaN or negative ranges (REP-117), not used
  std::uint64_t scans_dropped_no_pose = 0;     // no odometry or no laser transform for them
  std::uint64_t scans_dropped_overflow = 0;    // the wait queue was full
  std::uint64_t odometry_received = 0;
  std::uint64_t odometry_dropped_invalid = 0;  // did not decode or not finite
};

/// A scan paired with its odometry and the laser's place on the robot.
struct ReadyScan {
  StampedScan scan;
  std::int64_t stamp_ns = 0;
  std::chrono::steady_clock::time_point received{};  // when it came off the transport
};

struct ScanInputOptions {
  /// Scans waiting for odometry, for their laser transform or for the caller: beyond this, the
  /// oldest is dropped and counted.
  std::uint32_t queue_depth = 2000;
  /// False: scans alone. Each scan comes with an identity odometry, for a pipeline that does not
  /// use it (slam::LaserSlamOptions::use_odometry off).
  bool use_odometry = true;
  /// Without odometry, the robot frame, where /tf_static or /tf place the laser; empty: the
  /// laser's own frame is the robot. (With odometry the robot frame is the odometry's
  /// child_frame_id.)
  std::string base_frame{};
};

class ScanInput {
 public:
  /// kInput error for a namespace that is no ROS 2 name; the transport's errors otherwise.
  /// `transport` must outlive the input. Precondition: options.queue_depth > 0.
  [[nodiscard]] static Result<std::unique_ptr<ScanInput>> create(const std::string& ns,
                                                                 const ScanInputOptions& options,
                                                                 net::Transport& transport);
  ~ScanInput();
  ScanInput(const ScanInput&) = delete;
  ScanInput& operator=(const ScanInput&) = delete;

  /// The oldest waiting scan, once its odometry and laser transform are known; nullopt when it
  /// must still wait (or nothing waits). With `flush` (the input ends), a scan is paired with the
  /// odometry there is (clamped to the last message) or dropped and counted when there is none.
  /// Call after the transport has delivered (Transport::poll).
  [[nodiscard]] std::optional<ReadyScan> next(bool flush);

  [[nodiscard]] const ScanInputStats& stats() const;
  /// The odometry's frame (from the first odometry message); empty before it. Without odometry,
  /// the robot frame of the scans returned so far: the frame whose pose in the map is the
  /// robot's (REP-105's map -> odom becomes map -> that frame).
  [[nodiscard]] const std::string& odom_frame() const;
  /// The newest odometry message's T_odom_base and stamp; nullopt before the first.
  [[nodiscard]] std::optional<PoseAtNs> latest_odometry() const;

 private:
  struct State;
  explicit ScanInput(std::unique_ptr<State> state);
  std::unique_ptr<State> state_;
};

}  // namespace tessera::nodes
