#pragma once
// tessera's maps, poses, scans and cells as the ROS 2 messages a recording or the live view
// carries (io/ros_message_encoders.hpp). Frames: "map" for the world, "<robot>/base_link" for a
// robot, "<robot>/laser" for its scanner.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "tessera/core/pose2.hpp"
#include "tessera/core/stamped_pose2.hpp"
#include "tessera/grid/occupancy_grid.hpp"
#include "tessera/io/ros_message_encoders.hpp"
#include "tessera/sensors/range_scan.hpp"

namespace tessera {

/// Nanoseconds of a time in seconds (rounded to the nearest).
[[nodiscard]] std::int64_t to_ns(double t_s);

/// nav_msgs/OccupancyGrid of `map`: unknown cells -1, known ones their probability in percent
/// (rounded), origin the grid's lower-left corner.
[[nodiscard]] OccupancyGridMessage occupancy_grid_message(const OccupancyGrid& map,
                                                          std::int64_t stamp_ns,
                                                          const std::string& frame);
/// The same for the cells of `box` only (inside the map), at their place in space: origin the
/// box's lower-left corner. A robot sends the known_box() of its map so.
[[nodiscard]] OccupancyGridMessage occupancy_grid_message(const OccupancyGrid& map,
                                                          const CellBox& box, std::int64_t stamp_ns,
                                                          const std::string& frame);

/// nav_msgs/Path through `poses`, each stamped with `stamps_ns` (same length) in `frame`.
[[nodiscard]] PathMessage path_message(std::span<const Pose2> poses,
                                       std::span<const std::int64_t> stamps_ns,
                                       std::int64_t stamp_ns, const std::string& frame);

/// nav_msgs/Path through a stamped trajectory, each pose at its own stamp moved by `offset_ns`.
[[nodiscard]] PathMessage path_message(std::span<const StampedPose2> trajectory,
                                       std::int64_t stamp_ns, const std::string& frame,
                                       std::int64_t offset_ns = 0);

/// sensor_msgs/LaserScan of a scan in its sensor frame; ranges outside [min, max] stay as they
/// are (a reader treats them as no return). The beams' times go as time_increment from the stamp
/// (a scan whose first beam was not taken at its stamp, nor its last, keeps only the increment).
[[nodiscard]] LaserScanMessage laser_scan_message(const RangeScan& scan, std::int64_t stamp_ns,
                                                  const std::string& frame);

/// One geometry_msgs/TransformStamped: T_parent_child of a planar pose.
[[nodiscard]] TransformStampedMessage planar_transform_stamped(const Pose2& T_parent_child,
                                                               std::int64_t stamp_ns,
                                                               const std::string& parent,
                                                               const std::string& child);

/// A CUBE_LIST marker of grid cells (their centres at height z_m, cubes one cell wide and
/// `height_m` tall) in `frame`.
[[nodiscard]] MarkerMessage cell_marker(std::span<const Cell> cells, const GridGeometry& geometry,
                                        std::int64_t stamp_ns, const std::string& frame,
                                        const std::string& ns, RosColor color,
                                        double height_m = 0.05, double z_m = 0.0);

}  // namespace tessera
