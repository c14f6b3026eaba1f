// tessera team: the simulator and the robots as separate processes over DDS. A team explores the
// office by its own SLAM; a robot killed at 30 % coverage does not stop the others, and started
// again it rejoins and receives the team's map. Robots not told the starts place each other by map
// matching. Bad options are usage errors. (That the others
// keep every cell the killed robot published is nodes.ExplorerNode.WhenARobotDies...)
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_run.hpp"
#include "support/dds_isolation.hpp"
#include "support/temp_dir.hpp"

namespace tessera {
namespace {

using support::read_json;
using ::testing::HasSubstr;

// Half real time: four processes (three robots' SLAM and the simulator) keep up even in the
// sanitizer build beside other tests, where robots that fall behind the simulator would act on
// stale poses.
std::string team_args(const support::TempDir& dir, int max_s = 200) {
  return "team --builtin office --rate 0.5 --max-s " + std::to_string(max_s) +
         " --quiet --domain " + std::to_string(support::test_dds_domain()) + " --out " +
         dir.path().string();
}

// Three robot processes and the simulator; r2 is killed (SIGKILL) at 30 % coverage and started
// again 5 simulated seconds later. One run, as it is the longest test of the team.
TEST(CliTeam, ThreeRobotsExploreTheOfficeAndAKilledRobotRejoinsWithTheTeamsMap) {
  const support::TempDir dir;
  const support::CliRun run = support::run_cli(
      team_args(dir) + " --robots 3 --kill-robot 2 --at-coverage 0.3 --restart-after-s 5");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const nlohmann::json report = read_json(dir.path() / "report.json");
  const nlohmann::json& team = report["team"];
  EXPECT_EQ(team["end"], "every robot finished");
  EXPECT_GE(team["coverage"].get<double>(), 0.99);
  EXPECT_LT(report["map_accuracy"]["occupied_as_empty_share"].get<double>(), 0.005);
  EXPECT_EQ(report["command"], "team");
  ASSERT_EQ(team["robots"].size(), 3u);
  for (const nlohmann::json& r : team["robots"]) {
    EXPECT_GT(r["bytes_sent"].get<std::uint64_t>(), 0u) << r.dump();
    // Localised by its own SLAM: within 10 cm of the truth all along.
    EXPECT_LT(r["slam_position_error"]["max_m"].get<double>(), 0.10) << r.dump();
  }
  for (const char* f : {"map.png", "map.yaml", "map.pgm", "r1_truth.txt", "r3_slam.txt"}) {
    EXPECT_TRUE(std::filesystem::exists(dir.path() / f)) << f;
  }
  const nlohmann::json& r2 = team["robots"][1];
  ASSERT_FALSE(r2["killed_at_s"].is_null());
  ASSERT_FALSE(r2["restarted_at_s"].is_null());
  EXPECT_GE(r2["restarted_at_s"].get<double>(), r2["killed_at_s"].get<double>() + 5.0);
  for (const int i : {0, 2}) {
    EXPECT_EQ(team["robots"][i]["reason"], "no reachable frontier") << team["robots"][i].dump();
  }
  // The restarted r2 received its teammates' maps and their merged maps (transient local).
  const nlohmann::json explorer = read_json(dir.path() / "r2" / "report.json")["explorer"];
  EXPECT_GE(explorer["teammate_maps_received"].get<int>(), 2) << explorer.dump();
  EXPECT_GE(explorer["team_maps_received"].get<int>(), 1) << explorer.dump();
}

// Robots not told where they start find each other over DDS by matching their maps: each places
// the other within 10 cm of the truth early in the run (the whole run's figures: docs/ros2.md).
TEST(CliTeam, RobotsWithUnknownStartsPlaceEachOtherByMapMatching) {
  const support::TempDir dir;
  const support::CliRun run = support::run_cli(team_args(dir, 25) + " --robots 2 --unknown-starts");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const nlohmann::json report = read_json(dir.path() / "report.json");
  EXPECT_EQ(report["options"]["unknown_starts"], true);
  const nlohmann::json& robots = report["team"]["robots"];
  ASSERT_EQ(robots.size(), 2u);
  for (const int i : {0, 1}) {
    const nlohmann::json& placements = robots[i]["placements"];
    ASSERT_EQ(placements.size(), 1u) << robots[i].dump();
    EXPECT_EQ(placements[0]["robot"], i == 0 ? "r2" : "r1");
    EXPECT_LT(placements[0]["error_m"].get<double>(), 0.10) << placements.dump();
    EXPECT_LT(placements[0]["error_rad"].get<double>(), 0.02) << placements.dump();
  }
}

TEST(CliTeam, BadOptionsAreUsageErrors) {
  const support::TempDir dir;
  support::CliRun run = support::run_cli(team_args(dir) + " --kill-robot 2");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.output, HasSubstr("--kill-robot needs --at-coverage or --at-s"));
  run = support::run_cli(team_args(dir) + " --robots 2 --kill-robot 3 --at-s 1");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.output, HasSubstr("there is no robot 3"));
  const std::string domain = " --domain " + std::to_string(support::test_dds_domain());
  run = support::run_cli("explore --ros --team 2 --team-start 0,0 --team-start 1,0" + domain);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.output, HasSubstr("give no --team-start"));
  run = support::run_cli("explore --ros --ns r3 --team 2" + domain);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_THAT(run.output, HasSubstr("the team must include this robot (r3)"));
}

}  // namespace
}  // namespace tessera
