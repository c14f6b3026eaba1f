// Motion from depth alone (fusion/depth_icp.hpp): solved within 2 cm and 1 degree where the
// geometry pins it (a corner with the floor, the real TUM desk), refused where it does not (one
// plane, two planes), and never a confident wrong estimate.
#include "tessera/fusion/depth_icp.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "support/data.hpp"
#include "tessera/core/rng.hpp"
#include "tessera/io/rgbd_pair_folder.hpp"
#include "tessera/render/simulated_rgbd_sequence.hpp"
#include "tessera/sim/blank_room.hpp"

namespace tessera::fusion {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

struct SimPair {
  RgbdFrame prev;
  RgbdFrame curr;
  Eigen::Isometry3d T_prev_curr;
};

/// The view and a second frame after `motion` (robot frame), with the camera's depth noise.
SimPair render_pair(const BlankRoom& room, const BlankView& view, const Pose2& motion,
                    std::uint64_t seed) {
  Rng rng(seed);
  const Pose2 next = view.T_world_robot * motion;
  const double h = room.camera.options().mount_height_m;
  return {room.camera.render(view.T_world_robot, 0.0, 0.0, rng),
          room.camera.render(next, 0.0, 1.0, rng),
          optical_frame_pose(0.0, view.T_world_robot, 0.0, h).transform().inverse() *
              optical_frame_pose(1.0, next, 0.0, h).transform()};
}

const BlankView& view_named(const BlankRoom& room, const std::string& name) {
  for (const BlankView& v : room.views) {
    if (v.name == name) return v;
  }
  throw std::runtime_error("no view " + name);
}

double translation_error_m(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return (a.inverse() * b).translation().norm();
}

double rotation_error_rad(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return Eigen::AngleAxisd((a.inverse() * b).linear()).angle();
}

class DepthIcp : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    Result<BlankRoom> made = make_blank_room();
    ASSERT_TRUE(made) << made.error().message;
    room_ = new BlankRoom(std::move(made).value());
  }
  static void TearDownTestSuite() {
    delete room_;
    room_ = nullptr;
  }
  static BlankRoom* room_;
};
BlankRoom* DepthIcp::room_ = nullptr;

TEST_F(DepthIcp, ACornerWithTheFloorIsSolvedWithin2CmAnd1Degree) {
  const BlankView& view = view_named(*room_, "corner and floor (3.2 m)");
  ASSERT_TRUE(view.solvable);
  for (const Pose2& motion : {Pose2{0.04, -0.03, 2.0 * kDeg}, Pose2{-0.05, 0.02, -3.0 * kDeg},
                              Pose2{0.0, 0.05, 1.0 * kDeg}}) {
    const SimPair pair = render_pair(*room_, view, motion, 7);
    const DepthIcpResult r = align_depth(pair.prev, pair.curr, {});
    ASSERT_TRUE(r.accepted) << r.reason_text;
    EXPECT_EQ(r.reason, DepthIcpReason::kAccepted);
    EXPECT_LT(translation_error_m(r.T_prev_curr, pair.T_prev_curr), 0.02) << r.reason_text;
    EXPECT_LT(rotation_error_rad(r.T_prev_curr, pair.T_prev_curr), 1.0 * kDeg) << r.reason_text;
    EXPECT_GT(r.overlap, 0.8);
    EXPECT_GT(r.iterations, 0);
  }
}

TEST_F(DepthIcp, OnePlaneOrTwoLeaveAMotionFreeAndAreRefused) {
  for (const char* name : {"wall (1.5 m)", "wall and floor (3 m)", "corner (1.5 m)"}) {
    const BlankView& view = view_named(*room_, name);
    ASSERT_FALSE(view.solvable);
    const SimPair pair = render_pair(*room_, view, {0.03, 0.02, 1.5 * kDeg}, 11);
    const DepthIcpResult r = align_depth(pair.prev, pair.curr, {});
    EXPECT_FALSE(r.accepted) << name << ": " << r.reason_text;
    EXPECT_EQ(r.reason, DepthIcpReason::kDegenerate) << name << ": " << r.reason_text;
    EXPECT_NE(r.reason_text.find("condition number"), std::string::npos);
  }
}

TEST_F(DepthIcp, ViewsOfDifferentPlacesAreNotAcceptedAsAMotion) {
  // The corner and a wall 1.5 m away: no motion of a few centimetres relates them.
  Rng rng(3);
  const RgbdFrame corner = room_->camera.render(
      view_named(*room_, "corner and floor (3.2 m)").T_world_robot, 0.0, 0.0, rng);
  const RgbdFrame wall =
      room_->camera.render(view_named(*room_, "wall (1.5 m)").T_world_robot, 0.0, 1.0, rng);
  const DepthIcpResult r = align_depth(corner, wall, {});
  EXPECT_FALSE(r.accepted) << r.reason_text;
}

TEST_F(DepthIcp, FramesOfDifferentSizesAreRefusedAsInconsistent) {
  Rng rng(1);
  const RgbdFrame a = room_->camera.render(room_->views[0].T_world_robot, 0.0, 0.0, rng);
  RgbdFrame b = a;
  b.depth_m.pop_back();
  const DepthIcpResult r = align_depth(a, b, {});
  EXPECT_FALSE(r.accepted);
  EXPECT_EQ(r.reason, DepthIcpReason::kInconsistentFrames);
}

TEST(DepthIcpReal, TheTumDeskPairIsSolvedFromDepthAlone) {
  const auto folder = support::data_path("rgbd/tum_fr1_xyz_pairs/case_1");
  TESSERA_REQUIRE_DATA(folder);
  const Result<RgbdPair> pair = read_rgbd_pair_folder(folder);
  ASSERT_TRUE(pair) << pair.error().message;
  const DepthIcpResult r = align_depth(pair->prev, pair->curr, {});
  ASSERT_TRUE(r.accepted) << r.reason_text;
  EXPECT_LT(translation_error_m(r.T_prev_curr, pair->T_prev_curr_truth()), 0.02) << r.reason_text;
  EXPECT_LT(rotation_error_rad(r.T_prev_curr, pair->T_prev_curr_truth()), 1.0 * kDeg);
}

TEST(DepthIcpOptions, ValidateNamesTheBrokenField) {
  EXPECT_FALSE(validate(DepthIcpOptions{}));
  DepthIcpOptions o;
  o.levels = 0;
  EXPECT_NE(validate(o)->find("levels"), std::string::npos);
  o = {};
  o.max_condition_number = 0.5;
  EXPECT_NE(validate(o)->find("max_condition_number"), std::string::npos);
  o = {};
  o.min_depth_m = 5.0;
  EXPECT_NE(validate(o)->find("min_depth_m"), std::string::npos);
}

TEST(DepthIcpReason, NamesAreTheReportKeys) {
  EXPECT_EQ(to_string(DepthIcpReason::kAccepted), "accepted");
  EXPECT_EQ(to_string(DepthIcpReason::kDegenerate), "geometry degenerate");
  EXPECT_EQ(to_string(DepthIcpReason::kLowOverlap), "low overlap");
}

}  // namespace
}  // namespace tessera::fusion
