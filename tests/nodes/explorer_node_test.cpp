#include "tessera/nodes/explorer_node.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <optional>
#include <vector>

#include "support/text_world.hpp"
#include "tessera/eval/coverage.hpp"
#include "tessera/eval/map_accuracy.hpp"
#include "tessera/eval/truth_grid.hpp"
#include "tessera/io/ros_message_encoders.hpp"
#include "tessera/io/tf_tree.hpp"
#include "tessera/net/in_process_transport.hpp"
#include "tessera/nodes/sim_node.hpp"
#include "tessera/nodes/team_observer.hpp"
#include "tessera/sim/builtin_world.hpp"

namespace tessera::nodes {
namespace {

// Robot `robot` (0-based) dies, its process gone with its transport, at `at_s` simulated.
struct Kill {
  int robot = -1;
  double at_s = 0.0;
};

struct TeamRun {
  double coverage = 0.0;        // reachable free cells the map knows
  double coverage_free = 0.0;   // ... and shows free
  double occupied_shown_free = 0.0;
  double sim_s = 0.0;
  std::vector<std::uint8_t> states;
  std::vector<std::string> reasons;
  std::optional<OccupancyGridMessage> killed_map;  // the killed robot's last map
  std::vector<OccupancyGrid> team_maps;            // each surviving robot's team map at the end
};

// The simulator, the robots and an observer on one in-process bus, stepped in turn until every
// robot has finished or max_s of simulated time.
TeamRun run_team(const World& world, const std::vector<Pose2>& starts, double max_s,
                 Kill kill = {}) {
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
  if (kill.robot >= 0) {
    const std::string topic = "/" + team[static_cast<std::size_t>(kill.robot)].name + "/map";
    EXPECT_TRUE(obs_t->subscribe({topic, std::string(kRos2OccupancyGrid), net::Qos::map()},
                                 [&run](std::span<const std::uint8_t> cdr) {
                                   run.killed_map = *decode_cdr_occupancy_grid(cdr);
                                 })
                    .ok());
  }
  while ((*sim)->time_s() < max_s) {
    EXPECT_TRUE((*sim)->step().ok());
    if (kill.robot >= 0 && robots[static_cast<std::size_t>(kill.robot)] &&
        (*sim)->time_s() >= kill.at_s) {
      (*observer)->spin_once();
      robots[static_cast<std::size_t>(kill.robot)].reset();
      robot_t[static_cast<std::size_t>(kill.robot)].reset();
    }
    bool all_done = true;
    for (auto& r : robots) {
      if (!r) continue;
      EXPECT_TRUE(r->spin_once().ok());
      all_done = all_done && r->state() == RobotStatusMessage::kFinished;
    }
    if (all_done) break;
  }
  run.sim_s = (*sim)->time_s();
  for (auto& r : robots) {
    if (!r) continue;
    run.states.push_back(r->state());
    run.reasons.push_back(r->reason());
    run.team_maps.push_back(r->team_map());
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

// Robot r2 dies at 10 s: r1 and r3 finish the office, and every cell r2 had published is in
// their team maps.
TEST(ExplorerNode, WhenARobotDiesItsPublishedCellsStayInTheTeamsMap) {
  const World world = builtin_world("office", 0.05);
  const std::vector<Pose2> starts{{8.025, 7.025, 0.0}, {8.625, 7.025, 0.0}, {7.425, 7.025, 0.0}};
  const TeamRun run = run_team(world, starts, 300.0, {.robot = 1, .at_s = 10.0});
  EXPECT_GE(run.coverage, 0.99);
  ASSERT_EQ(run.states.size(), 2u);
  for (std::size_t i = 0; i < run.states.size(); ++i) {
    EXPECT_EQ(run.reasons[i], "no reachable frontier") << i;
  }
  ASSERT_TRUE(run.killed_map.has_value());
  const OccupancyGridMessage& m = *run.killed_map;
  const Pose2 T_team_origin = starts[1] * planar_pose(m.origin);
  std::size_t known = 0, missing = 0;
  for (std::uint32_t y = 0; y < m.height; ++y) {
    for (std::uint32_t x = 0; x < m.width; ++x) {
      if (m.data[y * m.width + x] < 0) continue;
      ++known;
      const Vec2 p = T_team_origin * Vec2{(x + 0.5) * m.resolution_m, (y + 0.5) * m.resolution_m};
      for (const OccupancyGrid& team : run.team_maps) {
        const std::optional<Cell> c = team.geometry().cell_at(p);
        if (!c || !team.known(*c)) ++missing;
      }
    }
  }
  EXPECT_GT(known, 1000u);
  EXPECT_EQ(missing, 0u);
}

}  // namespace
}  // namespace tessera::nodes
