#pragma once
// report.json of `tessera eval`: the core keys (report/core_report.hpp) and the section the evaluation fills, "relations" (Kummerle et al. 2009
// relation metric) or "trajectory" (TUM ATE and RPE, Sturm et al. 2012). Angles are reported in
// degrees, as the published figures are.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "tessera/eval/relation_metric.hpp"
#include "tessera/eval/trajectory_error.hpp"

namespace tessera {

/// What a report needs besides the evaluation itself.
struct EvalReportContext {
  std::string command;                                // "eval relations", "eval ate"
  nlohmann::json options = nlohmann::json::object();  // effective options and input files
  double wall_s = 0.0;
  std::optional<double> data_duration_s;  // trajectory_report: the estimate's time span
};

/// "relations": {count, skipped, trans_mean_m, trans_std_m, trans_sq_mean_m2, trans_sq_std_m2,
/// rot_mean_deg, rot_std_deg, rot_sq_mean_deg2, rot_sq_std_deg2} and "trajectory": {poses,
/// begin_s, end_s} (the span after the time offset, which is also timing.data_duration_s). "seed"
/// is null: nothing is random.
[[nodiscard]] nlohmann::json relations_report(const RelationMetric& metric,
                                              const EvalReportContext& context);

/// "trajectory": {poses, reference_poses, pairs, ate_rmse_m, ate_mean_m, ate_median_m, ate_std_m,
/// ate_min_m, ate_max_m, rpe_delta_s, rpe_pairs, rpe_trans_rmse_m, rpe_trans_m_per_s,
/// rpe_rot_rmse_deg, rpe_rot_deg_per_s}. The rpe_* values are null when `rpe` is empty (no pose
/// pair rpe_delta_s apart). "alignment" holds the 4x4 T_reference_estimate, row-major.
[[nodiscard]] nlohmann::json trajectory_report(const AbsoluteTrajectoryError& ate,
                                               const std::optional<RelativePoseError>& rpe,
                                               double rpe_delta_s,
                                               const EvalReportContext& context);

}  // namespace tessera
