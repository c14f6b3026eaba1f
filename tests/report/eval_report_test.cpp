#include "tessera/report/eval_report.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <numbers>
#include <set>
#include <string>

#include "support/json_fields.hpp"

namespace tessera {
namespace {

using support::keys;
using support::num;

RelationMetric small_metric() {
  RelationMetric m;
  m.count = 3;
  m.skipped = 1;
  m.trans_mean_m = 0.5;
  m.trans_std_m = 0.25;
  m.trans_sq_mean_m2 = 0.3;
  m.trans_sq_std_m2 = 0.1;
  m.rot_mean_rad = std::numbers::pi / 90.0;                                            // 2 deg
  m.rot_std_rad = std::numbers::pi / 180.0;                                            // 1 deg
  m.rot_sq_mean_rad2 = 4.0 * (std::numbers::pi / 180.0) * (std::numbers::pi / 180.0);  // 4 deg^2
  m.rot_sq_std_rad2 = 9.0 * (std::numbers::pi / 180.0) * (std::numbers::pi / 180.0);   // 9 deg^2
  m.poses = 40;
  m.trajectory_begin_s = 100.0;
  m.trajectory_end_s = 130.0;
  return m;
}

TEST(RelationsReport, CoreKeysWithTheTrajectorySpanAsDataClock) {
  const EvalReportContext context{"eval relations", {{"time_offset_s", 1.5}}, 6.0, std::nullopt};
  const nlohmann::json j = relations_report(small_metric(), context);
  EXPECT_EQ(keys(j), (std::set<std::string>{"tessera_version", "command", "seed", "options",
                                             "timing", "relations", "trajectory"}));
  EXPECT_EQ(j["command"], "eval relations");
  EXPECT_TRUE(j["seed"].is_null());  // nothing in an evaluation is random
  EXPECT_EQ(j["options"]["time_offset_s"], 1.5);
  EXPECT_DOUBLE_EQ(num(j["timing"]["wall_s"]), 6.0);
  // 130 s - 100 s of trajectory in 6 s of wall time.
  EXPECT_DOUBLE_EQ(num(j["timing"]["data_duration_s"]), 30.0);
  EXPECT_DOUBLE_EQ(num(j["timing"]["realtime_factor"]), 5.0);
}

TEST(RelationsReport, RelationsInMetresAndDegrees) {
  const nlohmann::json j = relations_report(small_metric(), {"eval relations", {}, 1.0, {}});
  const nlohmann::json& r = j["relations"];
  EXPECT_EQ(keys(r), (std::set<std::string>{"count", "skipped", "trans_mean_m", "trans_std_m",
                                             "trans_sq_mean_m2", "trans_sq_std_m2", "rot_mean_deg",
                                             "rot_std_deg", "rot_sq_mean_deg2", "rot_sq_std_deg2"}));
  EXPECT_EQ(r["count"], 3);
  EXPECT_EQ(r["skipped"], 1);
  EXPECT_DOUBLE_EQ(num(r["trans_mean_m"]), 0.5);
  EXPECT_DOUBLE_EQ(num(r["trans_std_m"]), 0.25);
  EXPECT_DOUBLE_EQ(num(r["trans_sq_mean_m2"]), 0.3);
  EXPECT_DOUBLE_EQ(num(r["trans_sq_std_m2"]), 0.1);
  EXPECT_DOUBLE_EQ(num(r["rot_mean_deg"]), 2.0);
  EXPECT_DOUBLE_EQ(num(r["rot_std_deg"]), 1.0);
  // Squared angles scale by (180 / pi)^2.
  EXPECT_DOUBLE_EQ(num(r["rot_sq_mean_deg2"]), 4.0);
  EXPECT_DOUBLE_EQ(num(r["rot_sq_std_deg2"]), 9.0);
  EXPECT_EQ(j["trajectory"]["poses"], 40);
  EXPECT_DOUBLE_EQ(num(j["trajectory"]["begin_s"]), 100.0);
  EXPECT_DOUBLE_EQ(num(j["trajectory"]["end_s"]), 130.0);
}

AbsoluteTrajectoryError small_ate() {
  AbsoluteTrajectoryError ate;
  ate.estimate_poses = 12;
  ate.reference_poses = 15;
  ate.trans_m = {10, 0.05, 0.04, 0.035, 0.02, 0.01, 0.09};
  // A quarter turn about z and a shift of (1, 2, 3).
  ate.T_reference_estimate = Eigen::Translation3d(1.0, 2.0, 3.0) *
                             Eigen::AngleAxisd(std::numbers::pi / 2.0, Eigen::Vector3d::UnitZ());
  return ate;
}

TEST(TrajectoryReport, AteRpeAndTheAlignment) {
  RelativePoseError rpe;
  rpe.delta_s = 2.0;
  rpe.trans_m = {8, 0.4, 0.3, 0.3, 0.1, 0.1, 0.6};
  rpe.rot_rad = {8, std::numbers::pi / 90.0, 0.0, 0.0, 0.0, 0.0, 0.0};  // rmse 2 deg
  const nlohmann::json j =
      trajectory_report(small_ate(), rpe, 2.0, {"eval ate", {}, 0.5, 20.0});
  EXPECT_EQ(j["command"], "eval ate");
  EXPECT_TRUE(j["seed"].is_null());
  EXPECT_DOUBLE_EQ(num(j["timing"]["data_duration_s"]), 20.0);
  EXPECT_DOUBLE_EQ(num(j["timing"]["realtime_factor"]), 40.0);
  const nlohmann::json& t = j["trajectory"];
  EXPECT_EQ(keys(t),
            (std::set<std::string>{"poses", "reference_poses", "pairs", "ate_rmse_m", "ate_mean_m",
                                   "ate_median_m", "ate_std_m", "ate_min_m", "ate_max_m",
                                   "rpe_delta_s", "rpe_pairs", "rpe_trans_rmse_m",
                                   "rpe_trans_m_per_s", "rpe_rot_rmse_deg", "rpe_rot_deg_per_s",
                                   "alignment"}));
  EXPECT_EQ(t["poses"], 12);
  EXPECT_EQ(t["reference_poses"], 15);
  EXPECT_EQ(t["pairs"], 10);
  EXPECT_DOUBLE_EQ(num(t["ate_rmse_m"]), 0.05);
  EXPECT_DOUBLE_EQ(num(t["ate_mean_m"]), 0.04);
  EXPECT_DOUBLE_EQ(num(t["ate_median_m"]), 0.035);
  EXPECT_DOUBLE_EQ(num(t["ate_std_m"]), 0.02);
  EXPECT_DOUBLE_EQ(num(t["ate_min_m"]), 0.01);
  EXPECT_DOUBLE_EQ(num(t["ate_max_m"]), 0.09);
  EXPECT_DOUBLE_EQ(num(t["rpe_delta_s"]), 2.0);
  EXPECT_EQ(t["rpe_pairs"], 8);
  EXPECT_DOUBLE_EQ(num(t["rpe_trans_rmse_m"]), 0.4);
  EXPECT_DOUBLE_EQ(num(t["rpe_trans_m_per_s"]), 0.2);  // 0.4 m over 2 s
  EXPECT_DOUBLE_EQ(num(t["rpe_rot_rmse_deg"]), 2.0);
  EXPECT_DOUBLE_EQ(num(t["rpe_rot_deg_per_s"]), 1.0);  // 2 deg over 2 s
  // Row-major 4 x 4: [R | t; 0 0 0 1] with R the quarter turn about z.
  const double expected[4][4] = {{0, -1, 0, 1}, {1, 0, 0, 2}, {0, 0, 1, 3}, {0, 0, 0, 1}};
  ASSERT_EQ(t["alignment"].size(), 4u);
  for (int r = 0; r < 4; ++r) {
    ASSERT_EQ(t["alignment"][r].size(), 4u);
    for (int c = 0; c < 4; ++c) {
      EXPECT_NEAR(num(t["alignment"][r][c]), expected[r][c], 1e-15) << r << "," << c;
    }
  }
}

TEST(TrajectoryReport, WithoutRpeTheRpeValuesAreNullAndNoDataClock) {
  const nlohmann::json j = trajectory_report(small_ate(), std::nullopt, 1.0, {"eval ate", {}, 0.5, {}});
  const nlohmann::json& t = j["trajectory"];
  for (const char* key : {"rpe_pairs", "rpe_trans_rmse_m", "rpe_trans_m_per_s", "rpe_rot_rmse_deg",
                          "rpe_rot_deg_per_s"}) {
    ASSERT_TRUE(t.contains(key)) << key;
    EXPECT_TRUE(t[key].is_null()) << key;
  }
  EXPECT_DOUBLE_EQ(num(t["rpe_delta_s"]), 1.0);
  EXPECT_EQ(t["pairs"], 10);
  EXPECT_TRUE(j["timing"]["data_duration_s"].is_null());
  EXPECT_TRUE(j["timing"]["realtime_factor"].is_null());
}

}  // namespace
}  // namespace tessera
