#include "slam_live.hpp"

#include <chrono>

#include "tessera/record/slam_recording.hpp"

namespace tessera::cli {

Result<slam::LaserSlamResult> run_laser_slam_served(
    const LaserLog& log, const std::vector<slam::TrajectoryStart>& starts,
    const slam::LaserSlamOptions& options, Recording& recording,
    const slam::AfterScan& after_scan) {
  MessageSink* live = recording.live_sink();
  if (!live) return slam::run_laser_slam(log, options, starts, after_scan);
  SlamLiveRecorder recorder(*live);
  auto last_map = std::chrono::steady_clock::now();
  return slam::run_laser_slam(
      log, options, starts, [&](const slam::LaserSlam& slam, int done) -> Status {
        if (after_scan) {
          if (Status s = after_scan(slam, done); !s) return s;
        }
        const bool with_map = std::chrono::steady_clock::now() - last_map > std::chrono::seconds(1);
        if (with_map) last_map = std::chrono::steady_clock::now();
        const StampedScan& scan = log.scans[static_cast<std::size_t>(done - 1)];
        if (!recording.failed()) recording.note(recorder.scan(slam, scan, with_map));
        recording.step_done();
        return Ok{};
      });
}

}  // namespace tessera::cli
