// tessera slam: laser SLAM (slam/laser_slam.hpp) on a 2D laser log, or on a simulated run in a
// world (sim/laser_run.hpp) that is then scored against its ground truth (ATE of SLAM and of
// odometry alone, map accuracy). Thin glue: read or simulate the input first, so that bad input
// writes nothing; run; write map, trajectory, graph and report.json; print one summary line.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "tessera/core/angle.hpp"
#include "tessera/eval/map_accuracy.hpp"
#include "tessera/eval/relation_metric.hpp"
#include "tessera/trajectory/stamped_pose3.hpp"
#include "tessera/eval/trajectory_error.hpp"
#include "tessera/io/atomic_file.hpp"
#include "tessera/io/carmen_log.hpp"
#include "tessera/report/core_report.hpp"
#include "tessera/report/eval_report.hpp"
#include "tessera/io/g2o_file.hpp"
#include "tessera/io/json_file.hpp"
#include "tessera/io/map_yaml.hpp"
#include "tessera/io/relations_file.hpp"
#include "tessera/render/render.hpp"
#include "tessera/io/robot_bag.hpp"
#include "tessera/io/tum_trajectory.hpp"
#include "tessera/sim/laser_run.hpp"
#include "tessera/slam/laser_slam.hpp"

namespace tessera::cli {
namespace {

/// Stamps may go backwards in real logs: the span is max - min.
double data_duration_s(const LaserLog& log) {
  if (log.scans.empty()) return 0.0;
  const auto [lo, hi] =
      std::minmax_element(log.scans.begin(), log.scans.end(),
                          [](const StampedScan& a, const StampedScan& b) { return a.t_s < b.t_s; });
  return hi->t_s - lo->t_s;
}

/// The scans' odometry poses as a trajectory.
std::vector<StampedPose2> odometry_trajectory(const LaserLog& log) {
  std::vector<StampedPose2> out;
  out.reserve(log.scans.size());
  for (const StampedScan& s : log.scans) out.push_back({s.t_s, s.odometry});
  return out;
}

/// The planar part of a 3D alignment (x, y and the rotation about z).
Pose2 planar(const Eigen::Isometry3d& T) {
  return {T.translation().x(), T.translation().y(), std::atan2(T.linear()(1, 0), T.linear()(0, 0))};
}

/// What a simulated run is scored by: the ATE of SLAM, of local SLAM alone and of odometry alone
/// against the truth, and the SLAM map against the world.
struct SimulationScore {
  double slam_ate_m = 0.0;
  double local_ate_m = 0.0;
  double odometry_ate_m = 0.0;
  Pose2 T_truth_map;  // the SLAM trajectory's alignment, applied to its map
  MapAccuracy map;
};

Result<SimulationScore> score_simulation(const SimulatedLaserRun& run, const World& world,
                                         const slam::LaserSlamResult& r) {
  Result<AbsoluteTrajectoryError> slam_ate = absolute_trajectory_error(r.trajectory, run.truth);
  if (!slam_ate) return slam_ate.error();
  Result<AbsoluteTrajectoryError> local_ate =
      absolute_trajectory_error(r.local_trajectory, run.truth);
  if (!local_ate) return local_ate.error();
  Result<AbsoluteTrajectoryError> odometry_ate =
      absolute_trajectory_error(odometry_trajectory(run.log), run.truth);
  if (!odometry_ate) return odometry_ate.error();
  SimulationScore score;
  score.slam_ate_m = slam_ate->trans_m.rmse;
  score.local_ate_m = local_ate->trans_m.rmse;
  score.odometry_ate_m = odometry_ate->trans_m.rmse;
  // The map lives in the SLAM trajectory's frame: align it as the ATE aligns the trajectory.
  score.T_truth_map = planar(slam_ate->T_reference_estimate);
  score.map = compare_to_truth_at_centres(r.map, TruthGrid(world.geometry(), world.solid_cells()),
                                          score.T_truth_map);
  return score;
}

}  // namespace

SlamCommand::SlamCommand(CLI::App& app) {
  sub_ = app.add_subcommand(
      "slam",
      "Laser SLAM (submaps, branch-and-bound loop closure, pose graph; Hess et al. 2016) on a 2D "
      "laser log (--log), or on a simulated run in a world (--world / --builtin) scored against "
      "its ground truth; writes map.yaml + map.pgm, map.png, trajectory.txt (one pose per scan), "
      "graph.g2o and report.json to --out");
  sub_->add_option("--log", log_, "Laser log: CARMEN .clf/.log (FLASER, ROBOTLASER1, RAWLASER1)");
  sub_->add_option("--bag", bag_,
                   "ROS bag: a ROS 1 .bag, a rosbag2 folder, a .db3 or an .mcap file (LaserScan, "
                   "Odometry, the laser pose from /tf_static and /tf)");
  sub_->add_option("--scan-topic", scan_topic_,
                   "--bag: the sensor_msgs/LaserScan topic (needed when there are several)");
  sub_->add_option("--odom-topic", odom_topic_,
                   "--bag: the nav_msgs/Odometry topic (needed when there are several)");
  sub_->add_option("--base-frame", base_frame_,
                   "--bag: the robot frame (default: the odometry's child_frame_id)");
  add_world_options(*sub_, world_);
  sub_->add_option("--seed", seed_, "Simulated run: seed of the start, odometry and range noise")
      ->capture_default_str();
  sub_->add_option("--duration-s", duration_s_,
                   "Simulated run: stop the covering tour after this many seconds (0: no limit)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  sub_->add_option("--start", start_, "Simulated run: start position X,Y in metres (default: random)");
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
  sub_->add_flag("--quiet", quiet_, "No progress line and no summary");
}

int SlamCommand::run() const {
  if (!std::isfinite(time_offset_s_)) {
    return report_error(usage_error("--time-offset must be a finite number of seconds"));
  }
  if (log_ && world_.file) return report_error(usage_error("give --log or --world, not both"));
  if (bag_ && (log_ || world_.file)) {
    return report_error(usage_error("give --bag alone, not with --log or --world"));
  }
  if (!bag_ && (!scan_topic_.empty() || !odom_topic_.empty() || !base_frame_.empty())) {
    return report_error(usage_error("--scan-topic, --odom-topic and --base-frame need --bag"));
  }
  if (!log_ && !bag_ && relations_) {
    return report_error(usage_error("--relations scores a log: it needs --log or --bag"));
  }
  slam::LaserSlamOptions options;
  options.loop_closure = !no_loop_closure_;

  // Inputs first: a bad log, world or relations file must leave nothing behind.
  std::optional<LaserLog> read_log;
  std::optional<World> world;
  std::optional<SimulatedLaserRun> simulated;
  nlohmann::json bag_report;  // --bag: the topics and frames read
  if (log_) {
    Result<LaserLog> read = read_carmen_log(*log_);
    if (!read) return report_error(read.error());
    read_log = std::move(read).value();
  } else if (bag_) {
    Result<RobotBag> read = read_robot_bag(*bag_, {scan_topic_, odom_topic_, base_frame_});
    if (!read) return report_error(read.error());
    const Pose2& laser = read->log.scans.front().laser_in_robot;
    bag_report = {{"format", read->format},
                  {"scan_topic", read->scan_topic},
                  {"odom_topic", read->odom_topic},
                  {"odom_frame", read->odom_frame},
                  {"base_frame", read->base_frame},
                  {"laser_frame", read->laser_frame},
                  {"laser_in_robot_m_rad", {laser.x, laser.y, laser.theta}},
                  {"no_return_readings", read->no_return_readings}};
    read_log = std::move(read->log);
  } else {
    Result<World> loaded = load_world(world_, 0.05);
    if (!loaded) return report_error(loaded.error());
    world = std::move(loaded).value();
    LaserRunOptions run_options;
    run_options.max_duration_s = duration_s_;
    if (start_) {
      Result<Vec2> p = parse_point(*start_, "--start");
      if (!p) return report_error(p.error());
      run_options.start = Pose2{p->x, p->y, 0.0};
    }
    Result<SimulatedLaserRun> run = simulate_laser_run(*world, run_options, seed_);
    if (!run) {
      Error e = run.error();
      e.message = world->name().empty() ? e.message : world->name() + ": " + e.message;
      return report_error(e);
    }
    simulated = std::move(run).value();
  }
  const LaserLog& log = simulated ? simulated->log : *read_log;
  options.map_resolution_m = cell_m_ ? *cell_m_ : world ? world->geometry().resolution_m() : 0.05;
  if (auto problem = slam::validate(options)) return report_error(usage_error(*problem));
  const std::string input_name = log_ ? log_->string() : bag_ ? bag_->string() : world->name();
  std::optional<std::vector<Relation>> relations;
  if (relations_) {
    Result<std::vector<Relation>> read = read_relations(*relations_);
    if (!read) return report_error(read.error());
    relations = std::move(read).value();
  }

  ProgressLine progress(!quiet_ && stderr_is_terminal());
  options.progress = [&progress](const slam::SlamProgress& p) {
    if (p.scans_done % 25 != 0 && p.scans_done != p.scans_total) return;
    progress.show(fmt::format("slam: scan {}/{}  nodes {}  submaps {}  loop closures {}",
                              p.scans_done, p.scans_total, p.nodes, p.submaps, p.loop_closures));
  };
  const auto t0 = std::chrono::steady_clock::now();
  Result<slam::LaserSlamResult> result = slam::run_laser_slam(log, options);
  progress.finish();
  const double wall_s = seconds_since(t0);
  if (!result) {
    Error e = result.error();
    e.message = input_name + ": " + e.message;
    return report_error(e);
  }
  const slam::LaserSlamResult& r = *result;
  const double duration_s = data_duration_s(log);

  std::optional<RelationMetric> metric;
  if (relations) {
    Result<RelationMetric> scored = relation_metric(r.trajectory, *relations, time_offset_s_);
    if (!scored) {
      Error e = scored.error();
      e.message = relations_->string() + " against the SLAM trajectory: " + e.message;
      return report_error(e);
    }
    metric = std::move(scored).value();
  }

  const slam::LaserSlamStats& st = r.stats;
  nlohmann::json report = {{"options",
                            {{log_ ? "log" : bag_ ? "bag" : "world", input_name},
                             {"loop_closure", options.loop_closure},
                             {"map_resolution_m", options.map_resolution_m},
                             {"submap_resolution_m", options.submaps.resolution_m},
                             {"scans_per_submap", options.submaps.scans_per_submap},
                             {"max_range_m", options.points.max_range_m},
                             {"loop_window_m", options.loop_closer.window.linear_m},
                             {"loop_window_rad", options.loop_closer.window.angular_rad},
                             {"loop_min_score", options.loop_closer.min_score},
                             {"loop_sampling_ratio", options.loop_sampling_ratio},
                             {"optimize_every_n_nodes", options.optimize_every_n_nodes},
                             {"travel_per_submap_m", options.submaps.travel_per_submap_m},
                             {"refiner_translation_weight_per_m",
                              options.refiner.translation_weight},
                             {"refiner_rotation_weight_per_rad", options.refiner.rotation_weight},
                             {"local_sigmas_per_m",
                              {options.local_sigmas_per_m.translation_m,
                               options.local_sigmas_per_m.rotation_rad}},
                             {"loop_window_growth_m_per_m", options.loop_window_growth_m_per_m},
                             {"loop_window_growth_rad_per_m", options.loop_window_growth_rad_per_m},
                             {"loop_window_max_m_rad",
                              {options.loop_window_max.linear_m,
                               options.loop_window_max.angular_rad}}}},
                           {"slam",
                            {{"scans", st.scans},
                             {"nodes", st.nodes},
                             {"submaps", st.submaps},
                             {"loop_searches", st.loop_searches},
                             {"global_searches", st.global_searches},
                             {"loop_closures", st.loop_closures},
                             {"loop_candidates", st.loop_candidates},
                             {"loop_unverified", st.loop_unverified},
                             {"loop_rejected", st.loop_rejected},
                             {"optimizations", st.optimizations},
                             {"graph_vertices", r.graph.poses.size()},
                             {"graph_edges", r.graph.edges.size()},
                             {"backward_stamps", log.backward_stamps},
                             {"matching_s", st.matching_s},
                             {"loop_search_s", st.loop_search_s},
                             {"optimization_s", st.optimization_s},
                             {"map_s", st.map_s}}}};
  // A log has no random draw: the seed is null unless the run is simulated.
  report.update(core_report({"slam",
                             simulated ? std::optional<std::uint64_t>(seed_) : std::nullopt,
                             report["options"], wall_s, duration_s}));
  if (relations_) report["options"]["relations"] = relations_->string();
  if (bag_) report["bag"] = bag_report;
  std::optional<SimulationScore> score;
  if (simulated) {
    Result<SimulationScore> scored = score_simulation(*simulated, *world, r);
    if (!scored) return report_error(scored.error());
    score = *scored;
    const MapAccuracy& m = score->map;
    report["simulation"] = {{"duration_s", simulated->duration_s},
                            {"path_length_m", simulated->path_length_m},
                            {"turned_rad", simulated->turned_rad},
                            {"tour_completed", simulated->tour_completed},
                            {"world_resolution_m", world->geometry().resolution_m()}};
    report["ate"] = {{"slam_rmse_m", score->slam_ate_m},
                     {"local_slam_rmse_m", score->local_ate_m},
                     {"odometry_rmse_m", score->odometry_ate_m},
                     {"odometry_over_slam",
                      score->slam_ate_m > 0.0 ? score->odometry_ate_m / score->slam_ate_m : 0.0}};
    report["map_accuracy"] = {{"truth", "world cell under each map cell's centre, map aligned as the ATE aligns the trajectory"},
                              {"alignment_m_rad",
                               {score->T_truth_map.x, score->T_truth_map.y,
                                score->T_truth_map.theta}},
                              {"cells_compared", m.cells_compared},
                              {"occupied_compared", m.occupied_compared},
                              {"occupied_as_empty", m.occupied_as_empty},
                              {"empty_as_occupied", m.empty_as_occupied},
                              {"occupied_as_empty_share", m.occupied_as_empty_share()},
                              {"success_rate", m.success_rate}};
  }
  if (metric) {
    report["options"]["time_offset_s"] = time_offset_s_;
    report["relations"] = relations_report(*metric, {})["relations"];
  }

  // Outputs: each file is written atomically; the folder is made only now.
  if (Status s = ensure_directory(out_); !s) return report_error(s.error());
  if (Status s = write_map_yaml(r.map, out_ / "map.yaml", MapSaveOptions{}); !s) {
    return report_error(s.error());
  }
  RenderLayers layers;
  layers.map = &r.map;
  if (world) {  // map errors in colour
    layers.truth = &*world;
    layers.T_truth_map = score->T_truth_map;
  }
  std::vector<Vec2> path;
  path.reserve(r.trajectory.size());
  for (const StampedPose2& p : r.trajectory) path.push_back(p.pose.translation());
  if (!path.empty()) layers.robots_m.push_back(path.back());
  layers.paths_m.push_back(std::move(path));
  Result<std::string> png = render_png(layers);
  if (!png) return report_error(png.error());
  const std::string trajectory = encode_tum_trajectory(r.trajectory);
  const std::string graph = encode_g2o(r.graph);
  const std::string json = encode_json(report);
  std::vector<PendingFile> files{{out_ / "map.png", *png},
                                 {out_ / "trajectory.txt", trajectory},
                                 {out_ / "graph.g2o", graph},
                                 {out_ / "report.json", json}};
  std::string truth_tum;  // PendingFile holds a view: the bytes must outlive the write
  std::string odometry_tum;
  if (simulated) {
    truth_tum = encode_tum_trajectory(simulated->truth);
    odometry_tum = encode_tum_trajectory(odometry_trajectory(log));
    files.push_back({out_ / "truth.txt", truth_tum});
    files.push_back({out_ / "odometry.txt", odometry_tum});
  }
  if (Status s = write_files_atomic(files); !s) return report_error(s.error());

  if (!quiet_) {
    fmt::print(
        "slam: {} scans, {} nodes, {} submaps, {} loop closures; {:.1f} s for {:.1f} s of data "
        "({:.1f}x real time)\n",
        st.scans, st.nodes, st.submaps, st.loop_closures, wall_s, duration_s,
        realtime_factor(duration_s, wall_s).value_or(0.0));
    if (metric) {
      fmt::print(
          "relations: {} scored; translation {:.4f} +/- {:.4f} m, rotation {:.3f} +/- "
          "{:.3f} deg\n",
          metric->count, metric->trans_mean_m, metric->trans_std_m,
          rad_to_deg(metric->rot_mean_rad), rad_to_deg(metric->rot_std_rad));
    }
    if (score) {
      fmt::print(
          "ground truth: ATE {:.4f} m with SLAM, {:.4f} m odometry alone ({:.1f}x); map: {} of "
          "{} occupied cells seen as empty ({:.2f} %)\n",
          score->slam_ate_m, score->odometry_ate_m,
          score->slam_ate_m > 0.0 ? score->odometry_ate_m / score->slam_ate_m : 0.0,
          score->map.occupied_as_empty, score->map.occupied_compared,
          100.0 * score->map.occupied_as_empty_share());
    }
    fmt::print("outputs: {}/map.yaml map.pgm map.png trajectory.txt graph.g2o report.json{}\n",
               out_.string(), simulated ? " truth.txt odometry.txt" : "");
  }
  return kExitOk;
}

}  // namespace tessera::cli
