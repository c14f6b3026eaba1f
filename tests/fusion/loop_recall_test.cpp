#include "tessera/fusion/loop_recall.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace tessera::fusion {
namespace {

TEST(RecallAtFullPrecision, HandMadeExampleStopsAboveTheBestWrongScore) {
  // Six queries have a true loop; five hypotheses. The wrong one scores 7, so the threshold is
  // the lowest correct score above it (8), accepting 12, 10 and 8: 3 of 6 found.
  const std::vector<ScoredHypothesis> h = {
      {10.0, true}, {8.0, true}, {7.0, false}, {6.0, true}, {12.0, true}};
  const RecallAtFullPrecision r = recall_at_full_precision(h, 6);
  EXPECT_DOUBLE_EQ(r.threshold, 8.0);
  EXPECT_EQ(r.found, 3);
  EXPECT_EQ(r.accepted, 3);
  EXPECT_EQ(r.positives, 6);
  EXPECT_DOUBLE_EQ(r.recall, 0.5);
}

TEST(RecallAtFullPrecision, ACorrectScoreTiedWithAWrongOneIsNotAccepted) {
  const std::vector<ScoredHypothesis> h = {{9.0, true}, {9.0, false}, {20.0, true}};
  const RecallAtFullPrecision r = recall_at_full_precision(h, 2);
  EXPECT_DOUBLE_EQ(r.threshold, 20.0);
  EXPECT_EQ(r.found, 1);
  EXPECT_EQ(r.accepted, 1);
  EXPECT_DOUBLE_EQ(r.recall, 0.5);
}

TEST(RecallAtFullPrecision, WithoutWrongHypothesesEveryCorrectOneIsAccepted) {
  const std::vector<ScoredHypothesis> h = {{3.0, true}, {40.0, true}};
  const RecallAtFullPrecision r = recall_at_full_precision(h, 4);
  EXPECT_DOUBLE_EQ(r.threshold, 3.0);
  EXPECT_EQ(r.found, 2);
  EXPECT_DOUBLE_EQ(r.recall, 0.5);
}

TEST(RecallAtFullPrecision, WhenTheBestScoreIsWrongNothingIsAccepted) {
  const std::vector<ScoredHypothesis> h = {{50.0, false}, {30.0, true}};
  const RecallAtFullPrecision r = recall_at_full_precision(h, 1);
  EXPECT_TRUE(std::isinf(r.threshold));
  EXPECT_EQ(r.found, 0);
  EXPECT_EQ(r.accepted, 0);
  EXPECT_DOUBLE_EQ(r.recall, 0.0);
}

TEST(RecallAtFullPrecision, NoPositivesGivesZeroRecallNotADivisionByZero) {
  const std::vector<ScoredHypothesis> h = {{5.0, false}};
  const RecallAtFullPrecision r = recall_at_full_precision(h, 0);
  EXPECT_DOUBLE_EQ(r.recall, 0.0);
  EXPECT_EQ(r.accepted, 0);
  EXPECT_EQ(recall_at_full_precision({}, 3).found, 0);
}

}  // namespace
}  // namespace tessera::fusion
