#include "tessera/fusion/replay.hpp"

namespace tessera::fusion {

Result<ReplayResult> replay(FusionSlam& slam, std::span<const ReplayStep> steps,
                            const FrameLoader& load, const ReplayProgress& progress) {
  ReplayResult result;
  result.path_m.reserve(steps.size());
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const ReplayStep& s = steps[i];
    const FusionUpdate u = slam.update(s.t_s, s.odometry, s.neck_pan_rad);
    if (u.wants_frame) {
      Result<RgbdFrame> frame = load(i);
      if (!frame) return frame.error();
      ++result.frames_loaded;
      (void)slam.add_frame(*frame);
    }
    // The estimate after the capture, so that a correction shows in the path at once.
    const Pose2 estimate = slam.estimate();
    result.path_m.push_back({estimate.x, estimate.y});
    if (progress) progress(i + 1, steps.size());
  }
  return result;
}

}  // namespace tessera::fusion
