#include "tessera/render/simulated_rgbd_sequence.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>

#include "tessera/io/tum_rgbd_sequence.hpp"

namespace tessera {

StampedPose3 optical_frame_pose(double t_s, const Pose2& T_world_robot, double neck_pan_rad,
                                double mount_height_m) {
  const Pose2 cam = RgbdCamera::camera_pose(T_world_robot, neck_pan_rad);
  const double c = std::cos(cam.theta), s = std::sin(cam.theta);
  Eigen::Matrix3d R;
  // Columns: the optical x (right), y (down) and z (forward) axes in the world.
  R.col(0) = Eigen::Vector3d(s, -c, 0.0);
  R.col(1) = Eigen::Vector3d(0.0, 0.0, -1.0);
  R.col(2) = Eigen::Vector3d(c, s, 0.0);
  StampedPose3 p;
  p.t_s = t_s;
  p.position_m = Eigen::Vector3d(cam.x, cam.y, mount_height_m);
  p.orientation = Eigen::Quaterniond(R).normalized();
  return p;
}

Status write_simulated_rgbd_run(const std::filesystem::path& folder, const RgbdCamera& camera,
                                const SimulatedRgbdRun& run) {
  TumRgbdSequenceContent c;
  c.frame_count = run.frames.size();
  c.frame_at = [&](std::size_t i) { return render_rgbd_run_frame(camera, run, i); };
  const double mount = camera.options().mount_height_m;
  for (const RgbdRunFrame& f : run.frames) {
    c.ground_truth.push_back(optical_frame_pose(f.t_s, f.truth, f.neck_pan_rad, mount));
    c.odometry.push_back({f.t_s, f.odometry});
    c.neck_pan_rad.push_back(f.neck_pan_rad);
  }
  return write_tum_rgbd_sequence(folder, c);
}

}  // namespace tessera
