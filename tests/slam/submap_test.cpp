#include "tessera/slam/submap.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace tessera::slam {
namespace {

ScanPoints one_return() {
  ScanPoints p;
  p.returns_m.push_back({1.0, 0.0});
  return p;
}

// Cartographer's window: a new submap every N scans, each scan into the (at most) two active
// ones, the older finished after 2N scans; matching uses the older one.
TEST(ActiveSubmaps, EveryScanGoesIntoTwoSubmapsAndEachFinishesAfterTwiceN) {
  SubmapOptions o;
  o.scans_per_submap = 3;
  o.initial_size_m = 4.0;
  ActiveSubmaps submaps(o);
  EXPECT_FALSE(submaps.matching_id().has_value());
  std::vector<int> finished_at;
  for (int scan = 0; scan < 12; ++scan) {
    const ActiveSubmaps::Insertion ins = submaps.insert(one_return(), {0.1 * scan, 0.0, 0.0});
    if (scan == 0) {
      EXPECT_EQ(ins.inserted_into, (std::vector<int>{0}));
    }
    if (scan >= 3) {
      EXPECT_EQ(ins.inserted_into.size(), 2u) << "scan " << scan;
    }
    if (ins.finished) finished_at.push_back(scan);
  }
  EXPECT_EQ(finished_at, (std::vector<int>{5, 8, 11}));
  EXPECT_EQ(submaps.size(), 4);
  EXPECT_EQ(submaps.submap(0).num_scans(), 6);
  EXPECT_TRUE(submaps.submap(0).finished());
  EXPECT_EQ(submaps.active_ids(), (std::vector<int>{2, 3}));
  EXPECT_EQ(submaps.matching_id(), 2);
  // A submap's frame sits at the position of the scan that started it, heading 0.
  EXPECT_NEAR(submaps.submap(1).local_pose().x, 0.3, 1e-12);
  EXPECT_EQ(submaps.submap(1).local_pose().theta, 0.0);
}

// A log with a scan every metre must not build submaps 180 m long: the newest submap is full
// after travel_per_submap_m metres even with few scans, and the oldest finishes then.
TEST(ActiveSubmaps, SubmapsAreFullAfterTheirTravelWhateverTheScanCount) {
  SubmapOptions o;
  o.scans_per_submap = 90;
  o.travel_per_submap_m = 2.5;
  o.initial_size_m = 4.0;
  ActiveSubmaps submaps(o);
  std::vector<int> finished_at;
  for (int scan = 0; scan < 12; ++scan) {
    const ActiveSubmaps::Insertion ins = submaps.insert(one_return(), {1.0 * scan, 0.0, 0.0});
    if (ins.finished) finished_at.push_back(scan);
  }
  // Scan 0 starts submap 0; it is full at scan 3 (3 m), so scan 4 starts submap 1, full at
  // scan 7, which finishes submap 0 (7 m, twice a full one).
  EXPECT_EQ(finished_at, (std::vector<int>{7, 11}));
  EXPECT_EQ(submaps.submap(0).num_scans(), 8);
  EXPECT_NEAR(submaps.submap(0).travel_m(), 7.0, 1e-12);
  EXPECT_NEAR(submaps.submap(1).local_pose().x, 4.0, 1e-12);
}

/// The probability of the cell at world (5, 0) in submap 0 after three scans taken `step_m` apart
/// along x, each returning from that point.
double wall_after_three_scans(double step_m) {
  SubmapOptions o;
  o.initial_size_m = 16.0;
  ActiveSubmaps submaps(o);
  for (int scan = 0; scan < 3; ++scan) {
    const double x = step_m * scan;
    ScanPoints p;
    p.returns_m.push_back({5.0 - x, 0.0});
    submaps.insert(p, {x, 0.0, 0.0});
  }
  const ProbabilityGrid& grid = submaps.submap(0).grid();
  return grid.probability(grid.geometry().cell_at_unchecked({5.0, 0.0}));
}

// Scans a metre apart each stand for many dense ones: their hits weigh twice the log-odds
// (0.6 instead of 0.55), from the second scan on (the first has no step yet); scans the motion
// filter's 0.2 m apart keep Cartographer's weight.
TEST(ActiveSubmaps, HitsWeighMoreWhenTheScansAreFarApart) {
  const double odds_dense = 0.55 / 0.45;
  const double odds_sparse = 0.6 / 0.4;
  const double dense = odds_dense * odds_dense * odds_dense;
  const double sparse = odds_dense * odds_sparse * odds_sparse;
  EXPECT_NEAR(wall_after_three_scans(0.2), dense / (1.0 + dense), 0.01);
  EXPECT_NEAR(wall_after_three_scans(1.0), sparse / (1.0 + sparse), 0.01);
  // A step of 0.35-0.7 m scales in between.
  EXPECT_GT(wall_after_three_scans(0.5), wall_after_three_scans(0.2) + 0.01);
  EXPECT_LT(wall_after_three_scans(0.5), wall_after_three_scans(1.0) - 0.01);
}

TEST(Submap, GridIsInTheSubmapFrame) {
  SubmapOptions o;
  Submap submap({5.0, 2.0, 0.0}, o);
  submap.insert(one_return(), {5.0, 2.0, 0.0}, RangeInserter(o.insert));
  const GridGeometry& g = submap.grid().geometry();
  EXPECT_GT(submap.grid().probability(g.cell_at_unchecked({1.0, 0.0})), 0.5);
  EXPECT_EQ(submap.num_scans(), 1);
}

TEST(SubmapOptions, DefaultsAreValidAndBrokenFieldsAreNamed) {
  EXPECT_FALSE(validate(SubmapOptions{}).has_value());
  SubmapOptions o;
  o.scans_per_submap = 0;
  EXPECT_THAT(validate(o).value_or(""), ::testing::HasSubstr("scans_per_submap"));
  o = SubmapOptions{};
  o.travel_per_submap_m = -1.0;
  EXPECT_THAT(validate(o).value_or(""), ::testing::HasSubstr("travel_per_submap_m"));
  o = SubmapOptions{};
  o.hit_evidence_step_m = 0.0;
  EXPECT_THAT(validate(o).value_or(""), ::testing::HasSubstr("hit_evidence_step_m"));
  o = SubmapOptions{};
  o.max_hit_evidence_scale = 0.5;
  EXPECT_THAT(validate(o).value_or(""), ::testing::HasSubstr("max_hit_evidence_scale"));
}

}  // namespace
}  // namespace tessera::slam
