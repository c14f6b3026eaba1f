#pragma once
// `tessera slam --serve`: the laser SLAM loop with the live view fed after every scan.
#include <vector>

#include "recording.hpp"
#include "tessera/core/result.hpp"
#include "tessera/sensors/laser_log.hpp"
#include "tessera/slam/laser_slam.hpp"

namespace tessera::cli {

/// slam::run_laser_slam (with a new trajectory at each of `starts`), or, when `recording` serves a
/// live view, the same loop with the current estimate published after every scan
/// (record/slam_recording.hpp's SlamLiveRecorder) and the map about once a second of wall time (a
/// map build costs what the final one does). The results are the same either way.
[[nodiscard]] Result<slam::LaserSlamResult> run_laser_slam_served(
    const LaserLog& log, const std::vector<slam::TrajectoryStart>& starts,
    const slam::LaserSlamOptions& options, Recording& recording,
    const slam::AfterScan& after_scan = {});

}  // namespace tessera::cli
