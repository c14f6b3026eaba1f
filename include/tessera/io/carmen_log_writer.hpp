#pragma once
// Writing CARMEN laser logs (.clf, .log), the format of the Radish and Freiburg benchmark logs:
// a simulated run written with its true poses is a "corrected" log like theirs, which
// ../shared/tools/perturb_carmen.py gives a drifting odometry and other SLAM systems (GMapping,
// CARMEN itself) read.
#include <filesystem>

#include "tessera/core/result.hpp"
#include "tessera/sensors/laser_log.hpp"

namespace tessera {

/// Writes `log` so that read_carmen_log reads it back (io/carmen_log.hpp), atomically
/// (io/atomic_file.hpp: a failed write leaves `path` as it was).
///
/// Each scan becomes one line carrying its robot pose (StampedScan::odometry) and its laser pose
/// (odometry * laser_in_robot): `FLASER` when its beams lie where CARMEN's old format puts them
/// (the first at -pi/2, the increment CARMEN guesses from the beam count, within 1e-9 rad), else
/// `ROBOTLASER1` with its start angle, field of view, resolution and maximum range. Readings are
/// written as they are, so a no-return reading stays at or above the scan's max_range_m (FLASER
/// states no maximum: read_carmen_log then takes the file's largest reading less 0.1 m as "no
/// return", CarmenReadOptions::no_return_m). Each
/// LaserLog::odometry reading becomes an `ODOM` line (speeds 0), placed before the first scan with
/// a later stamp. Both stamps of a line are t_s; the host is "tessera". Numbers have 6 decimals
/// (1 um, 1 urad, 1 us). The poses are written even when log.has_odometry is false (then they are
/// the identity, as the log holds them).
///
/// Errors: kUsage for a scan with no beams, a NaN or infinite range or pose; kRuntime naming
/// `path` when it cannot be written.
[[nodiscard]] Status write_carmen_log(const std::filesystem::path& path, const LaserLog& log);

}  // namespace tessera
