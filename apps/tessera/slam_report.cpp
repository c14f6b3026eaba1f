// The report.json blocks of tessera slam (cmd_slam.cpp): JSON of the library's result structs.
#include "slam_report.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "tessera/core/angle.hpp"
#include "tessera/io/atomic_file.hpp"
#include "tessera/io/g2o_file.hpp"
#include "tessera/io/json_file.hpp"
#include "tessera/io/map_yaml.hpp"
#include "tessera/io/tum_trajectory.hpp"
#include "tessera/render/render.hpp"

namespace tessera::cli {

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

nlohmann::json slam_options_json(const slam::LaserSlamOptions& options,
                                 const std::string& input_kind, const std::string& input_name) {
  return {{input_kind, input_name},
          {"loop_closure", options.loop_closure},
          {"use_odometry", options.use_odometry},
          {"manhattan", options.manhattan},
          {"manhattan_sigma_rad", options.manhattan_sigma_rad},
          {"manhattan_rotation_weight", options.manhattan_rotation_weight},
          {"manhattan_gate_rad", options.manhattan_gate_rad},
          {"map_resolution_m", options.map_resolution_m},
          {"map_miss_margin_m", options.map_insert.miss_margin_m},
          {"map_miss_inset_m", options.map_insert.miss_inset_m},
          {"submap_resolution_m", options.submaps.resolution_m},
          {"scans_per_submap", options.submaps.scans_per_submap},
          {"max_range_m", options.points.max_range_m},
          {"loop_window_m", options.loop_closer.window.linear_m},
          {"loop_window_rad", options.loop_closer.window.angular_rad},
          {"loop_min_score", options.loop_closer.min_score},
          {"loop_sampling_ratio", options.loop_sampling_ratio},
          {"optimize_every_n_nodes", options.optimize_every_n_nodes},
          {"travel_per_submap_m", options.submaps.travel_per_submap_m},
          {"submap_hit_probability", options.submaps.insert.hit_probability},
          {"hit_evidence_step_m", options.submaps.hit_evidence_step_m},
          {"max_hit_evidence_scale", options.submaps.max_hit_evidence_scale},
          {"refiner_translation_weight_per_m", options.refiner.translation_weight},
          {"refiner_rotation_weight_per_rad", options.refiner.rotation_weight},
          {"odometry_calibration", options.odometry_calibration.enabled},
          {"local_sigmas_per_m",
           {options.local_sigmas_per_m.translation_m, options.local_sigmas_per_m.rotation_rad}},
          {"loop_window_growth_m_per_m", options.loop_window_growth_m_per_m},
          {"loop_window_growth_rad_per_m", options.loop_window_growth_rad_per_m},
          {"loop_window_max_m_rad",
           {options.loop_window_max.linear_m, options.loop_window_max.angular_rad}},
          {"final_map_passes", options.final_map_passes},
          {"final_map_hessian_scale", options.final_map_hessian_scale}};
}

nlohmann::json slam_stats_json(const slam::LaserSlamResult& r, const LaserLog& log) {
  const slam::LaserSlamStats& st = r.stats;
  // A spinning lidar's scans, and those of them placed beam by beam (a velocity over the sweep,
  // from the odometry or, for scans alone, from odometry made from the scans).
  const auto swept = std::count_if(log.scans.begin(), log.scans.end(),
                                   [](const StampedScan& s) { return has_beam_times(s.scan); });
  const auto unwarped = std::count_if(log.scans.begin(), log.scans.end(), [](const StampedScan& s) {
    return has_beam_times(s.scan) && !s.robot_velocity.is_zero();
  });
  return {{"scans", st.scans},
          {"swept_scans", swept},
          {"swept_scans_with_velocity", unwarped},
          {"nodes", st.nodes},
          {"submaps", st.submaps},
          {"loop_searches", st.loop_searches},
          {"global_searches", st.global_searches},
          {"loop_closures", st.loop_closures},
          {"loop_candidates", st.loop_candidates},
          {"loop_unverified", st.loop_unverified},
          {"loop_rejected", st.loop_rejected},
          {"optimizations", st.optimizations},
          {"manhattan_priors", st.manhattan_priors},
          {"manhattan_pulls", st.manhattan_pulls},
          {"graph_vertices", r.graph.poses.size()},
          {"graph_edges", r.graph.edges.size()},
          {"backward_stamps", log.backward_stamps},
          {"odometry_translation_scale", st.odometry_translation_scale},
          {"odometry_rotation_scale", st.odometry_rotation_scale},
          {"odometry_drift_rad_per_m", st.odometry_drift_rad_per_m},
          {"matching_s", st.matching_s},
          {"loop_search_s", st.loop_search_s},
          {"optimization_s", st.optimization_s},
          {"whole_map_s", st.whole_map_s},
          {"map_s", st.map_s}};
}

nlohmann::json simulation_json(const SimulatedLaserRun& run, const World& world,
                               const LaserRunOptions& options) {
  return {{"duration_s", run.duration_s},
          {"scan_rate_hz", options.scan_rate_hz},
          {"lidar_sweep_s", options.lidar_sweep_s},
          {"path_length_m", run.path_length_m},
          {"turned_rad", run.turned_rad},
          {"tour_completed", run.tour_completed},
          {"world_resolution_m", world.geometry().resolution_m()}};
}

nlohmann::json ate_json(const DriftCorrectionScore& score) {
  return {{"slam_rmse_m", score.slam.trans_m.rmse},
          {"local_slam_rmse_m", score.local ? score.local->trans_m.rmse : 0.0},
          {"odometry_rmse_m", score.odometry.trans_m.rmse},
          {"odometry_over_slam", score.odometry_over_slam()}};
}

nlohmann::json map_accuracy_json(const MapAccuracy& m, const Pose2& T_truth_map) {
  return {{"truth",
           "world cell under each map cell's centre, map aligned as the ATE aligns the "
           "trajectory"},
          {"alignment_m_rad", {T_truth_map.x, T_truth_map.y, T_truth_map.theta}},
          {"cells_compared", m.cells_compared},
          {"occupied_compared", m.occupied_compared},
          {"occupied_as_empty", m.occupied_as_empty},
          {"empty_as_occupied", m.empty_as_occupied},
          {"occupied_as_empty_share", m.occupied_as_empty_share()},
          {"success_rate", m.success_rate}};
}

nlohmann::json bag_json(const RobotBag& bag) {
  const Pose2& laser = bag.log.scans.front().laser_in_robot;
  return {{"format", bag.format},
          {"scan_topic", bag.scan_topic},
          {"odom_topic", bag.odom_topic},
          {"odom_frame", bag.odom_frame},
          {"base_frame", bag.base_frame},
          {"laser_frame", bag.laser_frame},
          {"laser_in_robot_m_rad", {laser.x, laser.y, laser.theta}},
          {"no_return_readings", bag.no_return_readings}};
}

Status write_laser_slam_outputs(const std::filesystem::path& out, const slam::LaserSlamResult& r,
                                const nlohmann::json& report, const World* world,
                                const Pose2& T_truth_map, const SimulatedLaserRun* simulated) {
  if (Status s = ensure_directory(out); !s) return s;
  if (Status s = write_map_yaml(r.map, out / "map.yaml", MapSaveOptions{}); !s) {
    return s;
  }
  RenderLayers layers;
  layers.map = &r.map;
  if (world != nullptr) {  // map errors in colour
    layers.truth = world;
    layers.T_truth_map = T_truth_map;
  }
  std::vector<Vec2> path;
  path.reserve(r.trajectory.size());
  for (const StampedPose2& p : r.trajectory) path.push_back(p.pose.translation());
  if (!path.empty()) layers.robots_m.push_back(path.back());
  layers.paths_m.push_back(std::move(path));
  Result<std::string> png = render_png(layers);
  if (!png) return png.error();
  const std::string trajectory = encode_tum_trajectory(r.trajectory);
  const std::string graph = encode_g2o(r.graph);
  const std::string json = encode_json(report);
  std::vector<PendingFile> files{{out / "map.png", *png},
                                 {out / "trajectory.txt", trajectory},
                                 {out / "graph.g2o", graph},
                                 {out / "report.json", json}};
  std::string truth_tum;  // PendingFile holds a view: the bytes must outlive the write
  std::string odometry_tum;
  if (simulated != nullptr) {
    truth_tum = encode_tum_trajectory(simulated->truth);
    odometry_tum = encode_tum_trajectory(odometry_trajectory(simulated->log));
    files.push_back({out / "truth.txt", truth_tum});
    files.push_back({out / "odometry.txt", odometry_tum});
  }
  return write_files_atomic(files);
}

void print_relations_summary(const RelationMetric& metric) {
  fmt::print(
      "relations: {} scored; translation {:.4f} +/- {:.4f} m, rotation {:.3f} +/- {:.3f} deg\n",
      metric.count, metric.trans_mean_m, metric.trans_std_m, rad_to_deg(metric.rot_mean_rad),
      rad_to_deg(metric.rot_std_rad));
}

}  // namespace tessera::cli
