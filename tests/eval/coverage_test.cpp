#include "tessera/eval/coverage.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "tessera/core/rng.hpp"
#include "tessera/sim/world.hpp"

namespace tessera {
namespace {

// 5 x 3, a wall at x = 2 splits the free cells into a left part (4 cells) and a right part (6).
//   y=2  . . # . .
//   y=1  . . # . .
//   y=0  # # # . .
World split_world() {
  std::vector<std::uint8_t> solid{
      1, 1, 1, 0, 0,  // y = 0
      0, 0, 1, 0, 0,  // y = 1
      0, 0, 1, 0, 0,  // y = 2
  };
  return World(GridGeometry({0.0, 0.0}, 1.0, 5, 3), std::move(solid));
}

TEST(Coverage, CountsOnlyReachableCellsKnownAsFree) {
  const World truth = split_world();
  OccupancyGrid map(truth.geometry());
  map.set_probability({0, 1}, 0.1);  // reachable, free
  map.set_probability({1, 1}, 0.9);  // reachable but believed occupied: not covered
  map.set_probability({3, 1}, 0.1);  // free but in the other part
  EXPECT_DOUBLE_EQ(coverage(map, truth.reachable_from({0, 2})), 0.25);
  EXPECT_DOUBLE_EQ(coverage(map, truth.reachable_from({4, 0})), 1.0 / 6.0);
  // Solid start: nothing reachable.
  EXPECT_DOUBLE_EQ(coverage(map, truth.reachable_from({2, 0})), 0.0);
}

TEST(CoverageTracker, IncrementalCountEqualsFullCountUnderRandomUpdates) {
  const World truth = split_world();
  Rng rng(5);
  OccupancyGrid map(truth.geometry());
  CoverageTracker tracker(truth.reachable_from({4, 2}));
  EXPECT_EQ(tracker.reachable_cells(), 6u);
  EXPECT_EQ(tracker.covered_cells(), 0u);
  for (int step = 0; step < 500; ++step) {
    const Cell c{rng.uniform_int(0, 4), rng.uniform_int(0, 2)};
    if (rng.uniform(0.0, 1.0) < 0.2) {
      map.set_unknown(c);
    } else {
      map.set_probability(c, rng.uniform(0.0, 1.0));
    }
    const std::vector<Cell> touched{c, c, {-1, 0}};
    tracker.update(map, touched);
    ASSERT_DOUBLE_EQ(tracker.coverage(), coverage(map, truth.reachable_from({4, 2})))
        << "step " << step;
  }
  CoverageTracker fresh(truth.reachable_from({4, 2}));
  fresh.reset(map);
  EXPECT_EQ(fresh.covered_cells(), tracker.covered_cells());
}

}  // namespace
}  // namespace tessera
