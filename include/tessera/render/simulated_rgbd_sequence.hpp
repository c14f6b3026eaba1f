#pragma once
// A simulated RGB-D run (sim/rgbd_run.hpp) written as a TUM RGB-D sequence folder
// (io/tum_rgbd_sequence.hpp), so that every experiment runs the same way on simulated and real
// data (thesis chapter 5: the recorded runs are replayed offline). The reader and the generic
// writer stay in io; this part needs the simulated camera, so it lives here.
#include <filesystem>

#include "tessera/core/pose2.hpp"
#include "tessera/core/result.hpp"
#include "tessera/sim/rgbd_camera.hpp"
#include "tessera/sim/rgbd_run.hpp"
#include "tessera/trajectory/stamped_pose3.hpp"

namespace tessera {

/// T_world_camera of the simulated camera's optical frame (z forward, x right, y down) for the
/// robot at T_world_robot with the neck at neck_pan_rad, the optical centre mount_height_m above
/// the floor on the pan axis (sim/rgbd_camera.hpp). io's robot_pose_from_optical_frame inverts it.
[[nodiscard]] StampedPose3 optical_frame_pose(double t_s, const Pose2& T_world_robot,
                                              double neck_pan_rad, double mount_height_m);

/// A simulated run as a TUM sequence (write_tum_rgbd_sequence): frames rendered by
/// render_rgbd_run_frame, ground truth = optical_frame_pose of the true pose, odometry.txt and
/// neck.txt from the run.
[[nodiscard]] Status write_simulated_rgbd_run(const std::filesystem::path& folder,
                                              const RgbdCamera& camera,
                                              const SimulatedRgbdRun& run);

}  // namespace tessera
