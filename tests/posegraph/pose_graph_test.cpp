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
