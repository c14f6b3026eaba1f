// tessera slam's sessions (issue 16, io/session_file.hpp): --save FILE.tsm writes one at the
// end and, with --autosave-s, while the run goes on; --resume FILE.tsm continues one with a new
// log as a new trajectory, placed in the session's map by relocalization or --initial-pose.
#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string_view>

#include "commands.hpp"
#include "config_file.hpp"
#include "session_map.hpp"
#include "tessera/io/session_file.hpp"
#include "tessera/report/core_report.hpp"
#include "tessera/slam/scan_matched_odometry.hpp"

namespace tessera::cli {
namespace {

// The run's settings as a session keeps them: --print-config's YAML without the settings of
// where the run wrote and showed its outputs, which are not the session's (a session saved from
// another folder is the same session). Loop closure and odometry are the run's: a resumed run
// keeps the session's, whether or not its own command line repeats --no-loop-closure, and a log
// without odometry is mapped without, whether or not --no-odometry says so.
std::string session_options_yaml(const CLI::App& command, const slam::LaserSlamOptions& options) {
  static const std::set<std::string, std::less<>> kNotTheSessions = {
      "out",   "save",          "autosave_s",   "resume",        "initial_pose", "record",
      "serve", "serve_address", "serve_linger", "step_delay_ms", "quiet"};
  std::istringstream in(effective_config_yaml(command));
  std::string out, line;
  while (std::getline(in, line)) {
    std::string_view key = line;
    if (key.starts_with("# ")) key.remove_prefix(2);
    key = key.substr(0, key.find(':'));
    if (!kNotTheSessions.contains(key) && key != "no_loop_closure" && key != "no_odometry") {
      out += line + "\n";
    }
  }
  out += options.loop_closure ? "# no_loop_closure: ~  (unset)\n" : "no_loop_closure: true\n";
  out += options.use_odometry ? "# no_odometry: ~  (unset)\n" : "no_odometry: true\n";
  return out;
}

}  // namespace

void SlamCommand::add_session_options() {
  sub_->add_option("--save", save_,
                   "Save the session to this .tsm file (the scans, options, trajectory, pose "
                   "graph and map; docs/session-format.md), written atomically");
  sub_->add_option("--autosave-s", autosave_s_,
                   "With --save: also save the session so far every this many seconds of data "
                   "while the run goes on, so that a crash loses at most that much (0: at the end "
                   "only)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  sub_->add_option("--resume", resume_,
                   "Continue a saved session (.tsm) with --log or --bag as a new trajectory in "
                   "its pose graph, joined to the old ones by loop closures; the log's start is "
                   "found in the session's map (or given by --initial-pose). Save the result "
                   "with --save");
  sub_->add_flag("--keep-all-passes", keep_all_passes_,
                 "--resume --save: keep every scan of the session; by default the submaps of "
                 "earlier trajectories that later ones have seen again are trimmed, with their "
                 "scans, so that a session resumed again and again stays bounded "
                 "(docs/sessions.md)");
  sub_->add_option("--initial-pose", initial_pose_,
                   "--resume: X,Y[,THETA] (m, m, rad) of the log's first scan in the session's map "
                   "(default: found by global relocalization)");
}

Status SlamCommand::check_session_options() const {
  if (resume_ && !input_.given()) return usage_error("--resume needs --log or --bag");
  if (initial_pose_ && !resume_) {
    return usage_error("--initial-pose places a resumed log: it needs --resume");
  }
  if (autosave_s_ > 0.0 && !save_) return usage_error("--autosave-s saves to --save: give it");
  if (keep_all_passes_ && !(resume_ && save_)) {
    return usage_error(
        "--keep-all-passes is about what --resume saves: it needs --resume and --save");
  }
  return Ok{};
}

slam::AfterScan SlamCommand::autosaver(const LaserLog& log,
                                       const std::vector<slam::TrajectoryStart>& starts,
                                       const slam::LaserSlamOptions& options) const {
  if (!save_ || autosave_s_ <= 0.0) return {};
  // Data time counts forward steps between consecutive scans of a trajectory (a resumed log's
  // stamps may start anywhere). A resumed session's own scans are replayed, not new: saving
  // part of them over the file they came from would lose the rest.
  const int first_new = resume_ ? starts.back().first_scan : 0;
  return [this, &log, &starts, first_new, &options, since_save_s = 0.0](
             const slam::LaserSlam& slam, int done) mutable -> Status {
    const int i = done - 1;
    if (i <= first_new) return Ok{};
    const bool starts_here =
        std::any_of(starts.begin(), starts.end(),
                    [i](const slam::TrajectoryStart& t) { return t.first_scan == i; });
    const std::vector<StampedScan>& scans = log.scans;
    if (!starts_here) {
      since_save_s += std::max(
          0.0, scans[static_cast<std::size_t>(i)].t_s - scans[static_cast<std::size_t>(i - 1)].t_s);
    }
    if (since_save_s < autosave_s_) return Ok{};
    since_save_s = 0.0;
    return save_session({scans.begin(), scans.begin() + done}, starts, options, slam.snapshot());
  };
}

Result<SlamCommand::Resumed> SlamCommand::resume_session(LaserLog log,
                                                         slam::LaserSlamOptions& options,
                                                         nlohmann::json& report) const {
  const std::string name = resume_->string();
  Result<Session> session = read_session(*resume_);
  if (!session) return session.error();
  if (session->scans.empty()) return input_error(name + ": the session holds no scans");
  if (Status s = check_same_laser(*session, log, name, input_.name()); !s) return s.error();
  // The session's SLAM settings: its scans rebuild its state only under them.
  bool session_loop_closure = true;
  bool session_odometry = true;
  try {
    const YAML::Node settings = YAML::Load(session->options_yaml);
    if (settings["no_loop_closure"]) {
      session_loop_closure = !settings["no_loop_closure"].as<bool>();
    }
    if (settings["no_odometry"]) session_odometry = !settings["no_odometry"].as<bool>();
  } catch (const YAML::Exception& e) {
    return input_error(name + ": its settings (OPTS record) are not readable YAML: " + e.what());
  }
  const double session_cell_m = session->map.geometry().resolution_m();
  if ((cell_m_ && std::abs(*cell_m_ - session_cell_m) > 1e-12) ||
      (no_loop_closure_ && session_loop_closure)) {
    return usage_error(fmt::format(
        "--resume continues {} with its own settings (cell {} m, loop closure {}); leave "
        "--cell-m and --no-loop-closure out",
        name, session_cell_m, session_loop_closure ? "on" : "off"));
  }
  options.map_resolution_m = session_cell_m;
  options.loop_closure = session_loop_closure;

  // The session replays under its own odometry setting (a session mapped from scans alone
  // goes on so). The log's start is found by the localizer, which follows the robot between
  // scans by its odometry: a log without one gets an odometry made from its scans.
  options.use_odometry = session_odometry;
  const bool scan_matched = !log.has_odometry;
  if (scan_matched) {
    Result<LaserLog> matched = slam::with_scan_matched_odometry(std::move(log), options);
    if (!matched) return matched.error();
    log = std::move(matched).value();
  }

  // Where the log starts in the session's map.
  Pose2 T_map_first;
  std::optional<double> found_after_s;
  if (initial_pose_) {
    Result<Pose2> p = parse_pose(*initial_pose_, "--initial-pose");
    if (!p) return p.error();
    T_map_first = *p;
  } else {
    const slam::LocalizerOptions localizer_options;
    Result<slam::ProbabilityGrid> map = session_frozen_map(*session, localizer_options, name);
    if (!map) return map.error();
    slam::Localizer localizer(std::move(map).value(), localizer_options);
    const std::optional<FoundStart> found = find_log_start(localizer, log);
    if (!found) {
      return runtime_error(fmt::format(
          "{}: no scan of it could be placed in the map of {} (global relocalization found no "
          "place clearly better than all others); give --initial-pose X,Y,THETA",
          input_.name(), name));
    }
    T_map_first = found->T_map_robot;
    found_after_s = found->found_after_s;
  }

  Resumed out;
  for (const SessionTrajectoryStart& t : session->trajectory_starts) {
    out.starts.push_back({t.first_scan, t.T_map_robot});
  }
  out.starts.push_back({static_cast<int>(session->scans.size()), T_map_first});
  report = {
      {"session", name},
      {"session_scans", session->scans.size()},
      {"trajectories", slam::trajectory_count(out.starts)},
      {"start", {{"x_m", T_map_first.x}, {"y_m", T_map_first.y}, {"theta_rad", T_map_first.theta}}},
      {"start_from", initial_pose_ ? "--initial-pose" : "relocalization"},
      {"odometry", scan_matched ? "scan matching (the log has none)" : "the log"},
      {"relocalized_after_s", found_after_s ? nlohmann::json(*found_after_s) : nullptr}};
  out.log.scans = std::move(session->scans);
  out.log.backward_stamps = log.backward_stamps;
  out.log.scans.insert(out.log.scans.end(), std::make_move_iterator(log.scans.begin()),
                       std::make_move_iterator(log.scans.end()));
  return out;
}

Result<std::optional<slam::TrimmedRun>> SlamCommand::trim_session(
    const LaserLog& log, const std::vector<slam::TrajectoryStart>& starts,
    slam::LaserSlamOptions options, const slam::LaserSlamResult& r, nlohmann::json& report) const {
  if (!resume_ || !save_ || keep_all_passes_) {
    report = nullptr;
    return std::optional<slam::TrimmedRun>{};
  }
  slam::SubmapTrimOptions trim_options;
  trim_options.points = options.points;
  ProgressLine progress(!quiet_ && stderr_is_terminal());
  options.progress = [&progress](const slam::SlamProgress& p) {
    if (p.scans_done % 25 != 0 && p.scans_done != p.scans_total) return;
    progress.show(fmt::format("trim: replaying kept scan {}/{}", p.scans_done, p.scans_total),
                  p.scans_done, p.scans_total, "scans");
  };
  const auto t0 = std::chrono::steady_clock::now();
  Result<slam::TrimmedRun> trimmed = slam::trim_and_replay(log, starts, r, options, trim_options);
  progress.finish();
  if (!trimmed) {
    Error e = trimmed.error();
    e.message = "replaying the trimmed session: " + e.message;
    return e;
  }
  const slam::SubmapTrim& trim = trimmed->trim;
  const bool replayed = trim.kept_scans.size() < log.scans.size();
  report = {{"submaps", trim.submaps},
            {"submaps_trimmed", trim.submaps_trimmed},
            {"nodes", trim.nodes},
            {"nodes_trimmed", trim.nodes_trimmed},
            {"nodes_after", replayed ? trimmed->result.stats.nodes : trim.nodes},
            {"scans", log.scans.size()},
            {"scans_kept", trim.kept_scans.size()},
            {"trajectories_kept", slam::trajectory_count(trim.starts)},
            {"fresh_shares", trim.fresh_shares},
            {"fresh_areas_m2", trim.fresh_areas_m2},
            {"wall_s", seconds_since(t0)}};
  if (!replayed) return std::optional<slam::TrimmedRun>{};
  return std::optional<slam::TrimmedRun>{std::move(trimmed).value()};
}

std::vector<StampedPose2> SlamCommand::newest_poses(
    const std::vector<StampedPose2>& trajectory, const std::vector<slam::TrajectoryStart>& starts) {
  // Trajectory k holds the poses [begin(k), begin(k + 1)); the newest is scored whole, and each
  // older pose only outside the time spans of the trajectories after it.
  const auto begin = [&](std::size_t k) {
    return k == 0               ? std::size_t{0}
           : k <= starts.size() ? static_cast<std::size_t>(starts[k - 1].first_scan)
                                : trajectory.size();
  };
  std::vector<std::pair<double, double>> newer_spans;
  std::vector<StampedPose2> out;
  for (std::size_t k = starts.size() + 1; k-- > 0;) {
    const std::size_t b = begin(k), e = begin(k + 1);
    if (b >= e) continue;
    for (std::size_t i = b; i < e; ++i) {
      const double t = trajectory[i].t_s;
      if (std::none_of(newer_spans.begin(), newer_spans.end(),
                       [t](const auto& span) { return t >= span.first && t <= span.second; })) {
        out.push_back(trajectory[i]);
      }
    }
    const auto [lo, hi] = std::minmax_element(
        trajectory.begin() + static_cast<std::ptrdiff_t>(b),
        trajectory.begin() + static_cast<std::ptrdiff_t>(e),
        [](const StampedPose2& a, const StampedPose2& c) { return a.t_s < c.t_s; });
    newer_spans.emplace_back(lo->t_s, hi->t_s);
  }
  return out;
}

Status SlamCommand::save_session(const std::vector<StampedScan>& scans,
                                 const std::vector<slam::TrajectoryStart>& starts,
                                 const slam::LaserSlamOptions& options,
                                 const slam::LaserSlamResult& r) const {
  if (!save_) return Ok{};
  Session s;
  s.tessera_version = tessera_version();
  s.command = "slam";
  s.options_yaml = session_options_yaml(*sub_, options);
  s.scans = scans;
  for (const slam::TrajectoryStart& t : starts) {
    if (t.first_scan < static_cast<int>(scans.size())) {
      s.trajectory_starts.push_back({t.first_scan, t.T_map_robot});
    }
  }
  s.trajectory = r.trajectory;
  s.graph = r.graph;
  s.vertex_scan = r.vertex_scan;
  s.map = r.map;
  return write_session(*save_, s);
}

}  // namespace tessera::cli
