#pragma once
// Feeding a recorded run to the online Fusion SLAM (fusion_slam.hpp), the same way for a real TUM
// RGB-D sequence (io/tum_rgbd_sequence.hpp) and a simulated run (sim/rgbd_run.hpp): the odometry
// pose and neck angle of every frame go to update(), and a frame is loaded only when the system
// asks for one (a firing field, thesis section 4.3.2), which keeps a long sequence cheap.
#include <cstddef>
#include <functional>
#include <span>
#include <vector>

#include "tessera/core/pose2.hpp"
#include "tessera/core/result.hpp"
#include "tessera/core/vec2.hpp"
#include "tessera/fusion/fusion_slam.hpp"
#include "tessera/sensors/rgbd_frame.hpp"

namespace tessera::fusion {

/// One recorded frame's odometry: T_odom_robot as the wheels report it and the neck's pan angle.
struct ReplayStep {
  double t_s = 0.0;
  Pose2 odometry;
  double neck_pan_rad = 0.0;
};

/// Loads the frame of step i (from disk, or renders it); an error ends the replay.
using FrameLoader = std::function<Result<RgbdFrame>(std::size_t step)>;
/// Called after each step with (steps done, steps in all), e.g. for a progress line.
using ReplayProgress = std::function<void(std::size_t, std::size_t)>;

struct ReplayResult {
  std::vector<Vec2> path_m;  // the corrected estimate after each step (map frame)
  int frames_loaded = 0;
};

/// Runs `slam` along `steps` (stamps must not decrease). Errors: the loader's, passed on as they
/// are. Cost: one update() per step plus one add_frame() per frame the system asks for.
[[nodiscard]] Result<ReplayResult> replay(FusionSlam& slam, std::span<const ReplayStep> steps,
                                          const FrameLoader& load,
                                          const ReplayProgress& progress = {});

}  // namespace tessera::fusion
