#include "slam_live.hpp"

#include <chrono>
#include <optional>

#include "tessera/record/slam_recording.hpp"

namespace tessera::cli {

Result<slam::LaserSlamResult> run_laser_slam_served(
    const LaserLog& log, const std::vector<slam::TrajectoryStart>& starts,
    const slam::LaserSlamOptions& options, Recording& recording, const AfterScan& after_scan) {
  MessageSink* live = recording.live_sink();
  if ((!live && !after_scan) || log.scans.empty()) {
    return slam::run_laser_slam(log, options, starts);
  }
  slam::LaserSlam slam(options);
  std::optional<SlamLiveRecorder> recorder;
  if (live) recorder.emplace(*live);
  const int total = static_cast<int>(log.scans.size());
  auto last_map = std::chrono::steady_clock::now();
  auto next_start = starts.begin();
  for (int i = 0; i < total; ++i) {
    const StampedScan& scan = log.scans[static_cast<std::size_t>(i)];
    if (next_start != starts.end() && next_start->first_scan == i) {
      if (Status s = slam.start_trajectory(next_start->T_map_robot); !s) return s.error();
      ++next_start;
    }
    if (Status s = slam.add_scan(scan, total); !s) return s.error();
    if (after_scan) {
      if (Status s = after_scan(slam, i + 1); !s) return s.error();
    }
    if (!recorder) continue;
    const bool with_map = std::chrono::steady_clock::now() - last_map > std::chrono::seconds(1);
    if (with_map) last_map = std::chrono::steady_clock::now();
    if (!recording.failed()) recording.note(recorder->scan(slam, scan, with_map));
    recording.step_done();
  }
  return slam.finish();
}

}  // namespace tessera::cli
