#include "slam_live.hpp"

#include <chrono>

#include "tessera/record/slam_recording.hpp"

namespace tessera::cli {

Result<slam::LaserSlamResult> run_laser_slam_served(const LaserLog& log,
                                                    const slam::LaserSlamOptions& options,
                                                    Recording& recording) {
  MessageSink* live = recording.live_sink();
  if (!live || log.scans.empty()) return slam::run_laser_slam(log, options);
  slam::LaserSlam slam(options);
  SlamLiveRecorder recorder(*live);
  const int total = static_cast<int>(log.scans.size());
  auto last_map = std::chrono::steady_clock::now();
  for (const StampedScan& scan : log.scans) {
    if (Status s = slam.add_scan(scan, total); !s) return s.error();
    const bool with_map = std::chrono::steady_clock::now() - last_map > std::chrono::seconds(1);
    if (with_map) last_map = std::chrono::steady_clock::now();
    if (!recording.failed()) recording.note(recorder.scan(slam, scan, with_map));
    recording.step_done();
  }
  return slam.finish();
}

}  // namespace tessera::cli
