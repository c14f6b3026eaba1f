#include "tessera/eval/exploration_score.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace tessera {
namespace {

// A 10 x 1 map whose every cell is reachable: coverage is the share of cells known free.
struct Strip {
  GridGeometry g{{0.0, 0.0}, 1.0, 10, 1};
  OccupancyGrid map{g};
  std::vector<std::uint8_t> reachable = std::vector<std::uint8_t>(10, 1);

  /// Marks cells [0, n) free and returns them.
  std::vector<Cell> free_up_to(int n) {
    std::vector<Cell> changed;
    for (int x = 0; x < n; ++x) {
      map.set_probability({x, 0}, 0.1);
      changed.push_back({x, 0});
    }
    return changed;
  }
};

TEST(ExplorationScorer, CoverageFollowsTheChangedCellsAndMilestonesComeOnce) {
  Strip s;
  ExplorationScorer scorer(s.reachable, 2);
  scorer.observe(0, 0.0, s.map, {});
  EXPECT_EQ(scorer.coverage(), 0.0);
  EXPECT_EQ(scorer.reachable_cells(), 10u);
  scorer.observe(1, 1.0, s.map, s.free_up_to(5));
  EXPECT_DOUBLE_EQ(scorer.coverage(), 0.5);
  scorer.observe(2, 2.5, s.map, s.free_up_to(9));
  ASSERT_TRUE(scorer.metrics().steps_to_90.has_value());
  EXPECT_EQ(*scorer.metrics().steps_to_90, 2);
  EXPECT_DOUBLE_EQ(*scorer.metrics().path_m_to_90, 2.5);
  EXPECT_FALSE(scorer.metrics().steps_to_99.has_value());
  scorer.observe(3, 4.0, s.map, s.free_up_to(10));
  EXPECT_EQ(*scorer.metrics().steps_to_90, 2);  // the first time only
  EXPECT_EQ(*scorer.metrics().steps_to_99, 3);
  const ExplorationMetrics m = scorer.finish(3, 4.0, 4, 1, "no reachable frontier");
  EXPECT_EQ(m.robots, 2);
  EXPECT_EQ(m.steps, 3);
  EXPECT_DOUBLE_EQ(m.coverage, 1.0);
  EXPECT_EQ(m.path_length_cells, 4);
  EXPECT_EQ(m.turns, 1);
  EXPECT_EQ(m.stop_reason, "no reachable frontier");
  ASSERT_EQ(m.coverage_over_time.size(), 4u);  // steps 0 to 3, the last already there
  EXPECT_EQ(m.coverage_over_time.back().step, 3);
}

TEST(ExplorationScorer, TheSeriesThinsToMultiplesOfADoublingStrideAndEndsOnTheLastStep) {
  Strip s;
  ExplorationScorer scorer(s.reachable, 1);
  scorer.observe(0, 0.0, s.map, {});
  const auto n = static_cast<std::int64_t>(ExplorationScorer::kMaxSeriesSamples) + 5;
  for (std::int64_t step = 1; step <= n; ++step) {
    scorer.observe(step, static_cast<double>(step), s.map, {});
  }
  const std::vector<CoverageSample>& series = scorer.metrics().coverage_over_time;
  EXPECT_LE(series.size(), ExplorationScorer::kMaxSeriesSamples);
  EXPECT_EQ(series.front().step, 0);
  for (const CoverageSample& x : series) EXPECT_EQ(x.step % 2, 0) << x.step;
  const ExplorationMetrics m = scorer.finish(n, static_cast<double>(n), n, 0, "step limit");
  EXPECT_EQ(m.coverage_over_time.back().step, n);  // n is odd: added by finish()
  EXPECT_EQ(m.coverage_over_time.size(), series.size() + 1);
}

}  // namespace
}  // namespace tessera
