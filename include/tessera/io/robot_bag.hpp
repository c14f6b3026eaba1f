#pragma once
// A robot's laser run in a ROS bag as a LaserLog (the type CARMEN logs give, so `tessera slam
// --bag` runs the same SLAM as --log): one StampedScan per sensor_msgs/LaserScan message (or
// MultiEchoLaserScan, read by its first echoes: ros_messages.hpp) with
//   - t_s: the scan's header stamp (its log time when the stamp is 0), seconds since the epoch;
//   - odometry: T_odom_base from nav_msgs/Odometry interpolated at t_s between the odometry
//     messages just before and after it (by header stamp; linear in x, y, shortest arc in theta;
//     the nearer one outside their span). When the base frame is not the odometry's
//     child_frame_id, T_child_base from tf is appended. A bag without nav_msgs/Odometry takes
//     its odometry from tf instead: the lowest moving edge above the laser frame (odom -> base,
//     as a base driver publishes it on /tf; TfTree::lowest_moving_edge), its child the base. A
//     bag with neither (scans alone) gives a log without odometry (LaserLog::has_odometry false,
//     every scan's odometry the identity) whose base frame is the laser's own unless
//     RobotBagOptions::base_frame names one;
//   - laser_in_robot: T_base_laser from the tf tree (/tf_static and /tf) at t_s: the chain from
//     the base frame to the scan's header.frame_id (e.g. base_footprint -> base_link ->
//     base_laser_link). Never an option: a bag without that chain is an input error. A laser
//     mounted upside down (its z axis down) has its scan mirrored (tf_tree.hpp's planar_laser);
//   - scan: angle_min, angle_increment, range_min and range_max of the message; readings that are
//     not a return (inf, NaN, 0 or negative, below range_min, above range_max: what drivers write
//     for "nothing seen") become range_max, RangeScan's no-return.
// LaserLog::odometry holds every odometry message's T_odom_base in time order.
#include <filesystem>
#include <string>
#include <vector>

#include "tessera/core/result.hpp"
#include "tessera/io/ros_bag.hpp"
#include "tessera/io/ros_messages.hpp"
#include "tessera/sensors/laser_log.hpp"

namespace tessera {

struct RobotBagOptions {
  /// The LaserScan topic; empty: the bag's only sensor_msgs/LaserScan topic.
  std::string scan_topic;
  /// The Odometry topic; empty: the bag's only nav_msgs/Odometry topic, or /tf's odom -> base
  /// when the bag has none.
  std::string odom_topic;
  /// The robot frame the laser pose and odometry refer to; empty: the odometry messages'
  /// child_frame_id.
  std::string base_frame;
};

/// A LaserLog and what it was made from.
struct RobotBag {
  LaserLog log;
  std::string format;      // RosBag::format
  std::string scan_topic;  // the topics and frames chosen
  std::string odom_topic;  // "/tf" when the odometry came from tf, empty when there is none
  std::string odom_frame;  // the odometry's header.frame_id (the tf edge's parent; empty: none)
  std::string base_frame;
  std::string laser_frame;     // the scans' header.frame_id (the first scan's)
  int no_return_readings = 0;  // readings mapped to no-return
};

/// The RangeScan of one sensor_msgs/LaserScan, as above: readings that are not a return become
/// range_max and are counted in `no_return_readings`. kInput error (without a location: the caller
/// names the file or topic) when angle_increment is 0 or not finite, angle_min is not finite or
/// range_max is not > 0. A clockwise scan (angle_increment < 0) comes back counter-clockwise: the
/// same beams in reverse order.
/// The beams' times are the message's time_increment from its stamp (the first beam's time, as
/// sensor_msgs/LaserScan defines it), unless the sweep they make would last over a second.
[[nodiscard]] Result<RangeScan> range_scan_of(const LaserScanMessage& msg, int& no_return_readings);

/// Topics whose message bytes read_robot_bag needs: LaserScan, Odometry, and TFMessage on
/// /tf and /tf_static.
[[nodiscard]] bool robot_bag_needs(const BagTopic& topic);

/// Converts an already read bag (read with robot_bag_needs, or keeping everything).
/// Errors: kUsage when several LaserScan or Odometry topics exist and the option does not choose
/// (naming the candidates), or an option names a topic the bag lacks or of another type; kInput,
/// naming `file`, for no LaserScan topic or no scans on it, an Odometry topic without messages,
/// a message that does not decode (topic and message number), a scan frame with no tf
/// chain to the base frame, and a scan whose angle_increment is 0 or not finite.
[[nodiscard]] Result<RobotBag> robot_bag_from(const RosBag& bag, const std::string& file,
                                              const RobotBagOptions& options = {});

/// read_ros_bag(path) keeping robot_bag_needs, then robot_bag_from.
[[nodiscard]] Result<RobotBag> read_robot_bag(const std::filesystem::path& path,
                                              const RobotBagOptions& options = {});

}  // namespace tessera
