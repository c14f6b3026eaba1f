// tessera eval: scores a trajectory against ground-truth relations (Kummerle et al. 2009) or a
// reference trajectory (TUM ATE and RPE, Sturm et al. 2012). Thin glue: read, call eval, print,
// and with --out write report.json.
#include <fmt/format.h>

#include <chrono>
#include <cmath>

#include "commands.hpp"
#include "tessera/core/angle.hpp"
#include "tessera/io/atomic_file.hpp"
#include "tessera/io/carmen_log.hpp"
#include "tessera/report/eval_report.hpp"
#include "tessera/io/json_file.hpp"
#include "tessera/io/relations_file.hpp"
#include "tessera/io/tum_trajectory.hpp"

namespace tessera::cli {
namespace {

/// CARMEN logs (.clf, .log) give the robot pose of each laser scan: the corrected pose in a
/// corrected log, raw odometry in a raw one. Anything else is read as a TUM trajectory file.
Result<std::vector<StampedPose2>> read_planar_trajectory(const std::filesystem::path& path) {
  const std::string ext = path.extension().string();
  if (ext != ".clf" && ext != ".log") return read_tum_trajectory(path);
  Result<LaserLog> log = read_carmen_log(path);
  if (!log) return log.error();
  std::vector<StampedPose2> poses;
  poses.reserve(log->scans.size());
  for (const StampedScan& s : log->scans) poses.push_back({s.t_s, s.odometry});
  return poses;
}

/// Writes out/report.json; the folder is made only now, so a failed run leaves nothing behind.
int write_report(const std::optional<std::filesystem::path>& out, const nlohmann::json& report) {
  if (!out) return kExitOk;
  if (Status s = ensure_directory(*out); !s) return report_error(s.error());
  if (Status s = write_json_atomic(*out / "report.json", report); !s) {
    return report_error(s.error());
  }
  return kExitOk;
}

}  // namespace

EvalCommand::EvalCommand(CLI::App& app) {
  sub_ = app.add_subcommand("eval", "Score a trajectory: relation metric or TUM ATE/RPE");
  sub_->require_subcommand(1);

  relations_ = sub_->add_subcommand(
      "relations",
      "Kummerle et al. 2009 relation metric: mean and sample std of the translational (m) and "
      "rotational (deg) error of the relative motions in a relations file");
  relations_
      ->add_option("--trajectory", trajectory_,
                   "Estimated trajectory: TUM file, or CARMEN log (.clf/.log: the scans' poses)")
      ->required();
  relations_
      ->add_option("--relations", relations_file_, "Relations file 't1 t2 x y z roll pitch yaw'")
      ->required();
  relations_
      ->add_option("--time-offset", time_offset_s_,
                   "Seconds added to the trajectory's stamps to reach the relations' time base "
                   "(Intel logger stamps: 976052857.337284)")
      ->capture_default_str();
  relations_
      ->add_option("--snap-s", snap_s_,
                   "Take each relation's poses at the trajectory's scans nearest in time, when "
                   "within this many seconds, instead of interpolating (for a log whose stamps "
                   "jitter against the relations' clock; skips relations with no scan near "
                   "them); 0: interpolate")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  relations_->add_option("--out", out_, "Folder for report.json (default: print only)");

  ate_ = sub_->add_subcommand(
      "ate",
      "TUM RGB-D benchmark errors (Sturm et al. 2012): ATE after rigid alignment and RPE over a "
      "fixed time delta, as evaluate_ate.py and evaluate_rpe.py compute them");
  ate_->add_option("--trajectory", trajectory_, "Estimated trajectory (TUM file)")->required();
  ate_->add_option("--reference", reference_, "Reference (ground-truth) trajectory (TUM file)")
      ->required();
  ate_->add_option("--max-difference", options_.max_difference_s,
                   "Largest stamp difference (s) of an associated pair (associate.py)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  ate_->add_option("--rpe-delta", options_.rpe_delta_s, "RPE time delta (s)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  ate_->add_option("--out", out_, "Folder for report.json (default: print only)");
}

int EvalCommand::run() const { return relations_->parsed() ? run_relations() : run_ate(); }

int EvalCommand::run_relations() const {
  if (!std::isfinite(time_offset_s_)) {
    return report_error(usage_error("--time-offset must be a finite number of seconds"));
  }
  const auto t0 = std::chrono::steady_clock::now();
  Result<std::vector<StampedPose2>> trajectory = read_planar_trajectory(trajectory_);
  if (!trajectory) return report_error(trajectory.error());
  Result<std::vector<Relation>> relations = read_relations(relations_file_);
  if (!relations) return report_error(relations.error());
  Result<RelationMetric> metric = relation_metric(*trajectory, *relations, time_offset_s_, snap_s_);
  if (!metric) {
    Error e = metric.error();
    e.message = relations_file_.string() + " against " + trajectory_.string() + ": " + e.message;
    return report_error(e);
  }
  const RelationMetric& m = *metric;
  fmt::print(
      "relations: {} scored, {} skipped (outside the trajectory, in its gaps or with no scan "
      "near them); translation "
      "{:.4f} +/- {:.4f} m, rotation {:.3f} +/- {:.3f} deg\n",
      m.count, m.skipped, m.trans_mean_m, m.trans_std_m, rad_to_deg(m.rot_mean_rad),
      rad_to_deg(m.rot_std_rad));

  EvalReportContext context;
  context.command = "eval relations";
  context.options = {{"trajectory", trajectory_.string()},
                     {"relations", relations_file_.string()},
                     {"time_offset_s", time_offset_s_},
                     {"snap_s", snap_s_}};
  context.wall_s = seconds_since(t0);
  return write_report(out_, relations_report(m, context));
}

int EvalCommand::run_ate() const {
  if (auto problem = validate(options_)) return report_error(usage_error(*problem));
  const auto t0 = std::chrono::steady_clock::now();
  Result<std::vector<StampedPose3>> estimate = read_tum_trajectory3(trajectory_);
  if (!estimate) return report_error(estimate.error());
  Result<std::vector<StampedPose3>> reference = read_tum_trajectory3(reference_);
  if (!reference) return report_error(reference.error());
  const std::string pair = trajectory_.string() + " against " + reference_.string() + ": ";
  if (estimate->empty()) return report_error(input_error(trajectory_.string() + ": no poses"));
  if (reference->empty()) return report_error(input_error(reference_.string() + ": no poses"));

  Result<AbsoluteTrajectoryError> ate = absolute_trajectory_error(*estimate, *reference, options_);
  if (!ate) return report_error(input_error(pair + ate.error().message));
  // The RPE needs pose pairs rpe_delta_s apart; a short run has none, which is not an error of the
  // ATE: it is reported as absent.
  Result<RelativePoseError> rpe = relative_pose_error(*estimate, *reference, options_);
  const ErrorStatistics& a = ate->trans_m;
  fmt::print("ATE: {} pairs, RMSE {:.4f} m (mean {:.4f}, median {:.4f}, max {:.4f} m)\n", a.count,
             a.rmse, a.mean, a.median, a.max);
  if (rpe) {
    fmt::print("RPE over {} s: {} pairs, RMSE {:.4f} m and {:.3f} deg\n", rpe->delta_s,
               rpe->trans_m.count, rpe->trans_m.rmse, rad_to_deg(rpe->rot_rad.rmse));
  } else {
    fmt::print("RPE over {} s: none ({})\n", options_.rpe_delta_s, rpe.error().message);
  }

  EvalReportContext context;
  context.command = "eval ate";
  context.options = {{"trajectory", trajectory_.string()},
                     {"reference", reference_.string()},
                     {"max_difference_s", options_.max_difference_s},
                     {"rpe_delta_s", options_.rpe_delta_s}};
  context.wall_s = seconds_since(t0);
  context.data_duration_s = estimate->back().t_s - estimate->front().t_s;
  const std::optional<RelativePoseError> rpe_or_none =
      rpe ? std::optional<RelativePoseError>(*rpe) : std::nullopt;
  return write_report(out_, trajectory_report(*ate, rpe_or_none, options_.rpe_delta_s, context));
}

}  // namespace tessera::cli
