#include "tessera/report/exploration_report.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "support/json_fields.hpp"

namespace tessera {
namespace {

using support::keys;
using support::num;

// A 4 x 3 world of 0.25 m cells.
World small_world() {
  return World(GridGeometry({0.0, 0.0}, 0.25, 4, 3), std::vector<std::uint8_t>(12, 0), "small");
}

ExplorationResult small_result() {
  ExplorationResult r;
  r.frontier_left = {{1, 1}, {2, 1}, {3, 1}};
  r.unreachable_frontier = {{3, 1}};
  r.blacklisted_targets = {{2, 1}, {3, 1}};
  r.free_cells = 10;
  r.reachable_free_cells = 9;
  r.refused_moves = 2;
  r.planning_time_s = 0.125;
  ExplorationMetrics& m = r.metrics;
  m.robots = 2;
  m.coverage = 0.95;
  m.steps = 40;
  m.path_length_m = 17.5;
  m.path_length_cells = 70;
  m.turns = 11;
  m.steps_to_90 = 31;
  m.path_m_to_90 = 14.25;
  m.stop_reason = "step limit";
  m.coverage_over_time = {{0, 0.0, 0.1}, {20, 8.0, 0.6}, {40, 17.5, 0.95}};
  r.accuracy.cells_compared = 8;
  r.accuracy.correct = 6;
  r.accuracy.empty_as_occupied = 1;
  r.accuracy.occupied_as_empty = 1;
  r.accuracy.success_rate = 0.75;
  return r;
}

TEST(ExplorationReport, CoreKeysWithOneSecondPerStep) {
  const ExplorationReportContext context{7, "maps/small.world", {{"robots", 2}}, 4.0};
  const nlohmann::json j = exploration_report(small_result(), small_world(), context);
  EXPECT_EQ(keys(j), (std::set<std::string>{"tessera_version", "command", "seed", "options", "timing",
                                             "world", "exploration", "map_accuracy",
                                             "coverage_over_time"}));
  EXPECT_EQ(j["command"], "explore");
  EXPECT_EQ(j["seed"], 7);
  EXPECT_EQ(j["options"]["robots"], 2);
  EXPECT_DOUBLE_EQ(num(j["timing"]["wall_s"]), 4.0);
  // 40 steps are 40 s of simulated time: 10 data seconds per wall second.
  EXPECT_DOUBLE_EQ(num(j["timing"]["data_duration_s"]), 40.0);
  EXPECT_DOUBLE_EQ(num(j["timing"]["realtime_factor"]), 10.0);
  EXPECT_DOUBLE_EQ(num(j["timing"]["planning_s"]), 0.125);
}

TEST(ExplorationReport, WorldExplorationAndMapAccuracySections) {
  const nlohmann::json j =
      exploration_report(small_result(), small_world(), {7, "maps/small.world", {}, 4.0});
  const nlohmann::json& w = j["world"];
  EXPECT_EQ(w["file"], "maps/small.world");
  EXPECT_DOUBLE_EQ(num(w["resolution_m"]), 0.25);
  EXPECT_EQ(w["width_cells"], 4);
  EXPECT_EQ(w["height_cells"], 3);
  EXPECT_EQ(w["free_cells"], 10);
  EXPECT_EQ(w["reachable_free_cells"], 9);

  const nlohmann::json& e = j["exploration"];
  EXPECT_EQ(e["robots"], 2);
  EXPECT_DOUBLE_EQ(num(e["coverage"]), 0.95);
  EXPECT_EQ(e["steps"], 40);
  EXPECT_DOUBLE_EQ(num(e["path_length_m"]), 17.5);
  EXPECT_EQ(e["path_length_cells"], 70);
  EXPECT_EQ(e["turns"], 11);
  EXPECT_EQ(e["steps_to_90"], 31);
  EXPECT_DOUBLE_EQ(num(e["path_m_to_90"]), 14.25);
  // 99 % never reached: null, present.
  ASSERT_TRUE(e.contains("steps_to_99"));
  EXPECT_TRUE(e["steps_to_99"].is_null());
  ASSERT_TRUE(e.contains("path_m_to_99"));
  EXPECT_TRUE(e["path_m_to_99"].is_null());
  EXPECT_EQ(e["refused_moves"], 2);
  EXPECT_EQ(e["frontier_cells_left"], 3);
  EXPECT_EQ(e["unreachable_frontier_cells"], 1);
  EXPECT_EQ(e["blacklisted_targets"], 2);
  EXPECT_EQ(e["stop_reason"], "step limit");

  const nlohmann::json& a = j["map_accuracy"];
  EXPECT_EQ(keys(a), (std::set<std::string>{"cells_compared", "correct", "empty_as_occupied",
                                             "occupied_as_empty", "success_rate"}));
  EXPECT_EQ(a["cells_compared"], 8);
  EXPECT_EQ(a["correct"], 6);
  EXPECT_EQ(a["empty_as_occupied"], 1);
  EXPECT_EQ(a["occupied_as_empty"], 1);
  EXPECT_DOUBLE_EQ(num(a["success_rate"]), 0.75);
}

TEST(ExplorationReport, ShortCoverageSeriesIsCopiedWhole) {
  const nlohmann::json j = exploration_report(small_result(), small_world(), {});
  const nlohmann::json& c = j["coverage_over_time"];
  EXPECT_EQ(c["step"], nlohmann::json({0, 20, 40}));
  EXPECT_EQ(c["path_m"], nlohmann::json({0.0, 8.0, 17.5}));
  EXPECT_EQ(c["coverage"], nlohmann::json({0.1, 0.6, 0.95}));
}

std::vector<std::int64_t> reported_steps(std::size_t samples) {
  ExplorationResult r = small_result();
  r.metrics.coverage_over_time.clear();
  for (std::size_t i = 0; i < samples; ++i) {
    const auto s = static_cast<std::int64_t>(i);
    r.metrics.coverage_over_time.push_back({s, 0.5 * static_cast<double>(s), 0.001 * static_cast<double>(s)});
  }
  const nlohmann::json c = exploration_report(r, small_world(), {})["coverage_over_time"];
  EXPECT_EQ(c["path_m"].size(), c["step"].size());
  EXPECT_EQ(c["coverage"].size(), c["step"].size());
  return c["step"].get<std::vector<std::int64_t>>();
}

TEST(ExplorationReport, LongCoverageSeriesIsThinnedToAtMost500KeepingTheLast) {
  // 500 samples: stride 1, all kept.
  EXPECT_EQ(reported_steps(500).size(), 500u);
  // 501 samples: stride 2, samples 0, 2, ..., 500 (the last is on the stride): 251.
  const std::vector<std::int64_t> odd = reported_steps(501);
  ASSERT_EQ(odd.size(), 251u);
  EXPECT_EQ(odd[1], 2);
  EXPECT_EQ(odd.back(), 500);
  // 1001 samples: stride 3, samples 0, 3, ..., 999 (334) and the last, 1000: 335.
  const std::vector<std::int64_t> long_run = reported_steps(1001);
  ASSERT_EQ(long_run.size(), 335u);
  EXPECT_EQ(long_run[1], 3);
  EXPECT_EQ(long_run[333], 999);
  EXPECT_EQ(long_run.back(), 1000);
}

}  // namespace
}  // namespace tessera
