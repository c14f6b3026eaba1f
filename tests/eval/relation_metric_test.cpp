#include "tessera/eval/relation_metric.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "tessera/core/rng.hpp"

namespace tessera {
namespace {

using ::testing::HasSubstr;

/// The relation of the motion between two poses of `truth` (what a person would check).
Relation relation_between(const StampedPose2& a, const StampedPose2& b) {
  return {a.t_s, b.t_s, between(a.pose, b.pose)};
}

TEST(InterpolatePose, IsLinearInTranslationAndHeadingBetweenTwoPoses) {
  const std::vector<StampedPose2> sorted = {{0.0, {0.0, 0.0, 0.0}},
                                            {2.0, {2.0, 4.0, std::numbers::pi / 2.0}}};
  const std::optional<Pose2> p = interpolate_pose(sorted, 0.5);
  ASSERT_TRUE(p.has_value());
  EXPECT_DOUBLE_EQ(p->x, 0.5);
  EXPECT_DOUBLE_EQ(p->y, 1.0);
  EXPECT_DOUBLE_EQ(p->theta, std::numbers::pi / 8.0);
}

TEST(InterpolatePose, TurnsAlongTheShortestArcAcrossPlusMinusPi) {
  // From 3.0 rad to -3.0 rad is 2 pi - 6 = 0.283 rad counter-clockwise, not 6 rad clockwise.
  const std::vector<StampedPose2> sorted = {{0.0, {0.0, 0.0, 3.0}}, {1.0, {0.0, 0.0, -3.0}}};
  EXPECT_NEAR(interpolate_pose(sorted, 0.25)->theta, 3.0 + 0.25 * (2.0 * std::numbers::pi - 6.0),
              1e-12);
  EXPECT_NEAR(interpolate_pose(sorted, 0.75)->theta, -3.0 - 0.25 * (2.0 * std::numbers::pi - 6.0),
              1e-12);
}

TEST(InterpolatePose, ReturnsAPoseStampedExactlyAndNothingOutsideTheSpan) {
  const std::vector<StampedPose2> sorted = {
      {1.0, {1.0, 0.0, 0.1}}, {2.0, {5.0, 0.0, 0.2}}, {3.0, {7.0, 0.0, 0.3}}};
  EXPECT_DOUBLE_EQ(interpolate_pose(sorted, 1.0)->x, 1.0);
  EXPECT_DOUBLE_EQ(interpolate_pose(sorted, 2.0)->x, 5.0);
  EXPECT_DOUBLE_EQ(interpolate_pose(sorted, 3.0)->x, 7.0);
  EXPECT_DOUBLE_EQ(interpolate_pose(sorted, 2.5)->x, 6.0);
  EXPECT_FALSE(interpolate_pose(sorted, 0.999).has_value());
  EXPECT_FALSE(interpolate_pose(sorted, 3.001).has_value());
  EXPECT_FALSE(interpolate_pose({}, 0.0).has_value());
}

TEST(InterpolatePose, NothingInAGapWiderThanAsked) {
  const std::vector<StampedPose2> sorted = {
      {1.0, {1.0, 0.0, 0.0}}, {2.0, {2.0, 0.0, 0.0}}, {10.0, {9.0, 0.0, 0.0}}};
  EXPECT_DOUBLE_EQ(interpolate_pose(sorted, 1.5, 5.0)->x, 1.5);
  EXPECT_FALSE(interpolate_pose(sorted, 6.0, 5.0).has_value());
  EXPECT_DOUBLE_EQ(interpolate_pose(sorted, 10.0, 5.0)->x, 9.0);  // a pose's own stamp
  EXPECT_DOUBLE_EQ(interpolate_pose(sorted, 6.0)->x, 5.5);        // no limit asked
}

TEST(RelationMetric, SkipsRelationsInAStretchTheTrajectoryDoesNotCover) {
  // A trajectory with a 100 s hole (a resumed session that left part of the log out): the
  // relation into the hole is skipped, not scored against a straight line across it.
  std::vector<StampedPose2> trajectory;
  for (int i = 0; i <= 10; ++i) trajectory.push_back({0.2 * i, {0.1 * i, 0.0, 0.0}});
  for (int i = 0; i <= 10; ++i) trajectory.push_back({102.0 + 0.2 * i, {5.0, 0.1 * i, 0.0}});
  const std::vector<Relation> relations = {
      {0.2, 1.0, {0.4, 0.0, 0.0}}, {50.0, 102.4, {0.0, 0.0, 0.0}}, {102.2, 103.0, {0.0, 0.4, 0.0}}};
  const Result<RelationMetric> m = relation_metric(trajectory, relations);
  ASSERT_TRUE(m.ok()) << m.error().message;
  EXPECT_EQ(m->count, 2u);
  EXPECT_EQ(m->skipped, 1u);
  EXPECT_NEAR(m->trans_mean_m, 0.0, 1e-9);

  // Keyframes 3 s apart (a corrected log): a 10 s gap among them is an ordinary one.
  std::vector<StampedPose2> keyframes;
  for (int i = 0; i <= 20; ++i)
    keyframes.push_back({3.0 * i + (i > 10 ? 7.0 : 0.0), {1.0 * i, 0.0, 0.0}});
  const Result<RelationMetric> sparse = relation_metric(keyframes, {{31.0, 36.0, {0.5, 0.0, 0.0}}});
  ASSERT_TRUE(sparse.ok()) << sparse.error().message;
  EXPECT_EQ(sparse->count, 1u);
}

TEST(RelationMetric, ExactTrajectoryScoresZero) {
  std::vector<StampedPose2> truth;
  for (int k = 0; k < 20; ++k) {
    const double t = 0.5 * k;
    truth.push_back({t, {std::cos(t), std::sin(2.0 * t), normalize_angle(1.3 * t)}});
  }
  std::vector<Relation> relations;
  for (std::size_t k = 0; k + 3 < truth.size(); ++k) {
    relations.push_back(relation_between(truth[k], truth[k + 3]));
  }
  const Result<RelationMetric> m = relation_metric(truth, relations);
  ASSERT_TRUE(m.ok()) << m.error().message;
  EXPECT_EQ(m->count, relations.size());
  EXPECT_EQ(m->skipped, 0u);
  EXPECT_NEAR(m->trans_mean_m, 0.0, 1e-12);
  EXPECT_NEAR(m->rot_mean_rad, 0.0, 1e-12);
}

TEST(RelationMetric, TranslationErrorOfAKnownShortfall) {
  // The robot moved 1.1 m straight ahead; the estimate says 1.0 m: E = (1,0,0) * (1.1,0,0)^-1.
  const std::vector<StampedPose2> estimate = {{0.0, {0.0, 0.0, 0.0}}, {1.0, {1.0, 0.0, 0.0}}};
  const Result<RelationMetric> m = relation_metric(estimate, {{0.0, 1.0, {1.1, 0.0, 0.0}}});
  ASSERT_TRUE(m.ok()) << m.error().message;
  EXPECT_EQ(m->count, 1u);
  EXPECT_NEAR(m->trans_mean_m, 0.1, 1e-12);
  EXPECT_NEAR(m->trans_sq_mean_m2, 0.01, 1e-12);
  EXPECT_NEAR(m->rot_mean_rad, 0.0, 1e-12);
  EXPECT_EQ(m->trans_std_m, 0.0);  // one relation: no spread
}

TEST(RelationMetric, RotationErrorOfAKnownTurn) {
  // Estimate (1, 0, 0), relation (1, 0, 0.1): E = (1,0,0) * (1,0,0.1)^-1
  // = (1 - cos 0.1, sin 0.1, -0.1), so t = 2 sin(0.05) m and r = 0.1 rad.
  const std::vector<StampedPose2> estimate = {{0.0, {0.0, 0.0, 0.0}}, {1.0, {1.0, 0.0, 0.0}}};
  const Result<RelationMetric> m = relation_metric(estimate, {{0.0, 1.0, {1.0, 0.0, 0.1}}});
  ASSERT_TRUE(m.ok()) << m.error().message;
  EXPECT_NEAR(m->trans_mean_m, 2.0 * std::sin(0.05), 1e-12);
  EXPECT_NEAR(m->rot_mean_rad, 0.1, 1e-12);
  EXPECT_NEAR(m->rot_sq_mean_rad2, 0.01, 1e-12);
}

TEST(RelationMetric, CountsTheRelationsOffByMoreThanEitherBound) {
  // The true path (1 m along x, then 1 m more), scored against three claimed loop closures: one
  // right, one 0.5 m off, one 0.3 rad off (a poster matched to its copy elsewhere, say).
  const std::vector<StampedPose2> truth = {
      {0.0, {0.0, 0.0, 0.0}}, {1.0, {1.0, 0.0, 0.0}}, {2.0, {2.0, 0.0, 0.0}}};
  const std::vector<Relation> claims = {
      {0.0, 1.0, {1.01, 0.0, 0.0}}, {0.0, 2.0, {1.5, 0.0, 0.0}}, {1.0, 2.0, {1.0, 0.0, 0.3}}};
  const Result<RelationMetric> m = relation_metric(truth, claims);
  ASSERT_TRUE(m.ok()) << m.error().message;
  EXPECT_EQ(relations_off_by_more_than(*m), 2u);
  EXPECT_EQ(relations_off_by_more_than(*m, 0.6, 0.1), 1u);  // only the turned one
  EXPECT_EQ(relations_off_by_more_than(*m, 0.6, 0.4), 0u);
  EXPECT_EQ(relations_off_by_more_than(*m, 0.005, 0.4), 3u);  // the 1 cm one counts too
}

TEST(RelationMetric, ErrorComposesInKummerleOrder) {
  // The estimate moves (1, 0, 0) in its own frame while heading pi/2 in the world. Relation
  // (2, 0, 0.5), whose inverse is (-2 cos 0.5, 2 sin 0.5, -0.5):
  // E = (1,0,0) * (2,0,0.5)^-1 = (1 - 2 cos 0.5, 2 sin 0.5, -0.5), |t| = 1.22 m. The other order,
  // relation^-1 * (1,0,0) = (-cos 0.5, sin 0.5, -0.5), would give |t| = 1 m.
  const std::vector<StampedPose2> turned = {{0.0, {0.0, 0.0, std::numbers::pi / 2.0}},
                                            {1.0, {0.0, 1.0, std::numbers::pi / 2.0}}};
  const Result<RelationMetric> m = relation_metric(turned, {{0.0, 1.0, {2.0, 0.0, 0.5}}});
  ASSERT_TRUE(m.ok()) << m.error().message;
  EXPECT_NEAR(m->trans_mean_m, std::hypot(1.0 - 2.0 * std::cos(0.5), 2.0 * std::sin(0.5)), 1e-12);
  EXPECT_NEAR(m->rot_mean_rad, 0.5, 1e-12);
}

TEST(RelationMetric, InterpolatesTheEstimateBetweenItsPoses) {
  // Poses at 0 s and 2 s; the relation's stamps fall at 0.5 s and 1.5 s, where the estimate is at
  // x = 0.5 and x = 1.5 heading pi/8 and 3 pi/8: the true motion between them is that exactly.
  const std::vector<StampedPose2> estimate = {{0.0, {0.0, 0.0, 0.0}},
                                              {2.0, {2.0, 0.0, std::numbers::pi / 2.0}}};
  const Pose2 x1{0.5, 0.0, std::numbers::pi / 8.0}, x2{1.5, 0.0, 3.0 * std::numbers::pi / 8.0};
  const Result<RelationMetric> exact = relation_metric(estimate, {{0.5, 1.5, between(x1, x2)}});
  ASSERT_TRUE(exact.ok()) << exact.error().message;
  EXPECT_NEAR(exact->trans_mean_m, 0.0, 1e-12);
  EXPECT_NEAR(exact->rot_mean_rad, 0.0, 1e-12);
  // A relation that claims no turn at all is off by the interpolated pi/4.
  const Pose2 no_turn{between(x1, x2).x, between(x1, x2).y, 0.0};
  const Result<RelationMetric> off = relation_metric(estimate, {{0.5, 1.5, no_turn}});
  ASSERT_TRUE(off.ok());
  EXPECT_NEAR(off->rot_mean_rad, std::numbers::pi / 4.0, 1e-12);
}
TEST(NearestPose, TakesTheScanNearestInTimeWithinTheBound) {
  const std::vector<StampedPose2> sorted = {
      {0.0, {0.0, 0.0, 0.0}}, {0.2, {1.0, 0.0, 0.0}}, {0.4, {2.0, 0.0, 0.0}}};
  EXPECT_DOUBLE_EQ(nearest_pose(sorted, 0.27, 0.1)->x, 1.0);
  EXPECT_DOUBLE_EQ(nearest_pose(sorted, 0.33, 0.1)->x, 2.0);
  EXPECT_DOUBLE_EQ(nearest_pose(sorted, 0.3, 0.1)->x, 1.0);  // a tie: the earlier scan
  EXPECT_DOUBLE_EQ(nearest_pose(sorted, -0.05, 0.1)->x, 0.0);
  EXPECT_DOUBLE_EQ(nearest_pose(sorted, 0.45, 0.1)->x, 2.0);
  EXPECT_FALSE(nearest_pose(sorted, 0.55, 0.1).has_value());
  EXPECT_FALSE(nearest_pose(sorted, 0.27, 0.05).has_value());
  EXPECT_FALSE(nearest_pose({}, 0.0, 1.0).has_value());
}

TEST(RelationMetric, SnappedStampsScoreTheScansTheRelationJoinsNotTheJitter) {
  // Scans every 0.2 s while the robot drives 1 m/s; the relations' clock runs 40 ms off the
  // scans' in either direction. Interpolated at the relation's stamps the estimate seems 4 cm off
  // the exact relations; snapped to the nearest scan it scores zero.
  std::vector<StampedPose2> scans;
  for (int k = 0; k <= 10; ++k) scans.push_back({0.2 * k, {0.2 * k, 0.0, 0.0}});
  const std::vector<Relation> relations = {
      {0.2 + 0.04, 1.0 - 0.04, between(scans[1].pose, scans[5].pose)},
      {0.6 - 0.04, 1.4 + 0.04, between(scans[3].pose, scans[7].pose)}};
  const Result<RelationMetric> interpolated = relation_metric(scans, relations);
  ASSERT_TRUE(interpolated.ok()) << interpolated.error().message;
  EXPECT_NEAR(interpolated->trans_mean_m, 0.08, 1e-9);
  const Result<RelationMetric> snapped = relation_metric(scans, relations, 0.0, 0.07);
  ASSERT_TRUE(snapped.ok()) << snapped.error().message;
  EXPECT_EQ(snapped->count, 2u);
  EXPECT_NEAR(snapped->trans_mean_m, 0.0, 1e-12);
  // A relation whose scan is missing from the trajectory is skipped, not scored at a neighbour.
  std::vector<StampedPose2> missing = scans;
  missing.erase(missing.begin() + 5);
  const Result<RelationMetric> gap = relation_metric(missing, relations, 0.0, 0.07);
  ASSERT_TRUE(gap.ok()) << gap.error().message;
  EXPECT_EQ(gap->count, 1u);
  EXPECT_EQ(gap->skipped, 1u);
  // Two stamps 5 ms apart land on one scan: a relation the trajectory cannot tell, skipped.
  const Result<RelationMetric> one_scan =
      relation_metric(scans, {relations[0], {0.6, 0.605, {0.005, 0.0, 0.0}}}, 0.0, 0.07);
  ASSERT_TRUE(one_scan.ok()) << one_scan.error().message;
  EXPECT_EQ(one_scan->count, 1u);
  EXPECT_EQ(one_scan->skipped, 1u);
}

TEST(RelationMetric, AngleErrorWrapsAtPlusMinusPi) {
  // The estimate turns from 3.1 to -3.1 rad: 2 pi - 6.2 = 0.083 rad counter-clockwise.
  const std::vector<StampedPose2> estimate = {{0.0, {0.0, 0.0, 3.1}}, {1.0, {0.0, 0.0, -3.1}}};
  const double turn = 2.0 * std::numbers::pi - 6.2;
  const Result<RelationMetric> exact = relation_metric(estimate, {{0.0, 1.0, {0.0, 0.0, turn}}});
  ASSERT_TRUE(exact.ok());
  EXPECT_NEAR(exact->rot_mean_rad, 0.0, 1e-12);
  const Result<RelationMetric> still = relation_metric(estimate, {{0.0, 1.0, {0.0, 0.0, 0.0}}});
  ASSERT_TRUE(still.ok());
  EXPECT_NEAR(still->rot_mean_rad, turn, 1e-12);  // not 6.2 rad
  // A relation of -(pi - 0.05) against an estimate of +(pi - 0.05): off by 0.1 rad across pi.
  const std::vector<StampedPose2> half_turn = {{0.0, {0.0, 0.0, 0.0}},
                                               {1.0, {0.0, 0.0, std::numbers::pi - 0.05}}};
  const Result<RelationMetric> across =
      relation_metric(half_turn, {{0.0, 1.0, {0.0, 0.0, -(std::numbers::pi - 0.05)}}});
  ASSERT_TRUE(across.ok());
  EXPECT_NEAR(across->rot_mean_rad, 0.1, 1e-12);
}

TEST(RelationMetric, StandardDeviationIsTheSampleOneWithNMinusOne) {
  // Three relations straight ahead with shortfalls 0.1, 0.2 and 0.3 m.
  const std::vector<StampedPose2> estimate = {{0.0, {0.0, 0.0, 0.0}},
                                              {1.0, {1.0, 0.0, 0.0}},
                                              {2.0, {2.0, 0.0, 0.0}},
                                              {3.0, {3.0, 0.0, 0.0}}};
  const std::vector<Relation> relations = {
      {0.0, 1.0, {1.1, 0.0, 0.0}}, {1.0, 2.0, {1.2, 0.0, 0.0}}, {2.0, 3.0, {1.3, 0.0, 0.0}}};
  const Result<RelationMetric> m = relation_metric(estimate, relations);
  ASSERT_TRUE(m.ok()) << m.error().message;
  EXPECT_EQ(m->count, 3u);
  EXPECT_NEAR(m->trans_mean_m, 0.2, 1e-12);
  EXPECT_NEAR(m->trans_std_m, 0.1, 1e-12);  // population std would be 0.0816
  EXPECT_NEAR(m->trans_sq_mean_m2, 0.14 / 3.0, 1e-12);
  EXPECT_NEAR(m->trans_sq_std_m2, 0.0404145188432738, 1e-12);
  ASSERT_EQ(m->errors.size(), 3u);
  EXPECT_NEAR(m->errors[2].trans_m, 0.3, 1e-12);
  EXPECT_EQ(m->errors[2].t1_s, 2.0);
}

TEST(RelationMetric, SkipsAndCountsRelationsOutsideTheTrajectory) {
  const std::vector<StampedPose2> estimate = {{10.0, {0.0, 0.0, 0.0}}, {20.0, {1.0, 0.0, 0.0}}};
  const std::vector<Relation> relations = {
      {10.0, 20.0, {1.0, 0.0, 0.0}}, {5.0, 15.0, {9.0, 9.0, 0.0}}, {15.0, 20.5, {9.0, 9.0, 0.0}}};
  const Result<RelationMetric> m = relation_metric(estimate, relations);
  ASSERT_TRUE(m.ok()) << m.error().message;
  EXPECT_EQ(m->count, 1u);
  EXPECT_EQ(m->skipped, 2u);
  EXPECT_NEAR(m->trans_mean_m, 0.0, 1e-12);
}

TEST(RelationMetric, StampsThatGoBackwardsAreSortedFirst) {
  const std::vector<StampedPose2> in_order = {
      {0.0, {0.0, 0.0, 0.0}}, {1.0, {1.0, 0.0, 0.2}}, {2.0, {2.0, 1.0, 0.4}}};
  const std::vector<StampedPose2> jittered = {in_order[1], in_order[0], in_order[2]};
  const std::vector<Relation> relations = {{0.5, 2.0, {2.0, 0.5, 0.3}},
                                           {0.0, 1.5, {1.4, 0.6, 0.1}}};
  const Result<RelationMetric> a = relation_metric(in_order, relations);
  const Result<RelationMetric> b = relation_metric(jittered, relations);
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_EQ(b->count, 2u);
  EXPECT_DOUBLE_EQ(a->trans_mean_m, b->trans_mean_m);
  EXPECT_DOUBLE_EQ(a->rot_mean_rad, b->rot_mean_rad);
  EXPECT_GT(a->trans_mean_m, 0.1);  // the case is not trivially zero
}

TEST(RelationMetric, TimeOffsetIsAddedToTheTrajectoryStamps) {
  const std::vector<StampedPose2> estimate = {{0.0, {0.0, 0.0, 0.0}}, {1.0, {1.0, 0.0, 0.0}}};
  const std::vector<Relation> relations = {{1000.0, 1001.0, {1.5, 0.0, 0.0}}};
  const Result<RelationMetric> m = relation_metric(estimate, relations, 1000.0);
  ASSERT_TRUE(m.ok()) << m.error().message;
  EXPECT_NEAR(m->trans_mean_m, 0.5, 1e-12);
  EXPECT_DOUBLE_EQ(m->trajectory_begin_s, 1000.0);
  EXPECT_DOUBLE_EQ(m->trajectory_end_s, 1001.0);
}

TEST(RelationMetric, NoRelationInsideTheTrajectoryIsAnInputErrorThatNamesBothSpans) {
  const std::vector<StampedPose2> estimate = {{0.0, {0.0, 0.0, 0.0}}, {1.0, {1.0, 0.0, 0.0}}};
  const Result<RelationMetric> m = relation_metric(estimate, {{1000.0, 1001.0, {}}}, 5.0);
  ASSERT_FALSE(m.ok());
  EXPECT_EQ(m.error().kind, ErrorKind::kInput);
  EXPECT_THAT(m.error().message, HasSubstr("no relation falls within the trajectory's time span "
                                           "[5.000000, 6.000000] s (time offset 5.000000 s)"));
  EXPECT_THAT(m.error().message, HasSubstr("[1000.000000, 1001.000000]"));
}

TEST(RelationMetric, EmptyTrajectoryOrRelationsAreInputErrors) {
  const std::vector<StampedPose2> estimate = {{0.0, {}}, {1.0, {}}};
  const Result<RelationMetric> no_poses = relation_metric({}, {{0.0, 1.0, {}}});
  ASSERT_FALSE(no_poses.ok());
  EXPECT_EQ(no_poses.error().kind, ErrorKind::kInput);
  EXPECT_THAT(no_poses.error().message, HasSubstr("no poses"));
  const Result<RelationMetric> no_relations = relation_metric(estimate, {});
  ASSERT_FALSE(no_relations.ok());
  EXPECT_THAT(no_relations.error().message, HasSubstr("no relations"));
}

TEST(RelationMetric, IsBlindToWhereTheTrajectoryStartsSoNoAlignmentIsNeeded) {
  Rng rng(3);
  std::vector<StampedPose2> truth;
  Pose2 pose;
  for (int k = 0; k < 50; ++k) {
    truth.push_back({0.1 * k, pose});
    pose = pose * Pose2{rng.uniform(0.0, 0.3), rng.uniform(-0.05, 0.05), rng.uniform(-0.4, 0.4)};
  }
  std::vector<Relation> relations;
  for (int trial = 0; trial < 100; ++trial) {
    const int a = rng.uniform_int(0, 48), b = rng.uniform_int(a + 1, 49);
    relations.push_back(
        relation_between(truth[static_cast<std::size_t>(a)], truth[static_cast<std::size_t>(b)]));
  }
  const Pose2 T_other_world{12.0, -7.0, 2.5};
  std::vector<StampedPose2> moved = truth;
  for (StampedPose2& p : moved) p.pose = T_other_world * p.pose;
  const Result<RelationMetric> m = relation_metric(moved, relations);
  ASSERT_TRUE(m.ok());
  EXPECT_EQ(m->count, 100u);
  EXPECT_LT(m->trans_mean_m, 1e-9);
  EXPECT_LT(m->rot_mean_rad, 1e-9);
}

}  // namespace
}  // namespace tessera
