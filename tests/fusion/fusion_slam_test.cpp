// The online Fusion SLAM: the map grows with odometry, frames are wanted in firing fields only, and
// an accepted node match corrects odometry drift through the pose graph (thesis 6.2 item 2).
#include "tessera/fusion/fusion_slam.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "sim/rgbd_room.hpp"

namespace tessera::fusion {
namespace {

TEST(FusionSlam, WithoutFramesTheEstimateIsOdometryAndTheMapGrows) {
  FusionSlam slam;
  int wanted = 0;  // firing-field entries that want a frame (it keeps wanting one until it comes)
  bool wanting = false;
  for (int i = 0; i <= 100; ++i) {
    const Pose2 odom{0.02 * i, 0.0, 0.0};  // 2 m along x
    const FusionUpdate u = slam.update(0.1 * i, odom, 0.0);
    if (u.wants_frame && !wanting) ++wanted;
    wanting = u.wants_frame;
    EXPECT_NEAR(slam.estimate().x, odom.x, 1e-12);
    EXPECT_NEAR(slam.estimate().y, 0.0, 1e-12);
  }
  // Cells every 0.3 m * sqrt(3)/2 along x (zigzag columns) or 0.3 m: at least 6 for 2 m.
  EXPECT_GE(slam.map().cell_count(), 6u);
  // Pose nodes every 0.15 m.
  EXPECT_NEAR(static_cast<double>(slam.map().pose_nodes().size()), 2.0 / 0.15, 2.0);
  // A capture is wanted once per firing-field visit, not at every update.
  EXPECT_GE(wanted, 3);
  EXPECT_LE(static_cast<std::size_t>(wanted), slam.map().cell_count());
  EXPECT_EQ(slam.image_nodes().size(), 0u);
  EXPECT_EQ(slam.corrected_trajectory().size(), slam.odometry_trajectory().size());
}

TEST(FusionSlam, AMatchWithTheFirstNodeRemovesOdometryDrift) {
  const RgbdCamera camera = support::room_camera();
  Rng rng(1);
  const Pose2 truth{4.0, 2.25, 0.0};  // facing the east poster, 2.95 m away
  FusionSlam slam;
  const FusionUpdate first = slam.update(0.0, truth, 0.0);
  ASSERT_TRUE(first.wants_frame);
  const FusionCapture c0 = slam.add_frame(camera.render(truth, 0.0, 0.0, rng));
  ASSERT_TRUE(c0.stored) << to_string(c0.check);
  // The robot has not moved, but its odometry says it drove 11 cm and turned 1.1 degrees.
  const Pose2 drifted{4.1, 2.3, 0.02};
  (void)slam.update(1.0, drifted, 0.0);
  EXPECT_NEAR(slam.estimate().x, 4.1, 1e-9);
  const FusionCapture c1 = slam.add_frame(camera.render(truth, 0.0, 1.0, rng));
  ASSERT_TRUE(c1.stored);
  ASSERT_EQ(c1.accepted, 1) << (c1.matches.empty() ? "" : c1.matches[0].reason);
  EXPECT_TRUE(c1.optimised);
  EXPECT_EQ(slam.match_edges(), 1u);
  // One match against one short odometry edge: the estimate moves most of the way (the edges are
  // weighted by their standard deviations: 1 cm for the match, 3.3 cm for 11 cm of odometry).
  const Pose2 corrected = slam.estimate();
  EXPECT_NEAR(corrected.x, truth.x, 0.02);
  EXPECT_NEAR(corrected.y, truth.y, 0.02);
  EXPECT_NEAR(corrected.theta, truth.theta, 0.01);
  // The stored nodes moved with the graph.
  EXPECT_NEAR(slam.image_nodes()[1].node.placement.T_map_robot.x, corrected.x, 1e-9);
  // The image-node search's confirmation sees the robot on the node.
  const NodeConfirmation confirm = slam.confirm_node(0, camera.render(truth, 0.0, 2.0, rng));
  ASSERT_TRUE(confirm.confirmed) << confirm.reason;
  EXPECT_NEAR(std::hypot(confirm.T_node_robot.x, confirm.T_node_robot.y), 0.0, 0.01);
}

TEST(FusionSlam, ABlankWallIsNeverANodeOrAMatch) {
  const RgbdCamera camera = support::room_camera();
  Rng rng(2);
  const Pose2 facing_north{3.5, 2.5, 1.5707963267948966};  // the north wall is blank
  FusionSlam slam;
  (void)slam.update(0.0, facing_north, 0.0);
  const FusionCapture c = slam.add_frame(camera.render(facing_north, 0.0, 0.0, rng));
  EXPECT_FALSE(c.stored);
  EXPECT_NE(c.check, NodeCheck::kOk);
  EXPECT_EQ(slam.statistics().frames_rejected, 1);
  EXPECT_EQ(slam.match_edges(), 0u);
}

// The same view captured again where odometry says the robot is 5 m away (far beyond the first
// node's neighbouring cells, with recent nodes left out): the thesis' search by cell never
// compares the two; a whole-map search does, and then only the graph gate stands between the
// match and the graph (issue 18 item 11's ablation).
struct FarCopy {
  FusionCapture second;
  std::size_t match_edges = 0;
  std::vector<Relation> relations;
};
FarCopy capture_the_same_view_far_away(CandidateSearch search, bool gate) {
  const RgbdCamera camera = support::room_camera();
  Rng rng(3);
  const Pose2 truth{4.0, 2.25, 0.0};  // facing the east poster
  FusionSlamOptions options;
  options.recent_candidates = 0;
  options.candidate_search = search;
  options.match_gate = gate;
  FusionSlam slam(options);
  (void)slam.update(0.0, truth, 0.0);
  const FusionCapture first = slam.add_frame(camera.render(truth, 0.0, 0.0, rng));
  EXPECT_TRUE(first.stored);
  for (int i = 1; i <= 100; ++i) (void)slam.update(0.1 * i, {4.0 - 0.05 * i, 2.25, 0.0}, 0.0);
  FarCopy out;
  out.second = slam.add_frame(camera.render(truth, 0.0, 10.0, rng));
  EXPECT_TRUE(out.second.stored);
  out.match_edges = slam.match_edges();
  out.relations = slam.match_relations();
  return out;
}

TEST(FusionSlam, OnlyAWholeMapSearchComparesANodeWithAFarCopyAndTheGateRefusesIt) {
  const FarCopy cells = capture_the_same_view_far_away(CandidateSearch::kCells, true);
  EXPECT_TRUE(cells.second.matches.empty());
  EXPECT_EQ(cells.match_edges, 0u);

  const FarCopy gated = capture_the_same_view_far_away(CandidateSearch::kWholeMap, true);
  ASSERT_EQ(gated.second.matches.size(), 1u);
  EXPECT_EQ(gated.second.matches[0].stored_node, 0u);
  EXPECT_FALSE(gated.second.matches[0].accepted);
  EXPECT_EQ(gated.second.matches[0].reason, "inconsistent with the graph");
  EXPECT_EQ(gated.match_edges, 0u);

  const FarCopy ungated = capture_the_same_view_far_away(CandidateSearch::kWholeMap, false);
  ASSERT_EQ(ungated.second.matches.size(), 1u);
  EXPECT_TRUE(ungated.second.matches[0].accepted) << ungated.second.matches[0].reason;
  ASSERT_EQ(ungated.relations.size(), 1u);
  // The match claims the robot is where it stood at the first capture (t = 0 s, 10 s).
  EXPECT_DOUBLE_EQ(ungated.relations[0].t1_s, 0.0);
  EXPECT_DOUBLE_EQ(ungated.relations[0].t2_s, 10.0);
  EXPECT_NEAR(ungated.relations[0].motion.x, 0.0, 0.02);
  EXPECT_NEAR(ungated.relations[0].motion.y, 0.0, 0.02);
}

TEST(FusionSlam, InvalidOptionsNameTheField) {
  FusionSlamOptions o;
  EXPECT_FALSE(validate(o));
  o.match_sigma_xy_m = 0.0;
  ASSERT_TRUE(validate(o));
  EXPECT_NE(validate(o)->find("match"), std::string::npos);
  o = {};
  o.map.cell_radius_m = -1.0;
  ASSERT_TRUE(validate(o));
  EXPECT_EQ(validate(o)->rfind("map: ", 0), 0u);
}

}  // namespace
}  // namespace tessera::fusion
