// tessera slam: laser SLAM (slam/laser_slam.hpp) on a 2D laser log, or on a simulated run in a
// world (sim/laser_run.hpp) that is then scored against its ground truth (ATE of SLAM and of
// odometry alone, map accuracy). Thin glue: read or simulate the input first, so that bad input
// writes nothing; run; write map, trajectory, graph and report.json; print one summary line.
#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "recording.hpp"
#include "slam_live.hpp"
#include "slam_report.hpp"
#include "tessera/eval/drift_correction.hpp"
#include "tessera/eval/map_accuracy.hpp"
#include "tessera/eval/relation_metric.hpp"
#include "tessera/io/json_file.hpp"
#include "tessera/io/map_yaml.hpp"
#include "tessera/io/relations_file.hpp"
#include "tessera/io/tum_trajectory.hpp"
#include "tessera/record/slam_recording.hpp"
#include "tessera/render/render.hpp"
#include "tessera/report/core_report.hpp"
#include "tessera/report/eval_report.hpp"
#include "tessera/sim/laser_run.hpp"
#include "tessera/slam/laser_slam.hpp"
#include "tessera/slam/scan_matched_odometry.hpp"

namespace tessera::cli {

SlamCommand::SlamCommand(CLI::App& app) {
  sub_ = app.add_subcommand(
      "slam",
      "Laser SLAM (submaps, branch-and-bound loop closure, pose graph; Hess et al. 2016) on a 2D "
      "laser log (--log), or on a simulated run in a world (--world / --builtin) scored against "
      "its ground truth; writes map.yaml + map.pgm, map.png, trajectory.txt (one pose per scan), "
      "graph.g2o and report.json to --out");
  input_.add_options(*sub_);
  add_world_options(*sub_, world_);
  simulated_input_.add_options(*sub_);
  sub_->add_option("--out", out_, "Output folder")->capture_default_str();
  sub_->add_option("--relations", relations_,
                   "Score the trajectory against a relations file (Kummerle et al. 2009)");
  sub_->add_option("--time-offset", time_offset_s_,
                   "Seconds added to the log's stamps to reach the relations' time base (Intel "
                   "raw log: 976052857.337284)")
      ->capture_default_str();
  sub_->add_option("--cell-m", cell_m_,
                   "Cell size of the output map (default: 0.05 for a log, the world's cell size "
                   "for a simulated run, so that the map compares with it cell by cell)")
      ->check(CLI::PositiveNumber);
  sub_->add_flag("--no-loop-closure", no_loop_closure_,
                 "Local SLAM only: scan-to-submap matching, no pose graph corrections");
  sub_->add_flag("--manhattan", manhattan_,
                 "Walls at right angles: a heading prior on every node whose scan shows a "
                 "dominant wall direction (docs/slam-manhattan.md)");
  sub_->add_flag("--no-whole-map", no_whole_map_,
                 "Skip the final match of every scan against the whole map (decision 0037)");
  sub_->add_flag("--no-odometry-calibration", no_odometry_calibration_,
                 "Take the odometry as it reads: no scales or drift estimated (decision 0039)");
  add_output_stream_options(*sub_, streams_);
  sub_->add_flag("--quiet", quiet_, "No progress line and no summary");
  add_ros_options();
  add_session_options();
}

int SlamCommand::run() const {
  if (ros_) return run_ros();
  if (!std::isfinite(time_offset_s_)) {
    return report_error(usage_error("--time-offset must be a finite number of seconds"));
  }
  if (input_.given() && world_.file) {
    return report_error(usage_error("give --log or --bag, or --world, not both"));
  }
  if (Status s = input_.check(); !s) return report_error(s.error());
  if (!input_.given() && relations_) {
    return report_error(usage_error("--relations scores a log: it needs --log or --bag"));
  }
  if (Status s = check_session_options(); !s) return report_error(s.error());
  slam::LaserSlamOptions options = method_options();

  // Inputs first: a bad log, world or relations file must leave nothing behind.
  std::optional<LaserLog> read_log;
  std::optional<World> world;
  std::optional<SimulatedLaserRun> simulated;
  LaserRunOptions run_options;  // of the simulated run
  nlohmann::json bag_report;  // --bag: the topics and frames read
  if (input_.given()) {
    Result<LaserLog> read = input_.read(&bag_report);
    if (!read) return report_error(read.error());
    read_log = std::move(read).value();
    options.use_odometry = read_log->has_odometry;
  } else {
    Result<World> loaded = load_world(world_, 0.05);
    if (!loaded) return report_error(loaded.error());
    world = std::move(loaded).value();
    Result<LaserRunOptions> o = simulated_input_.options();
    if (!o) return report_error(o.error());
    run_options = *o;
    Result<SimulatedLaserRun> run = simulated_input_.simulate(*world, run_options);
    if (!run) return report_error(run.error());
    simulated = std::move(run).value();
  }
  options.map_resolution_m = cell_m_ ? *cell_m_ : world ? world->geometry().resolution_m() : 0.05;
  std::vector<slam::TrajectoryStart> starts;  // --resume: the session's scans, then the log's
  nlohmann::json resumed;
  double sweep_s = 0.0;  // scans alone: making the sweeps' velocities
  if (resume_) {
    Result<Resumed> r = resume_session(std::move(*read_log), options, resumed);
    if (!r) return report_error(r.error());
    read_log = std::move(r->log);
    starts = std::move(r->starts);
  } else if (read_log) {
    // Scans alone from a spinning lidar: each sweep's velocity from odometry made from the scans
    // (a resumed log gets it with the odometry its start is found by); its time is SLAM's. A log
    // with odometry, or without beam times, is left as it is.
    const auto t_sweep = std::chrono::steady_clock::now();
    Result<LaserLog> swept =
        slam::with_scan_matched_sweep_velocities(std::move(*read_log), options);
    if (!swept) return report_error(swept.error());
    read_log = std::move(swept).value();
    sweep_s = seconds_since(t_sweep);
  }
  const LaserLog& log = simulated ? simulated->log : *read_log;
  if (auto problem = slam::validate(options)) return report_error(usage_error(*problem));
  const std::string input_name = input_.given() ? input_.name() : world->name();
  std::optional<std::vector<Relation>> relations;
  if (relations_) {
    Result<std::vector<Relation>> read = read_relations(*relations_);
    if (!read) return report_error(read.error());
    relations = std::move(read).value();
  }

  Result<Recording> recording = Recording::open(streams_, "slam");
  if (!recording) return report_error(recording.error());

  ProgressLine progress(!quiet_ && stderr_is_terminal());
  options.progress = [&progress](const slam::SlamProgress& p) {
    if (p.scans_done % 25 != 0 && p.scans_done != p.scans_total) return;
    progress.show(fmt::format("slam: scan {}/{}  submaps {}  loop closures {}", p.scans_done,
                              p.scans_total, p.submaps, p.loop_closures),
                  p.scans_done, p.scans_total, "scans");
  };
  const auto t0 = std::chrono::steady_clock::now();
  Result<slam::LaserSlamResult> result =
      run_laser_slam_served(log, starts, options, *recording, autosaver(log, starts, options));
  progress.finish();
  const double wall_s = sweep_s + seconds_since(t0);
  if (!result) {
    Error e = result.error();
    e.message = input_name + ": " + e.message;
    return report_error(e);
  }
  const slam::LaserSlamResult& r = *result;
  const double duration_s = data_duration_s(log);

  std::optional<RelationMetric> metric;
  if (relations) {
    Result<RelationMetric> scored =
        relation_metric(newest_poses(r.trajectory, starts), *relations, time_offset_s_);
    if (!scored) {
      Error e = scored.error();
      e.message = relations_->string() + " against the SLAM trajectory: " + e.message;
      return report_error(e);
    }
    metric = std::move(scored).value();
  }

  const slam::LaserSlamStats& st = r.stats;
  nlohmann::json report = {{"options", slam_options_json(options,
                                                         input_.log   ? "log"
                                                         : input_.bag ? "bag"
                                                                      : "world",
                                                         input_name)},
                           {"slam", slam_stats_json(r, log)}};
  // A log has no random draw: the seed is null unless the run is simulated.
  report.update(core_report(
      {"slam", simulated ? std::optional<std::uint64_t>(simulated_input_.seed) : std::nullopt,
       report["options"], wall_s, duration_s}));
  if (relations_) report["options"]["relations"] = relations_->string();
  if (input_.bag) report["bag"] = bag_report;
  Result<std::optional<slam::TrimmedRun>> trimmed =
      trim_session(log, starts, options, r, resumed["trim"] = nlohmann::json::object());
  if (!trimmed) return report_error(trimmed.error());
  if (resume_) report["resume"] = resumed;
  // A simulated run: its ATE of SLAM, local SLAM and odometry against the truth, and the map
  // against the world, aligned as the ATE aligns the trajectory.
  std::optional<DriftCorrectionScore> score;
  MapAccuracy map_accuracy;
  if (simulated) {
    Result<DriftCorrectionScore> scored = score_drift_correction(
        r.trajectory, odometry_trajectory(log), simulated->truth, &r.local_trajectory);
    if (!scored) return report_error(scored.error());
    score = *scored;
    map_accuracy = compare_to_truth_at_centres(
        r.map, TruthGrid(world->geometry(), world->solid_cells()), score->T_truth_slam());
    report["simulation"] = simulation_json(*simulated, *world, run_options);
    report["ate"] = ate_json(*score);
    report["map_accuracy"] = map_accuracy_json(map_accuracy, score->T_truth_slam());
  }
  if (metric) {
    report["options"]["time_offset_s"] = time_offset_s_;
    report["relations"] = relations_report(*metric, {})["relations"];
  }

  // Outputs: each file is written atomically; the folder is made only now.
  if (Status s = write_laser_slam_outputs(out_, r, report, world ? &*world : nullptr,
                                          score ? score->T_truth_slam() : Pose2{},
                                          simulated ? &*simulated : nullptr);
      !s) {
    return report_error(s.error());
  }
  if (Status s = *trimmed ? save_session((*trimmed)->log.scans, (*trimmed)->trim.starts, options,
                                         (*trimmed)->result)
                          : save_session(log.scans, starts, options, r);
      !s) {
    return report_error(s.error());
  }
  if (MessageSink* file = recording->file_sink()) recording->note(record_laser_slam(*file, log, r));
  if (MessageSink* live = recording->live_sink()) {
    recording->note(record_laser_slam_result(*live, r));
  }
  if (Status s = recording->finish(); !s) return report_error(s.error());

  if (!quiet_) {
    fmt::print(
        "slam: {} scans, {} nodes, {} submaps, {} loop closures; {:.1f} s for {:.1f} s of data "
        "({:.1f}x real time)\n",
        st.scans, st.nodes, st.submaps, st.loop_closures, wall_s, duration_s,
        realtime_factor(duration_s, wall_s).value_or(0.0));
    if (metric) print_relations_summary(*metric);
    if (score) {
      fmt::print(
          "ground truth: ATE {:.4f} m with SLAM, {:.4f} m odometry alone ({:.1f}x); map: {} of "
          "{} occupied cells seen as empty ({:.2f} %)\n",
          score->slam.trans_m.rmse, score->odometry.trans_m.rmse, score->odometry_over_slam(),
          map_accuracy.occupied_as_empty, map_accuracy.occupied_compared,
          100.0 * map_accuracy.occupied_as_empty_share());
    }
    fmt::print("outputs: {}/map.yaml map.pgm map.png trajectory.txt graph.g2o report.json{}\n",
               out_.string(), simulated ? " truth.txt odometry.txt" : "");
    if (streams_.record) fmt::print("recording: {}\n", streams_.record->string());
  }
  recording->linger(!quiet_);
  return kExitOk;
}

}  // namespace tessera::cli
