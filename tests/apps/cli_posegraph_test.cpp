// tessera posegraph optimize end to end: the summary line, the optimised graph and its report,
// and bad input that leaves nothing behind.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_run.hpp"
#include "support/data.hpp"

namespace tessera {
namespace {

using support::count_lines;
using support::run_cli;
using support::TempDir;
using ::testing::HasSubstr;

int count_of(const std::string& text, const std::string& word) {
  int n = 0;
  for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) {
    ++n;
  }
  return n;
}

// A square of odometry edges whose last node drifted, closed by a loop edge.
const std::string kSquare =
    "VERTEX_SE2 0 0 0 0\nVERTEX_SE2 1 2 0 1.6\nVERTEX_SE2 2 2.1 2 3.1\nVERTEX_SE2 3 0.2 2.2 -1.5\n"
    "EDGE_SE2 0 1 2 0 1.5707963 100 0 0 100 0 100\nEDGE_SE2 1 2 2 0 1.5707963 100 0 0 100 0 100\n"
    "EDGE_SE2 2 3 2 0 1.5707963 100 0 0 100 0 100\nEDGE_SE2 3 0 2 0 1.5707963 100 0 0 100 0 100\n";

TEST(CliPosegraph, OptimiseWritesTheGraphAndAReportBesideIt) {
  TempDir dir;
  support::write_bytes(dir / "square.g2o", kSquare);
  const auto out = dir / "opt.g2o";
  const support::CliRun run =
      run_cli("posegraph optimize " + (dir / "square.g2o").string() + " " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_EQ(count_lines(run.output), 1) << run.output;
  EXPECT_THAT(run.output, HasSubstr("posegraph: 4 nodes, 4 edges, cost "));
  EXPECT_THAT(run.output, HasSubstr(", converged\n"));

  const std::string g2o = support::read_bytes(out);
  EXPECT_EQ(count_of(g2o, "VERTEX_SE2 "), 4);
  EXPECT_EQ(count_of(g2o, "EDGE_SE2 "), 4);
  EXPECT_THAT(g2o, HasSubstr("VERTEX_SE2 0 0 0 0\n")) << "node 0 is held fixed";

  const nlohmann::json report = nlohmann::json::parse(support::read_bytes(dir / "opt.report.json"));
  EXPECT_EQ(report["command"], "posegraph optimize");
  const nlohmann::json& p = report["posegraph"];
  EXPECT_EQ(p["nodes"], 4);
  EXPECT_EQ(p["edges"], 4);
  EXPECT_EQ(p["converged"], true);
  EXPECT_LT(p["final_cost"].get<double>(), 1e-3 * p["initial_cost"].get<double>());
  EXPECT_GE(p["iterations"].get<int>(), 1);
  EXPECT_TRUE(p.contains("time_s"));
  EXPECT_TRUE(p.contains("termination"));
}

TEST(CliPosegraph, ReportGoesWhereAskedAndQuietPrintsNothing) {
  TempDir dir;
  support::write_bytes(dir / "square.g2o", kSquare);
  const auto report = dir / "r.json";
  const support::CliRun run =
      run_cli("posegraph optimize --quiet --iterations 5 --report " + report.string() + " " +
              (dir / "square.g2o").string() + " " + (dir / "opt.g2o").string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_EQ(run.output, "");
  EXPECT_TRUE(std::filesystem::exists(report));
  EXPECT_FALSE(std::filesystem::exists(dir / "opt.report.json"));
  EXPECT_EQ(nlohmann::json::parse(support::read_bytes(report))["options"]["iterations"], 5);
}

/// Runs optimize on `text` and expects exit 3, one line naming `phrase`, and no output.
void expect_input_error(const std::string& text, const std::string& phrase) {
  TempDir dir;
  support::write_bytes(dir / "in.g2o", text);
  const support::CliRun run =
      run_cli("posegraph optimize " + (dir / "in.g2o").string() + " " + (dir / "out.g2o").string());
  EXPECT_EQ(run.exit_code, 3) << run.output;
  EXPECT_EQ(count_lines(run.output), 1) << run.output;
  EXPECT_THAT(run.output, HasSubstr(phrase));
  EXPECT_FALSE(std::filesystem::exists(dir / "out.g2o")) << "output left behind";
  EXPECT_FALSE(std::filesystem::exists(dir / "out.report.json")) << "report left behind";
}

TEST(CliPosegraph, EdgeToAMissingVertexIsAnInputErrorAndWritesNothing) {
  expect_input_error(kSquare + "EDGE_SE2 3 9 1 0 0 1 0 0 1 0 1\n",
                     "in.g2o:9: EDGE_SE2 names vertex 9, which has no VERTEX_SE2 line");
}

TEST(CliPosegraph, MalformedLineIsAnInputError) {
  expect_input_error("VERTEX_SE2 0 0 0\n", "in.g2o:1: VERTEX_SE2 line has 4 fields, expected 5");
}

TEST(CliPosegraph, InformationThatIsNotPositiveDefiniteIsAnInputError) {
  expect_input_error("VERTEX_SE2 0 0 0 0\nVERTEX_SE2 1 1 0 0\nEDGE_SE2 0 1 1 0 0 0 0 0 0 0 0\n",
                     "in.g2o:3: EDGE_SE2 0 1: information matrix is not positive definite");
}

TEST(CliPosegraph, MissingInputIsAnInputError) {
  TempDir dir;
  const support::CliRun run = run_cli("posegraph optimize " + (dir / "nope.g2o").string() + " " +
                                      (dir / "out.g2o").string());
  EXPECT_EQ(run.exit_code, 3) << run.output;
  EXPECT_THAT(run.output, HasSubstr("nope.g2o: no such file"));
  EXPECT_FALSE(std::filesystem::exists(dir / "out.g2o"));
}

TEST(CliPosegraph, ZeroIterationsIsAUsageError) {
  TempDir dir;
  support::write_bytes(dir / "in.g2o", kSquare);
  const support::CliRun run = run_cli("posegraph optimize --iterations 0 " +
                                      (dir / "in.g2o").string() + " " + (dir / "out.g2o").string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_THAT(run.output, HasSubstr("--iterations"));
  EXPECT_FALSE(std::filesystem::exists(dir / "out.g2o"));
}

TEST(CliPosegraph, ReportOverTheGraphIsAUsageError) {
  TempDir dir;
  support::write_bytes(dir / "in.g2o", kSquare);
  const auto out = dir / "out.g2o";
  const support::CliRun run = run_cli("posegraph optimize --report " + out.string() + " " +
                                      (dir / "in.g2o").string() + " " + out.string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_THAT(run.output, HasSubstr("the report would overwrite the graph"));
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(CliPosegraph, ManhattanEdgesOnlyGraphConvergesAndGainsItsVertices) {
  const auto in = support::data_path("posegraph/manhattan.g2o");
  TESSERA_REQUIRE_DATA(in);
  TempDir dir;
  const support::CliRun run =
      run_cli("posegraph optimize " + in.string() + " " + (dir / "m.g2o").string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_THAT(run.output, HasSubstr("posegraph: 3500 nodes, 5453 edges"));
  EXPECT_THAT(run.output, HasSubstr(", converged\n"));
  const std::string g2o = support::read_bytes(dir / "m.g2o");
  EXPECT_EQ(count_of(g2o, "VERTEX_SE2 "), 3500);
  EXPECT_EQ(count_of(g2o, "EDGE_SE2 "), 5453);
}

}  // namespace
}  // namespace tessera
