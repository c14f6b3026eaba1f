#include "tessera/nodes/explorer_node.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

#include "support/text_world.hpp"
#include "tessera/eval/coverage.hpp"
#include "tessera/eval/map_accuracy.hpp"
#include "tessera/eval/truth_grid.hpp"
#include "tessera/net/in_process_transport.hpp"
#include "tessera/nodes/sim_node.hpp"
#include "tessera/nodes/team_observer.hpp"
#include "tessera/sim/builtin_world.hpp"

namespace tessera::nodes {
namespace {

struct TeamRun {
  double coverage = 0.0;        // reachable free cells the map knows
  double coverage_free = 0.0;   // ... and shows free
  double occupied_shown_free = 0.0;
  double sim_s = 0.0;
  std::vector<std::uint8_t> states;
  std::vector<std::string> reasons;
};

// The simulator, the robots and an observer on one in-process bus, stepped in turn until every
// robot has finished or max_s of simulated time.
TeamRun run_team(const World& world, const std::vector<Pose2>& starts, double max_s) {
  net::InProcessBus bus;
  auto sim_t = bus.join();
  SimNodeOptions sim_options;
  sim_options.starts = starts;
  auto sim = SimNode::create(world, sim_options, 7, *sim_t);
  EXPECT_TRUE(sim.ok()) << sim.error().message;
  std::vector<TeamMember> team;
  for (std::size_t i = 0; i < starts.size(); ++i) {
    team.push_back({robot_name(static_cast<int>(i)), starts[i]});
  }
  std::vector<std::unique_ptr<net::Transport>> robot_t;
  std::vector<std::unique_ptr<ExplorerNode>> robots;
  for (const TeamMember& m : team) {
    robot_t.push_back(bus.join());
    ExplorerNodeOptions o;
    o.name = m.name;
    o.team = team;
    auto node = ExplorerNode::create(o, *robot_t.back());
    EXPECT_TRUE(node.ok()) << node.error().message;
    robots.push_back(std::move(*node));
  }
  auto obs_t = bus.join();
  auto observer = TeamObserver::create(team, 0.05, *obs_t);
  EXPECT_TRUE(observer.ok());
  TeamRun run;
  while ((*sim)->time_s() < max_s) {
    EXPECT_TRUE((*sim)->step().ok());
    bool all_done = true;
    for (auto& r : robots) {
      EXPECT_TRUE(r->spin_once().ok());
      all_done = all_done && r->state() == RobotStatusMessage::kFinished;
    }
    if (all_done) break;
  }
  run.sim_s = (*sim)->time_s();
  for (auto& r : robots) {
    run.states.push_back(r->state());
    run.reasons.push_back(r->reason());
    EXPECT_TRUE(r->finish().ok());
  }
  (*observer)->spin_once();
  const OccupancyGrid merged = (*observer)->merged(world.geometry());
  const Cell start = *world.geometry().cell_at({starts[0].x, starts[0].y});
  run.coverage = coverage(merged, world.reachable_from(start), 1.0);
  run.coverage_free = coverage(merged, world.reachable_from(start));
  run.occupied_shown_free =
      compare_to_truth(merged, TruthGrid(world.geometry(), world.solid_cells()))
          .occupied_as_empty_share();
  std::printf("team of %zu: %.1f s simulated, coverage %.4f (free %.4f), occupied shown free "
              "%.4f\n",
              starts.size(), run.sim_s, run.coverage, run.coverage_free, run.occupied_shown_free);
  return run;
}

// Two robots, each localised by its own SLAM, explore the office and stop by themselves. Starts
// at cell centres: see decision 0022 on scoring a map against a truth grid of its own cell size.
TEST(ExplorerNode, TwoRobotsExploreTheOfficeByTheirOwnSlam) {
  const World world = builtin_world("office", 0.05);
  const TeamRun run = run_team(world, {{8.025, 7.025, 0.0}, {8.625, 7.025, 0.0}}, 300.0);
  EXPECT_GE(run.coverage, 0.99);
  EXPECT_LT(run.occupied_shown_free, 0.005);
  for (std::size_t i = 0; i < run.states.size(); ++i) {
    EXPECT_EQ(run.states[i], RobotStatusMessage::kFinished) << i;
    EXPECT_EQ(run.reasons[i], "no reachable frontier") << i;
  }
}

}  // namespace
}  // namespace tessera::nodes
