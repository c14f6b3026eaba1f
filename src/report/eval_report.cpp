#include "tessera/report/eval_report.hpp"

#include "tessera/core/angle.hpp"
#include "tessera/report/core_report.hpp"

namespace tessera {
namespace {

/// Nothing in an evaluation is random: the seed is null.
nlohmann::json core_keys(const EvalReportContext& context, std::optional<double> data_duration_s) {
  return core_report({context.command, std::nullopt, context.options, context.wall_s,
                              data_duration_s});
}

}  // namespace

nlohmann::json relations_report(const RelationMetric& m, const EvalReportContext& context) {
  const double deg_per_rad = rad_to_deg(1.0);
  nlohmann::json j = core_keys(context, m.trajectory_end_s - m.trajectory_begin_s);
  j["relations"] = {{"count", m.count},
                    {"skipped", m.skipped},
                    {"trans_mean_m", m.trans_mean_m},
                    {"trans_std_m", m.trans_std_m},
                    {"trans_sq_mean_m2", m.trans_sq_mean_m2},
                    {"trans_sq_std_m2", m.trans_sq_std_m2},
                    {"rot_mean_deg", rad_to_deg(m.rot_mean_rad)},
                    {"rot_std_deg", rad_to_deg(m.rot_std_rad)},
                    {"rot_sq_mean_deg2", m.rot_sq_mean_rad2 * deg_per_rad * deg_per_rad},
                    {"rot_sq_std_deg2", m.rot_sq_std_rad2 * deg_per_rad * deg_per_rad}};
  j["trajectory"] = {
      {"poses", m.poses}, {"begin_s", m.trajectory_begin_s}, {"end_s", m.trajectory_end_s}};
  return j;
}

nlohmann::json trajectory_report(const AbsoluteTrajectoryError& ate,
                                 const std::optional<RelativePoseError>& rpe, double rpe_delta_s,
                                 const EvalReportContext& context) {
  nlohmann::json j = core_keys(context, context.data_duration_s);
  nlohmann::json t = {{"poses", ate.estimate_poses},    {"reference_poses", ate.reference_poses},
                      {"pairs", ate.trans_m.count},     {"ate_rmse_m", ate.trans_m.rmse},
                      {"ate_mean_m", ate.trans_m.mean}, {"ate_median_m", ate.trans_m.median},
                      {"ate_std_m", ate.trans_m.std},   {"ate_min_m", ate.trans_m.min},
                      {"ate_max_m", ate.trans_m.max},   {"rpe_delta_s", rpe_delta_s}};
  if (rpe) {
    t["rpe_pairs"] = rpe->trans_m.count;
    t["rpe_trans_rmse_m"] = rpe->trans_m.rmse;
    t["rpe_trans_m_per_s"] = rpe->trans_m.rmse / rpe->delta_s;
    t["rpe_rot_rmse_deg"] = rad_to_deg(rpe->rot_rad.rmse);
    t["rpe_rot_deg_per_s"] = rad_to_deg(rpe->rot_rad.rmse) / rpe->delta_s;
  } else {
    for (const char* key : {"rpe_pairs", "rpe_trans_rmse_m", "rpe_trans_m_per_s",
                            "rpe_rot_rmse_deg", "rpe_rot_deg_per_s"}) {
      t[key] = nullptr;
    }
  }
  const Eigen::Matrix4d T = ate.T_reference_estimate.matrix();
  nlohmann::json rows = nlohmann::json::array();
  for (int r = 0; r < 4; ++r) rows.push_back({T(r, 0), T(r, 1), T(r, 2), T(r, 3)});
  t["alignment"] = rows;
  j["trajectory"] = t;
  return j;
}

}  // namespace tessera
