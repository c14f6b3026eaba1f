#pragma once
// CARMEN laser logs (.clf, .log): the format of the Radish and Freiburg SLAM benchmark logs (Intel
// Research Lab, FR079, ACES). Field layouts as CARMEN's own reader, src/global/readlog.c, parses
// them; the conventions this reader adds are in docs/decisions/0006-carmen-beam-geometry.md.
#include <filesystem>
#include <optional>
#include <string>

#include "tessera/core/result.hpp"
#include "tessera/sensors/laser_log.hpp"

namespace tessera {

/// What read_carmen_log decides where the old-format messages leave it open.
struct CarmenReadOptions {
  /// Readings >= this many metres mean "no return"; it becomes every scan's max_range_m. 0 picks it
  /// automatically: ROBOTLASER1 and RAWLASER1 scans use the maximum_range their message carries;
  /// FLASER and RLASER scans, which carry none, use the largest FLASER/RLASER reading in the file
  /// less 0.1 m, because logs store a missing return as the sensor's maximum (81.83 m in Intel,
  /// 81.91 m in FR079, 50 m in ACES, 51.05 and 51.1 m in FHW). A log with no missing return at
  /// all then loses the readings within 0.1 m of its farthest one; set the value for such a log.
  double no_return_m = 0.0;
  /// RLASER (rear laser) scans are skipped unless this is set. Read ones face backwards: their
  /// laser_in_robot is turned by pi unless the logged laser pose already is.
  bool rear_laser = false;
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const CarmenReadOptions& options);

/// Reads a CARMEN log in file order (stamps are not assumed to increase).
///
/// Messages: `ODOM x y theta tv rv accel` goes to LaserLog::odometry. Scans come from
/// `FLASER n r_0..r_{n-1} x y theta odom_x odom_y odom_theta` (front laser, old format), `RLASER`
/// (the same, rear laser), `ROBOTLASER1 type start_angle fov resolution max_range accuracy
/// remission_mode n r.. n_rem rem.. laser_x laser_y laser_theta robot_x robot_y robot_theta tv rv
/// forward_safety side_safety turn_axis` and `RAWLASER1 type start_angle fov resolution max_range
/// accuracy remission_mode n r.. n_rem rem..`. Every message ends in `ipc_timestamp ipc_hostname
/// logger_timestamp`. PARAM, NEFF, TRUEPOS, SYNC and any other message, '#' comments and blank
/// lines are skipped.
///
/// Stamp: t_s is the ipc_timestamp, the first of the three trailing fields (the time base of the
/// Kummerle relations files; the Intel raw and corrected logs carry the same value in both).
/// Poses: the first pose of a FLASER/RLASER/ROBOTLASER1 is the laser's in the world, the second
/// the robot's. StampedScan::odometry is the robot pose and laser_in_robot = between(robot, laser)
/// (in corrected logs both poses are the corrected one, so laser_in_robot is the identity).
/// RAWLASER1 has no pose: its odometry is interpolated at its stamp between the ODOM messages just
/// before and just after it in the file (linear in x, y, shortest arc in theta); when its stamp
/// lies outside theirs, or only one exists, it takes the one nearer in time. Its laser_in_robot is
/// the identity.
/// Beams: ROBOTLASER1/RAWLASER1 carry start_angle and resolution. FLASER/RLASER follow CARMEN's
/// guess from n: the first beam at -pi/2 (the robot's right), counter-clockwise, 1 degree apart for
/// 180 and 181 beams, 0.5 degree for 360 and 361, 0.25 degree for 400 and 401, and pi/(n-1)
/// otherwise (so 180 beams end at +89 degrees, as readlog.c's "last beam ignored").
/// LaserLog::backward_stamps counts scans whose stamp is smaller than the previous scan's.
///
/// Errors, kInput, "<path>:<line>: ...": an unreadable file, a truncated line, a FLASER/RLASER
/// whose beam count does not match its ranges, a field that is not a number where one is expected,
/// a NaN, infinite or negative range, a RAWLASER1 in a file without ODOM, and a file with no laser
/// scans at all. Usage error for invalid options.
/// Cost: one pass over the file (the 5.4 MB Intel raw log reads in about 0.1 s).
[[nodiscard]] Result<LaserLog> read_carmen_log(const std::filesystem::path& path,
                                               const CarmenReadOptions& options = {});

}  // namespace tessera
