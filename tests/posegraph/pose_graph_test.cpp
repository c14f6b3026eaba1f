#include "tessera/posegraph/pose_graph.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace tessera::posegraph {
namespace {

// A square of four odometry edges with a drifting heading, closed by one loop edge: the optimum
// puts the nodes back on the square.
TEST(PoseGraph, LoopClosureStraightensASquare) {
  PoseGraph graph;
  const double half_pi = std::numbers::pi / 2.0;
  const Pose2 side{2.0, 0.0, half_pi};
  graph.poses.push_back({});
  for (int i = 0; i < 3; ++i) {
    const Pose2 drifted{side.x, side.y, side.theta + 0.1};
    graph.poses.push_back(graph.poses.back() * drifted);
  }
  for (int i = 0; i < 3; ++i) graph.edges.push_back({i, i + 1, side});
  graph.edges.push_back({3, 0, side});
  const auto summary = optimize(graph, {});
  ASSERT_TRUE(summary.ok()) << summary.error().message;
  EXPECT_GT(summary->initial_cost, 1e-3);
  EXPECT_LT(summary->final_cost, 1e-12);
  EXPECT_NEAR(graph.poses[2].x, 2.0, 1e-6);
  EXPECT_NEAR(graph.poses[2].y, 2.0, 1e-6);
  EXPECT_NEAR(std::abs(graph.poses[2].theta), std::numbers::pi, 1e-6);
}

// One wrong loop closure among right ones barely moves the map when closures carry the robust
// loss, and bends it when they do not.
TEST(PoseGraph, RobustLossLimitsAWrongClosure) {
  const auto end_after_wrong_closure = [](bool robust) {
    const Eigen::Matrix3d information = 100.0 * Eigen::Matrix3d::Identity();
    PoseGraph graph;
    for (int i = 0; i <= 10; ++i) graph.poses.push_back({1.0 * i, 0.0, 0.0});
    for (int i = 0; i < 10; ++i) graph.edges.push_back({i, i + 1, {1.0, 0.0, 0.0}, information});
    graph.edges.push_back({0, 10, {10.0, 0.0, 0.0}, information, robust});
    graph.edges.push_back({2, 10, {8.0, 0.0, 0.0}, information, robust});
    graph.edges.push_back({0, 8, {8.0, 0.0, 0.0}, information, robust});
    graph.edges.push_back({0, 10, {7.0, 3.0, 0.5}, information, robust});  // the wrong one
    EXPECT_TRUE(optimize(graph, {}).ok());
    return graph.poses[10];
  };
  const Pose2 robust = end_after_wrong_closure(true);
  EXPECT_NEAR(robust.x, 10.0, 0.1);
  EXPECT_NEAR(robust.y, 0.0, 0.1);
  const Pose2 plain = end_after_wrong_closure(false);
  EXPECT_GT(std::hypot(plain.x - 10.0, plain.y), 0.5);
}

// A corridor walked with a gyro that drifts 0.5 degrees per step: the odometry edges carry the
// drift, the Manhattan priors (every scan's walls along the corridor, offset 0) take it out; the
// axis is estimated, here from a start 3 degrees off.
TEST(PoseGraph, ManhattanPriorsRemoveHeadingDriftAlongACorridor) {
  constexpr double kDeg = std::numbers::pi / 180.0;
  PoseGraph graph;
  const int n = 20;
  for (int i = 0; i < n; ++i) graph.poses.push_back({1.0 * i, 0.0, 0.5 * kDeg * i});
  Eigen::Matrix3d information = Eigen::Matrix3d::Identity();
  information(2, 2) = 1.0 / (0.5 * kDeg * 0.5 * kDeg);  // the odometry's own heading sigma
  for (int i = 0; i + 1 < n; ++i) {
    graph.edges.push_back({i, i + 1, {1.0, 0.0, 0.5 * kDeg}, information});
  }
  for (int i = 0; i < n; ++i) graph.heading_priors.push_back({i, 0.0, 1.0 * kDeg});
  graph.axis_rad = 3.0 * kDeg;
  const auto summary = optimize(graph, {});
  ASSERT_TRUE(summary.ok()) << summary.error().message;
  // Node 0 is held at heading 0, so the axis settles near 0 and the 9.5 degrees of drift at the
  // end shrink to under a quarter (what remains is the balance of the edges' and the priors'
  // sigmas).
  EXPECT_NEAR(graph.axis_rad, 0.0, 1.5 * kDeg);
  EXPECT_LT(std::abs(graph.poses[n - 1].theta), 0.25 * 9.5 * kDeg);
}

// Walls across the axis count as along it (period 90 degrees), and a scan whose walls are 30
// degrees off the axis is an outlier under the Cauchy loss: its pull is bounded and small.
TEST(PoseGraph, ManhattanPriorsFoldRightAnglesAndIgnoreOddWalls) {
  constexpr double kDeg = std::numbers::pi / 180.0;
  PoseGraph graph;
  graph.poses = {{0.0, 0.0, 0.0}, {1.0, 0.0, 90.0 * kDeg}, {1.0, 1.0, 92.0 * kDeg}};
  Eigen::Matrix3d loose = Eigen::Matrix3d::Identity() * 100.0;
  loose(2, 2) = 1.0 / (5.0 * kDeg * 5.0 * kDeg);
  graph.edges.push_back({0, 1, {1.0, 0.0, 90.0 * kDeg}, loose});
  graph.edges.push_back({1, 2, {1.0, 0.0, 2.0 * kDeg}, loose});
  graph.heading_priors = {{0, 0.0, 1.0 * kDeg}, {1, 0.0, 1.0 * kDeg}, {2, 0.0, 1.0 * kDeg}};
  const auto summary = optimize(graph, {});
  ASSERT_TRUE(summary.ok()) << summary.error().message;
  EXPECT_NEAR(graph.poses[2].theta, 90.0 * kDeg, 0.5 * kDeg);  // pulled to the right angle

  PoseGraph odd = graph;
  odd.poses[2].theta = 92.0 * kDeg;
  odd.heading_priors[2].offset_rad = 30.0 * kDeg;  // its walls point 30 degrees off the axis
  ASSERT_TRUE(optimize(odd, {}).ok());
  EXPECT_NEAR(odd.poses[2].theta, 92.0 * kDeg, 1.0 * kDeg);  // left near where the edges put it
}

TEST(PoseGraph, HeadingPriorOnAMissingNodeIsAnError) {
  PoseGraph graph;
  graph.poses = {{}, {1.0, 0.0, 0.0}};
  graph.edges.push_back({0, 1, {1.0, 0.0, 0.0}});
  graph.heading_priors.push_back({5, 0.0, 0.05});
  const auto summary = optimize(graph, {});
  ASSERT_FALSE(summary.ok());
  EXPECT_NE(summary.error().message.find("heading prior on node 5"), std::string::npos);
}

TEST(PoseGraph, EdgeToMissingNodeIsAnError) {
  PoseGraph graph;
  graph.poses.push_back({});
  graph.edges.push_back({0, 3, {}});
  const auto summary = optimize(graph, {});
  ASSERT_FALSE(summary.ok());
  EXPECT_THAT(summary.error().message, testing::HasSubstr("not in the graph"));
}

}  // namespace
}  // namespace tessera::posegraph
