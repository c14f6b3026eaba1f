#include "tessera/render/simulated_rgbd_sequence.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>

#include "sim/rgbd_room.hpp"
#include "support/temp_dir.hpp"
#include "tessera/io/tum_rgbd_sequence.hpp"

namespace tessera {
namespace {

namespace fs = std::filesystem;

TEST(TumRgbdSequence, ASimulatedRunRoundTripsFramesAndGroundTruth) {
  const World room = support::rgbd_room();
  RgbdRunOptions o;
  o.start = {2.0, 2.25, 0.3};
  o.waypoints_m = {{3.0, 2.0}};
  o.frame_rate_hz = 2.0;
  o.neck_sweep_amplitude_rad = 0.4;
  const Result<SimulatedRgbdRun> run = simulate_rgbd_run(room, o, 11);
  ASSERT_TRUE(run.ok()) << run.error().message;
  ASSERT_GE(run->frames.size(), 4u);
  const RgbdCamera cam = support::room_camera({}, /*noise=*/true);

  support::TempDir dir;
  const fs::path folder = dir / "sim_run";
  const Status written = write_simulated_rgbd_run(folder, cam, *run);
  ASSERT_TRUE(written.ok()) << written.error().message;
  EXPECT_FALSE(fs::exists(dir / ("sim_run.tmp-" + std::to_string(::getpid()))));

  const Result<TumRgbdSequence> seq = TumRgbdSequence::open(folder);
  ASSERT_TRUE(seq.ok()) << seq.error().message;
  ASSERT_EQ(seq->size(), run->frames.size());
  EXPECT_EQ(seq->intrinsics_source(), IntrinsicsSource::kFile);
  EXPECT_DOUBLE_EQ(seq->intrinsics().fx_px, cam.options().intrinsics.fx_px);
  EXPECT_EQ(seq->intrinsics().width_px, 640);
  EXPECT_TRUE(seq->has_ground_truth_file());
  for (std::size_t i = 0; i < seq->size(); ++i) {
    const TumRgbdEntry& e = seq->entry(i);
    EXPECT_NEAR(e.t_s, run->frames[i].t_s, 1e-6);
    ASSERT_TRUE(e.has_truth && e.has_odometry && e.has_neck) << i;
    const Pose2 truth = robot_pose_from_optical_frame(e.T_world_camera, e.neck_pan_rad);
    EXPECT_NEAR(truth.x, run->frames[i].truth.x, 1e-6);
    EXPECT_NEAR(truth.y, run->frames[i].truth.y, 1e-6);
    EXPECT_NEAR(std::remainder(truth.theta - run->frames[i].truth.theta, 2.0 * std::numbers::pi),
                0.0, 1e-6);
    EXPECT_NEAR(e.T_world_camera.position_m.z(), 1.03, 1e-6);
    EXPECT_NEAR(e.neck_pan_rad, run->frames[i].neck_pan_rad, 1e-8);
    EXPECT_NEAR(e.odometry.x, run->frames[i].odometry.x, 1e-6);
  }
  for (const std::size_t i : {std::size_t{0}, seq->size() - 1}) {
    const Result<RgbdFrame> back = seq->load(i);
    ASSERT_TRUE(back.ok()) << back.error().message;
    const RgbdFrame original = render_rgbd_run_frame(cam, *run, i);
    EXPECT_EQ(back->rgb, original.rgb);
    ASSERT_EQ(back->depth_m.size(), original.depth_m.size());
    int valid = 0;
    for (std::size_t p = 0; p < original.depth_m.size(); ++p) {
      // Half a TUM step (1 / 5000 m) plus float rounding at 4.5 m.
      ASSERT_NEAR(back->depth_m[p], original.depth_m[p], 0.5 / 5000.0 + 1e-6) << p;
      valid += original.depth_m[p] > 0.0F;
    }
    EXPECT_GT(valid, 100000);
  }
}

TEST(OpticalFramePose, LooksAlongTheCameraHeadingFromTheMountHeight) {
  // Robot at (1, 2) facing +y, neck panned 0: the optical z axis is the robot's heading, x points
  // to the robot's right (+x in the world), y down.
  const StampedPose3 p = optical_frame_pose(5.0, {1.0, 2.0, std::numbers::pi / 2}, 0.0, 0.8);
  EXPECT_DOUBLE_EQ(p.t_s, 5.0);
  EXPECT_NEAR(p.position_m.z(), 0.8, 1e-12);
  const Eigen::Vector3d z = p.orientation * Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d x = p.orientation * Eigen::Vector3d::UnitX();
  const Eigen::Vector3d y = p.orientation * Eigen::Vector3d::UnitY();
  EXPECT_NEAR(z.y(), 1.0, 1e-12);
  EXPECT_NEAR(x.x(), 1.0, 1e-12);
  EXPECT_NEAR(y.z(), -1.0, 1e-12);
  const Pose2 back = robot_pose_from_optical_frame(p, 0.0);
  EXPECT_NEAR(back.theta, std::numbers::pi / 2, 1e-12);
}

}  // namespace
}  // namespace tessera
