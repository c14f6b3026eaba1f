// tessera localize: the robot's pose in a saved session's map, scan by scan, with no new map
// (slam/localizer.hpp): tracking, loss detection, and global relocalization when no initial pose
// is given or tracking is lost. Thin glue: read the session and the log first, so that bad input
// writes nothing; localize; write the poses, the picture and report.json. The live node (--ros)
// is in cmd_localize_ros.cpp.
#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "session_map.hpp"
#include "slam_report.hpp"
#include "tessera/eval/relation_metric.hpp"
#include "tessera/io/atomic_file.hpp"
#include "tessera/io/json_file.hpp"
#include "tessera/io/relations_file.hpp"
#include "tessera/io/session_file.hpp"
#include "tessera/io/tum_trajectory.hpp"
#include "tessera/render/render.hpp"
#include "tessera/report/core_report.hpp"
#include "tessera/report/eval_report.hpp"
#include "tessera/slam/localizer.hpp"
#include "tessera/slam/scan_matched_odometry.hpp"

namespace tessera::cli {
namespace {

/// One line per scan: its stamp, state, whether the pose is to be trusted, the pose, its score,
/// the share of the scan on the map and how well that share fits, and the pose's standard
/// deviations.
std::string encode_poses_csv(const std::vector<slam::LocalizedScan>& scans) {
  std::string out =
      "t_s,state,confident,x_m,y_m,theta_rad,score,map_share,map_fit,sigma_x_m,sigma_y_m,"
      "sigma_theta_rad\n";
  for (const slam::LocalizedScan& s : scans) {
    const Eigen::Matrix3d& c = s.covariance;
    out += fmt::format(
        "{:.6f},{},{:d},{:.4f},{:.4f},{:.5f},{:.4f},{:.3f},{:.3f},{:.4g},{:.4g},{:.4g}\n", s.t_s,
        slam::to_string(s.state), s.confident, s.T_map_robot.x, s.T_map_robot.y,
        s.T_map_robot.theta, s.score, s.map_share, s.map_fit, std::sqrt(std::max(0.0, c(0, 0))),
        std::sqrt(std::max(0.0, c(1, 1))), std::sqrt(std::max(0.0, c(2, 2))));
  }
  return out;
}

}  // namespace

LocalizeCommand::LocalizeCommand(CLI::App& app) {
  sub_ = app.add_subcommand(
      "localize",
      "Localize a robot in a saved session's map (tessera slam --save) without mapping: tracks "
      "every scan against the frozen map, finds the robot with no initial pose (branch and bound "
      "over the whole map, accepted only when clearly better than any other place) and again "
      "after a kidnapping; writes poses.csv (pose, state, confidence, standard deviations per "
      "scan), trajectory.txt (TUM, the localized scans), localization.png and report.json to "
      "--out");
  sub_->add_option("--session", session_, "Session file (.tsm) whose map to localize in")
      ->required();
  input_.add_options(*sub_);
  sub_->add_option("--initial-pose", initial_pose_,
                   "X,Y[,THETA] (m, m, rad) of the first scan in the map (default: search)");
  sub_->add_option("--out", out_, "Output folder")->capture_default_str();
  sub_->add_option(
      "--relations", relations_,
      "Score the localized trajectory against a relations file (Kummerle et al. 2009)");
  sub_->add_option("--time-offset", time_offset_s_,
                   "Seconds added to the log's stamps to reach the relations' time base")
      ->capture_default_str();
  sub_->add_flag("--quiet", quiet_, "No progress line and no summary");
  add_ros_options();
}

int LocalizeCommand::run() const {
  if (ros_) return run_ros();
  if (!input_.given()) return report_error(usage_error("localize needs --log, --bag or --ros"));
  if (Status s = input_.check(); !s) return report_error(s.error());
  // Inputs first: a bad session, relations file or log leaves nothing behind.
  Result<Setup> setup = read_setup();
  if (!setup) return report_error(setup.error());
  const Session& session = setup->session;
  Result<LaserLog> log = input_.read(nullptr);
  if (!log) return report_error(log.error());
  if (Status s = check_same_laser(session, *log, session_.string(), input_.name()); !s) {
    return report_error(s.error());
  }

  // The localizer follows the robot between scans by its odometry: an input without one gets an
  // odometry made from its scans (local SLAM alone; counted in the run's time).
  const auto t0 = std::chrono::steady_clock::now();
  const bool scan_matched = !log->has_odometry;
  if (scan_matched) {
    log = slam::with_scan_matched_odometry(std::move(log).value());
    if (!log) return report_error(log.error());
  }
  // The frozen map: the session's nodes at their optimised poses, as the SLAM built its submaps.
  const slam::LocalizerOptions options;
  Result<slam::ProbabilityGrid> map = session_frozen_map(session, options, session_.string());
  if (!map) return report_error(map.error());
  slam::Localizer localizer(std::move(map).value(), options);
  if (setup->initial_pose) localizer.set_pose(*setup->initial_pose);

  ProgressLine progress(!quiet_ && stderr_is_terminal());
  std::vector<slam::LocalizedScan> scans;
  scans.reserve(log->scans.size());
  for (const StampedScan& scan : log->scans) {
    scans.push_back(localizer.add_scan(scan));
    if (scans.size() % 50 == 0 || scans.size() == log->scans.size()) {
      progress.show(fmt::format("localize: scan {}/{}  {}", scans.size(), log->scans.size(),
                                slam::to_string(scans.back().state)),
                    static_cast<std::int64_t>(scans.size()),
                    static_cast<std::int64_t>(log->scans.size()), "scans");
    }
  }
  progress.finish();
  return write_outputs(scans, localizer, input_.name(),
                       !scan_matched        ? "the input"
                       : input_.no_odometry ? "scan matching (--no-odometry)"
                                            : "scan matching (the input has none)",
                       seconds_since(t0), data_duration_s(*log), setup->relations, nullptr);
}

Result<LocalizeCommand::Setup> LocalizeCommand::read_setup() const {
  if (!std::isfinite(time_offset_s_)) {
    return usage_error("--time-offset must be a finite number of seconds");
  }
  Setup setup;
  if (initial_pose_) {
    Result<Pose2> p = parse_pose(*initial_pose_, "--initial-pose");
    if (!p) return p.error();
    setup.initial_pose = *p;
  }
  Result<Session> session = read_session(session_);
  if (!session) return session.error();
  if (session->scans.empty()) {
    return input_error(session_.string() + ": the session holds no scans");
  }
  setup.session = std::move(session).value();
  if (relations_) {
    Result<std::vector<Relation>> read = read_relations(*relations_);
    if (!read) return read.error();
    setup.relations = std::move(read).value();
  }
  return setup;
}

int LocalizeCommand::write_outputs(const std::vector<slam::LocalizedScan>& scans,
                                   const slam::Localizer& localizer, const std::string& input,
                                   const std::string& odometry, double wall_s, double duration_s,
                                   const std::optional<std::vector<Relation>>& relations,
                                   const nlohmann::json* ros) const {
  nlohmann::json options_json = {{"session", session_.string()},
                                 {"input", input},
                                 {"odometry", odometry},
                                 {"initial_pose", initial_pose_.value_or("")},
                                 {"time_offset_s", time_offset_s_}};
  if (ros) options_json["ns"] = ns_;
  std::optional<double> first_pose_after_s;
  std::vector<StampedPose2> trajectory;
  for (const slam::LocalizedScan& s : scans) {
    if (s.state == slam::LocalizationState::kLost) continue;
    if (!first_pose_after_s) first_pose_after_s = s.t_s - scans.front().t_s;
    trajectory.push_back({s.t_s, s.T_map_robot});
  }
  std::optional<RelationMetric> metric;
  if (relations && !trajectory.empty()) {
    Result<RelationMetric> scored = relation_metric(trajectory, *relations, time_offset_s_);
    if (!scored) {
      Error e = scored.error();
      e.message = relations_->string() + " against the localized trajectory: " + e.message;
      return report_error(e);
    }
    metric = std::move(scored).value();
  }

  const slam::LocalizerStats& st = localizer.stats();
  nlohmann::json report = core_report({"localize", std::nullopt, options_json, wall_s, duration_s});
  report["localization"] = {{"scans", st.scans},
                            {"localized_scans", st.tracked},
                            {"first_pose_after_s", first_pose_after_s.value_or(-1.0)},
                            {"searches", st.searches},
                            {"relocalizations", st.relocalizations},
                            {"ambiguous_searches", st.ambiguous},
                            {"losses", st.losses},
                            {"jumps", st.jumps},
                            {"glitches", st.glitches},
                            {"strays", st.strays},
                            {"tracking_wall_s", st.tracking_s},
                            {"search_wall_s", st.search_s}};
  if (metric) report["relations"] = relations_report(*metric, {})["relations"];
  if (ros) report["ros"] = *ros;

  const OccupancyGrid picture_map = localizer.map().to_occupancy_grid(2);
  RenderLayers layers;
  layers.map = &picture_map;
  std::vector<Vec2> path;
  for (const StampedPose2& p : trajectory) path.push_back(p.pose.translation());
  if (!path.empty()) layers.robots_m.push_back(path.back());
  layers.paths_m.push_back(std::move(path));
  Result<std::string> png = render_png(layers);
  if (!png) return report_error(png.error());
  const std::string csv = encode_poses_csv(scans);
  const std::string tum = encode_tum_trajectory(trajectory);
  const std::string json = encode_json(report);
  if (Status s = ensure_directory(out_); !s) return report_error(s.error());
  const std::vector<PendingFile> files{{out_ / "poses.csv", csv},
                                       {out_ / "trajectory.txt", tum},
                                       {out_ / "localization.png", *png},
                                       {out_ / "report.json", json}};
  if (Status s = write_files_atomic(files); !s) {
    return report_error(s.error());
  }
  if (!quiet_) {
    fmt::print(
        "localize: {} of {} scans localized, first pose after {:.1f} s of data, {} "
        "relocalizations ({} searches, {} ambiguous), {} losses, {} jumps; "
        "{:.1f} s for {:.1f} s of data ({:.1f}x real time)\n",
        st.tracked, st.scans, first_pose_after_s.value_or(NAN), st.relocalizations, st.searches,
        st.ambiguous, st.losses, st.jumps, wall_s, duration_s,
        realtime_factor(duration_s, wall_s).value_or(0.0));
    if (metric) print_relations_summary(*metric);
    fmt::print("outputs: {}/poses.csv trajectory.txt localization.png report.json\n",
               out_.string());
  }
  return kExitOk;
}

}  // namespace tessera::cli
