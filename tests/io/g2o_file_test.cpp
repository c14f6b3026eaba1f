#include "tessera/io/g2o_file.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <numbers>
#include <string>

#include "io_test_util.hpp"
#include "support/data.hpp"

namespace tessera {
namespace {

using io_test::TempDir;
using ::testing::HasSubstr;
using ::testing::StartsWith;

Result<posegraph::PoseGraph> read_g2o_text(const TempDir& dir, const std::string& text) {
  io_test::write_bytes(dir / "g.g2o", text);
  return read_g2o(dir / "g.g2o");
}

TEST(G2oFile, MapsVertexIdsToNodeIndicesInFileOrder) {
  TempDir dir;
  const Result<posegraph::PoseGraph> g = read_g2o_text(
      dir,
      "# a comment\nVERTEX_SE2 20 1 2 0.5\nVERTEX_SE2 10 0 0 0\n\nFIX 10\n"
      "EDGE_SE2 10 20 1 2 0.5 11 1 2 22 3 33\r\nEDGE_SE2\t20  10 -1 0 7 1 0 0 1 0 1\n");
  ASSERT_TRUE(g.ok()) << g.error().message;
  ASSERT_EQ(g->poses.size(), 2u);
  EXPECT_EQ(g->ids, (std::vector<int>{20, 10}));
  EXPECT_DOUBLE_EQ(g->poses[0].x, 1.0);
  EXPECT_DOUBLE_EQ(g->poses[0].theta, 0.5);
  ASSERT_EQ(g->edges.size(), 2u);
  const posegraph::PoseGraphEdge& e = g->edges[0];
  EXPECT_EQ(e.from, 1);
  EXPECT_EQ(e.to, 0);
  EXPECT_DOUBLE_EQ(e.measurement.y, 2.0);
  EXPECT_FALSE(e.robust);
  Eigen::Matrix3d expected;
  expected << 11, 1, 2, 1, 22, 3, 2, 3, 33;
  EXPECT_EQ(e.information, expected);
  EXPECT_NEAR(g->edges[1].measurement.theta, 7.0 - 2.0 * std::numbers::pi, 1e-12) << "wrapped";
}

TEST(G2oFile, EdgesOnlyFileChainsTheOdometryEdgesFromTheOrigin) {
  TempDir dir;
  const std::string info = " 1 0 0 1 0 1\n";
  const Result<posegraph::PoseGraph> g = read_g2o_text(
      dir, "EDGE_SE2 0 2 9 9 0" + info +  // a loop edge
               "EDGE_SE2 1 2 1 0 1.5707963267948966" + info + "EDGE_SE2 0 1 2 0 0" + info);
  ASSERT_TRUE(g.ok()) << g.error().message;
  EXPECT_EQ(g->ids, (std::vector<int>{0, 1, 2}));
  ASSERT_EQ(g->poses.size(), 3u);
  EXPECT_DOUBLE_EQ(g->poses[0].x, 0.0);
  EXPECT_DOUBLE_EQ(g->poses[1].x, 2.0);
  EXPECT_DOUBLE_EQ(g->poses[2].x, 3.0);
  EXPECT_NEAR(g->poses[2].theta, std::numbers::pi / 2.0, 1e-15);
  EXPECT_EQ(g->edges.size(), 3u);
  EXPECT_EQ(g->edges[0].to, 2);
}

TEST(G2oFile, RoundTripGivesTheGraphBackExactly) {
  posegraph::PoseGraph graph;
  graph.poses = {{0.1, -0.2, 0.3}, {1.0 / 3.0, 2.5e-7, -3.1}, {-4.0, 5.0, 1e-9}};
  graph.ids = {5, 7, 9};
  Eigen::Matrix3d info;
  info << 100.0 / 3.0, 0.1, 0.2, 0.1, 50.0, -0.3, 0.2, -0.3, 1000.0;
  graph.edges.push_back({0, 1, {1.0 / 7.0, 0.2, -0.1}, info});
  graph.edges.push_back({2, 0, {-1.0, 0.0, 3.0}, Eigen::Matrix3d::Identity()});
  TempDir dir;
  ASSERT_TRUE(write_g2o(dir / "g.g2o", graph).ok());
  EXPECT_EQ(io_test::files_in(dir.path()), (std::vector<std::string>{"g.g2o"})) << "no temp";
  const Result<posegraph::PoseGraph> back = read_g2o(dir / "g.g2o");
  ASSERT_TRUE(back.ok()) << back.error().message;
  EXPECT_EQ(back->ids, graph.ids);
  ASSERT_EQ(back->poses.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(back->poses[i].x, graph.poses[i].x);
    EXPECT_EQ(back->poses[i].y, graph.poses[i].y);
    EXPECT_EQ(back->poses[i].theta, graph.poses[i].theta);
  }
  ASSERT_EQ(back->edges.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(back->edges[i].from, graph.edges[i].from);
    EXPECT_EQ(back->edges[i].to, graph.edges[i].to);
    EXPECT_EQ(back->edges[i].measurement.x, graph.edges[i].measurement.x);
    EXPECT_EQ(back->edges[i].measurement.theta, graph.edges[i].measurement.theta);
    EXPECT_EQ(back->edges[i].information, graph.edges[i].information);
  }
}

TEST(G2oFile, EncodeWritesNodeIndicesWhenTheGraphHasNoIds) {
  posegraph::PoseGraph graph;
  graph.poses = {{}, {1.5, 0, 0}};
  graph.edges.push_back({0, 1, {1.5, 0, 0}, 2.0 * Eigen::Matrix3d::Identity()});
  EXPECT_EQ(encode_g2o(graph),
            "VERTEX_SE2 0 0 0 0\nVERTEX_SE2 1 1.5 0 0\nEDGE_SE2 0 1 1.5 0 0 2 0 0 2 0 2\n");
}

TEST(G2oFile, FailedWriteLeavesNothingBehind) {
  TempDir dir;
  posegraph::PoseGraph graph;
  graph.poses = {{}};
  const Status s = write_g2o(dir / "missing-folder" / "g.g2o", graph);
  ASSERT_FALSE(s.ok());
  EXPECT_TRUE(io_test::files_in(dir.path()).empty());
}

void expect_bad_g2o(const std::string& text, const std::string& where, const std::string& phrase) {
  TempDir dir;
  const Result<posegraph::PoseGraph> g = read_g2o_text(dir, text);
  ASSERT_FALSE(g.ok());
  EXPECT_EQ(g.error().kind, ErrorKind::kInput);
  EXPECT_THAT(g.error().message, StartsWith((dir / where).string()));
  EXPECT_THAT(g.error().message, HasSubstr(phrase));
}

const std::string kVertices = "VERTEX_SE2 0 0 0 0\nVERTEX_SE2 1 1 0 0\n";

TEST(G2oFile, EdgeNamingAMissingVertexIsRejected) {
  expect_bad_g2o(kVertices + "EDGE_SE2 0 1 1 0 0 1 0 0 1 0 1\nEDGE_SE2 1 7 1 0 0 1 0 0 1 0 1\n",
                 "g.g2o:4:", "EDGE_SE2 names vertex 7, which has no VERTEX_SE2 line");
}

TEST(G2oFile, EdgesOnlyVertexOutsideTheOdometryChainIsRejected) {
  expect_bad_g2o("EDGE_SE2 0 1 1 0 0 1 0 0 1 0 1\nEDGE_SE2 2 3 1 0 0 1 0 0 1 0 1\n",
                 "g.g2o:2:", "vertex 2 is not reached by the odometry chain");
}

TEST(G2oFile, VertexWithTooFewFieldsIsRejected) {
  expect_bad_g2o("VERTEX_SE2 0 0 0\n", "g.g2o:1:", "VERTEX_SE2 line has 4 fields, expected 5");
}

TEST(G2oFile, EdgeWithTooFewFieldsIsRejected) {
  expect_bad_g2o(kVertices + "EDGE_SE2 0 1 1 0 0 1 0 0 1 0\n",
                 "g.g2o:3:", "EDGE_SE2 line has 11 fields, expected 12");
}

TEST(G2oFile, NonIntegerVertexIdIsRejected) {
  expect_bad_g2o("VERTEX_SE2 1.5 0 0 0\n", "g.g2o:1:", "vertex id '1.5' is not an integer");
}

TEST(G2oFile, NonNumericFieldIsRejected) {
  expect_bad_g2o(kVertices + "EDGE_SE2 0 1 1 0 0 1 0 0 one 0 1\n",
                 "g.g2o:3:", "EDGE_SE2 I22 is 'one', expected a finite number");
}

TEST(G2oFile, NanPoseIsRejected) {
  expect_bad_g2o("VERTEX_SE2 0 nan 0 0\n", "g.g2o:1:", "VERTEX_SE2 x is 'nan'");
}

TEST(G2oFile, RepeatedVertexIsRejected) {
  expect_bad_g2o(kVertices + "VERTEX_SE2 0 5 5 0\n",
                 "g.g2o:3:", "vertex 0 is already defined on line 1");
}

TEST(G2oFile, EdgeFromAVertexToItselfIsRejected) {
  expect_bad_g2o(kVertices + "EDGE_SE2 1 1 0 0 0 1 0 0 1 0 1\n",
                 "g.g2o:3:", "joins vertex 1 to itself");
}

TEST(G2oFile, InformationThatIsNotPositiveDefiniteIsRejected) {
  expect_bad_g2o(kVertices + "EDGE_SE2 0 1 1 0 0 1 0 0 1 0 0\n",
                 "g.g2o:3:", "EDGE_SE2 0 1: information matrix is not positive definite");
  expect_bad_g2o(kVertices + "EDGE_SE2 0 1 1 0 0 1 2 0 1 0 1\n",
                 "g.g2o:3:", "not positive definite");
}

TEST(G2oFile, FileWithoutVerticesOrEdgesIsRejected) {
  expect_bad_g2o("# nothing\nFIX 0\n", "g.g2o: ", "no VERTEX_SE2 or EDGE_SE2 lines");
}

TEST(G2oFile, MissingFileIsAnInputError) {
  TempDir dir;
  const Result<posegraph::PoseGraph> g = read_g2o(dir / "nope.g2o");
  ASSERT_FALSE(g.ok());
  EXPECT_EQ(g.error().kind, ErrorKind::kInput);
  EXPECT_THAT(g.error().message, HasSubstr("no such file"));
}

// ---- the benchmark graphs (../shared/data/posegraph): both must converge ----

/// Reads and optimises a benchmark graph with the default options; Ceres must report CONVERGENCE
/// and the cost must fall below `max_cost_ratio` of the initial one.
void expect_converges(const std::string& name, std::size_t nodes, std::size_t edges,
                      double max_cost_ratio) {
  const auto path = support::data_path("posegraph/" + name);
  TESSERA_REQUIRE_DATA(path);
  Result<posegraph::PoseGraph> g = read_g2o(path);
  ASSERT_TRUE(g.ok()) << g.error().message;
  EXPECT_EQ(g->poses.size(), nodes);
  EXPECT_EQ(g->edges.size(), edges);
  const Result<posegraph::OptimizeSummary> s = posegraph::optimize(*g, {});
  ASSERT_TRUE(s.ok()) << s.error().message;
  EXPECT_TRUE(s->converged) << s->termination;
  EXPECT_LT(s->final_cost, max_cost_ratio * s->initial_cost);
}

// Intel's VERTEX_SE2 poses are already a fair guess: the cost falls from 274.6 to 22.2.
TEST(G2oFileData, IntelGraphConverges) { expect_converges("intel.g2o", 1728, 2512, 0.1); }

TEST(G2oFileData, ManhattanEdgesOnlyGraphConvergesFromChainedOdometry) {
  expect_converges("manhattan.g2o", 3500, 5453, 1e-2);
}

}  // namespace
}  // namespace tessera
