// The main job end to end, as `make demo` runs it, plus render, info and convert.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli_run.hpp"
#include "support/data.hpp"

namespace tessera {
namespace {

using support::read_json;
using support::run_cli;
using support::TempDir;
using ::testing::HasSubstr;

std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(CliExplore, BuiltInWorldWritesMapPictureTrajectoryAndReport) {
  TempDir dir;
  const auto out = dir.path() / "demo";
  const support::CliRun run = run_cli("explore --out " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_THAT(run.output, HasSubstr(out.string()));
  for (const char* f : {"map.yaml", "map.pgm", "map.png", "trajectory.txt", "report.json"}) {
    EXPECT_TRUE(std::filesystem::exists(out / f)) << f;
  }
  const nlohmann::json report = read_json(out / "report.json");
  EXPECT_EQ(report["command"], "explore");
  EXPECT_EQ(report["seed"], 1);
  const auto& e = report["exploration"];
  EXPECT_GE(e["coverage"].get<double>(), 0.99);
  EXPECT_EQ(e["stop_reason"], "no reachable frontier");
  EXPECT_GT(e["steps"].get<int>(), 0);
  EXPECT_LE(e["steps_to_90"].get<int>(), e["steps_to_99"].get<int>());
  EXPECT_EQ(report["map_accuracy"]["occupied_as_empty"], 0);
  EXPECT_GT(report["world"]["reachable_free_cells"].get<int>(), 1000);
  // No temporary file survives a successful run either.
  for (const auto& entry : std::filesystem::directory_iterator(out)) {
    EXPECT_THAT(entry.path().filename().string(), ::testing::Not(HasSubstr(".tmp")));
  }
}

TEST(CliExplore, SameSeedGivesTheSameMapAndPath) {
  TempDir dir;
  const std::string common = " --sensor lidar --robots 2 --strategy priority --quiet --seed 5";
  ASSERT_EQ(run_cli("explore --out " + (dir.path() / "a").string() + common).exit_code, 0);
  ASSERT_EQ(run_cli("explore --out " + (dir.path() / "b").string() + common).exit_code, 0);
  EXPECT_EQ(read_text(dir.path() / "a" / "map.pgm"), read_text(dir.path() / "b" / "map.pgm"));
  EXPECT_EQ(read_text(dir.path() / "a" / "trajectory.txt"),
            read_text(dir.path() / "b" / "trajectory.txt"));
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "a" / "trajectory_robot2.txt"));
}

TEST(CliExplore, ExploredMapCanBeRenderedDescribedAndConverted) {
  TempDir dir;
  const auto out = dir.path() / "run";
  ASSERT_EQ(run_cli("explore --quiet --builtin labyrinth --out " + out.string()).exit_code, 0);

  const support::CliRun info = run_cli("info " + (out / "map.yaml").string());
  ASSERT_EQ(info.exit_code, 0) << info.output;
  EXPECT_THAT(info.output, HasSubstr("ros_map_server"));
  EXPECT_THAT(info.output, HasSubstr("80 x 80 cells"));

  const auto png = dir.path() / "r.png";
  const support::CliRun render =
      run_cli("render " + (out / "map.yaml").string() + " --out " + png.string() +
              " --trajectory " + (out / "trajectory.txt").string());
  ASSERT_EQ(render.exit_code, 0) << render.output;
  EXPECT_EQ(read_text(png).substr(1, 3), "PNG");

  const auto yaml = dir.path() / "copy.yaml";
  ASSERT_EQ(run_cli("convert " + (out / "map.yaml").string() + " " + yaml.string()).exit_code, 0);
  EXPECT_EQ(read_text(dir.path() / "copy.pgm"), read_text(out / "map.pgm"));
}

TEST(CliExplore, RealRosMapIsExploredCompletely) {
  const auto world = support::data_path("maps/ros_map_server/nav2_tb3_sandbox/tb3_sandbox.yaml");
  TESSERA_REQUIRE_DATA(world);
  TempDir dir;
  const auto out = dir.path() / "run";
  const support::CliRun run =
      run_cli("explore --quiet --world " + world.string() + " --out " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const nlohmann::json report = read_json(out / "report.json");
  EXPECT_GE(report["exploration"]["coverage"].get<double>(), 0.99);
  EXPECT_EQ(report["map_accuracy"]["occupied_as_empty"], 0);
}

}  // namespace
}  // namespace tessera
