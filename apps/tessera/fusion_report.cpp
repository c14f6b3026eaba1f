// The report.json blocks, pictures and summary lines of tessera fusion (cmd_fusion*.cpp): JSON of
// the library's result structs, nothing computed here beyond formatting.
#include "fusion_report.hpp"

#include <fmt/format.h>

#include <cmath>
#include <string>
#include <tuple>
#include <utility>

#include "tessera/core/angle.hpp"
#include "tessera/eval/drift_correction.hpp"
#include "tessera/io/atomic_file.hpp"
#include "tessera/io/json_file.hpp"
#include "tessera/io/tum_trajectory.hpp"

namespace tessera::cli {

nlohmann::json transform_json(const Eigen::Isometry3d& T) {
  const Eigen::Quaterniond q(T.linear());
  nlohmann::json rows = nlohmann::json::array();
  for (int r = 0; r < 3; ++r) {
    rows.push_back({T(r, 0), T(r, 1), T(r, 2), T(r, 3)});
  }
  return {{"translation_m", {T.translation().x(), T.translation().y(), T.translation().z()}},
          {"quaternion_xyzw", {q.x(), q.y(), q.z(), q.w()}},
          {"rotation_deg", rad_to_deg(Eigen::AngleAxisd(T.linear()).angle())},
          {"matrix_3x4", rows}};
}

nlohmann::json node_json(const fusion::NodeCreation& c) {
  return {{"check", std::string(fusion::to_string(c.check))},
          {"valid_depth_fraction", c.valid_depth_fraction},
          {"features", c.features},
          {"features_with_depth", c.features_with_depth}};
}

nlohmann::json pose_json(const Pose2& p) {
  return {{"x_m", p.x}, {"y_m", p.y}, {"theta_rad", p.theta}};
}

/// The SLAM's counters, as both the teach-and-repeat rows and the --world / --sequence reports give
/// them.
nlohmann::json statistics_json(const fusion::FusionStatistics& st) {
  return {{"frames_rejected", st.frames_rejected},
          {"node_check_failures", st.node_check_failures},
          {"matches_tried", st.matches_tried},
          {"matches_accepted", st.matches_accepted},
          {"matches_rejected", st.matches_tried - st.matches_accepted},
          {"match_rejections", st.match_rejections},
          {"optimisations", st.optimisations}};
}

nlohmann::json run_json(const TeachAndRepeatRun& r) {
  nlohmann::json searches = nlohmann::json::array();
  for (const TeachAndRepeatRun::Search& s : r.searches) {
    searches.push_back({{"node", s.node},
                        {"confirmed", s.confirmed},
                        {"captures", s.captures},
                        {"reason", s.last_reason},
                        {"offset_m", s.offset_m},
                        {"true_offset_m", s.true_offset_m},
                        {"first_offset_m", s.first_offset_m},
                        {"odometry_error_m", s.odometry_error_m}});
  }
  nlohmann::json row = {{"seed", r.seed},
                        {"start", pose_json(r.start)},
                        {"goal_m", {r.goal_m.x, r.goal_m.y}},
                        {"taught_route_length_m", r.taught_route_length_m},
                        {"taught_goal_pose", pose_json(r.taught_goal_pose)},
                        {"reached_goal_cell", r.reached_goal_cell},
                        {"goal_cell_distance_m", r.goal_cell_distance_m},
                        {"final_pose", pose_json(r.final_pose)},
                        {"final_error_x_m", r.final_error_x_m},
                        {"final_error_y_m", r.final_error_y_m},
                        {"final_error_m", r.final_error_m},
                        {"final_heading_error_deg", rad_to_deg(r.final_heading_error_rad)},
                        {"navigation_path_m", r.navigation_path_m},
                        {"shortest_cell_path_m", r.shortest_cell_path_m},
                        {"path_ratio", r.path_ratio},
                        {"navigation_time_s", r.navigation_time_s},
                        {"heading_reversals", r.heading_reversals},
                        {"odometry_error_at_goal_m", r.odometry_error_at_goal_m},
                        {"estimate_error_at_goal_m", r.estimate_error_at_goal_m},
                        {"ate_corrected_m", r.ate_corrected_m},
                        {"ate_odometry_m", r.ate_odometry_m},
                        {"ate_ratio", r.ate_ratio},
                        {"wrong_matches", r.wrong_matches},
                        {"max_match_error_m", r.max_match_error_m},
                        {"search_trials", r.search_trials},
                        {"search_successes", r.search_successes},
                        {"searches", searches},
                        {"cells", r.cells},
                        {"goal_cell", r.goal_cell},
                        {"goal_cell_image_nodes", r.goal_cell_image_nodes},
                        {"image_nodes", r.image_nodes},
                        {"pose_nodes", r.pose_nodes},
                        {"frames", r.slam.frames},
                        {"frames_dropped", r.frames_dropped},
                        {"simulated_s", r.duration_s}};
  row.update(statistics_json(r.slam));
  if (!r.obstacles_m.empty()) {
    nlohmann::json boxes = nlohmann::json::array();
    for (const auto& [lo, hi] : r.obstacles_m) boxes.push_back({lo.x, lo.y, hi.x, hi.y});
    row["obstacle_course"] = {{"boxes_m", boxes},
                              {"avoidance_updates", r.avoidance_updates},
                              {"detours", r.detours},
                              {"bumper_hits", r.bumper_hits},
                              {"blocked_steps", r.blocked_steps}};
  }
  return row;
}

HexMapPicture picture_of_slam(const fusion::FusionSlam& slam, const World* world) {
  HexMapPicture p;
  p.map = &slam.map();
  p.floor_plan = world;
  for (const fusion::StoredImageNode& n : slam.image_nodes()) {
    p.image_nodes_m.push_back({n.node.placement.T_map_robot.x, n.node.placement.T_map_robot.y});
  }
  if (world != nullptr) {
    const GridGeometry& g = world->geometry();
    const double extent_m = std::max(g.width(), g.height()) * g.resolution_m();
    p.pixels_per_m = std::min(100.0, 4000.0 / std::max(extent_m, 1.0));
  }
  return p;
}

HexMapPicture picture_of(const TeachAndRepeatResult& result, const World& world) {
  HexMapPicture p = picture_of_slam(result.slam, &world);
  p.taught_path_m = result.run.taught_path_m;
  p.repeated_path_m = result.run.repeated_path_m;
  p.true_path_m = result.run.true_path_m;
  p.start_cell = static_cast<std::ptrdiff_t>(result.run.start_cell);
  p.goal_cell = static_cast<std::ptrdiff_t>(result.run.goal_cell);
  p.obstacles_m = result.run.obstacles_m;
  return p;
}

nlohmann::json slam_json(const fusion::FusionSlam& slam, std::size_t frames, int frames_loaded) {
  nlohmann::json j = {{"frames_in_sequence", frames},
                      {"frames_loaded", frames_loaded},
                      {"cells", slam.map().cell_count()},
                      {"image_nodes", slam.image_nodes().size()},
                      {"pose_nodes", slam.map().pose_nodes().size()}};
  j.update(statistics_json(slam.statistics()));
  return j;
}

/// The ATE (aligned, as TUM's evaluate_ate.py) of the corrected trajectory and of odometry alone at
/// the pose-graph nodes (eval/drift_correction.hpp), when there is ground truth (robot poses,
/// world frame).
nlohmann::json trajectory_json(const fusion::FusionSlam& slam,
                               const std::vector<StampedPose2>& truth) {
  const std::vector<StampedPose2> corrected = slam.corrected_trajectory();
  nlohmann::json trajectory = {{"poses", corrected.size()}};
  if (truth.empty()) return trajectory;
  const Result<DriftCorrectionScore> score =
      score_drift_correction(corrected, slam.odometry_trajectory(), truth);
  if (score) {
    trajectory["ate_rmse_m"] = score->slam.trans_m.rmse;
    trajectory["ate_odometry_rmse_m"] = score->odometry.trans_m.rmse;
    trajectory["ate_ratio"] = score->odometry_over_slam();
    trajectory["ate_pairs"] = score->slam.trans_m.count;
  }
  return trajectory;
}

/// The outputs of --world and --sequence: hex_map.svg and .png, trajectory.txt (the corrected
/// trajectory at the graph nodes), truth.txt when there is ground truth, and report.json last.
Status write_slam_outputs(const std::filesystem::path& out, const std::string& svg,
                          const HexMapPicture& picture, const fusion::FusionSlam& slam,
                          const std::vector<StampedPose2>& truth, const nlohmann::json& report) {
  if (Status s = ensure_directory(out); !s) return s;
  if (Status s = write_file_atomic(out / "hex_map.svg", svg); !s) return s;
  if (Status s = write_hex_map_png(out / "hex_map.png", picture); !s) return s;
  if (Status s = write_tum_trajectory(out / "trajectory.txt", slam.corrected_trajectory()); !s) {
    return s;
  }
  if (!truth.empty()) {
    if (Status s = write_tum_trajectory(out / "truth.txt", truth); !s) return s;
  }
  return write_json_atomic(out / "report.json", report);
}

void print_slam_summary(const std::string& what, fusion::FeatureType type,
                        const fusion::FusionSlam& slam, const nlohmann::json& trajectory,
                        const std::filesystem::path& out, bool wrote_truth) {
  const fusion::FusionStatistics& st = slam.statistics();
  std::string ate;
  if (trajectory.contains("ate_rmse_m")) {
    ate = fmt::format(", ATE {:.3f} m (odometry {:.3f} m)", trajectory["ate_rmse_m"].get<double>(),
                      trajectory["ate_odometry_rmse_m"].get<double>());
  }
  fmt::print("fusion: {} ({}): {} cells, {} image nodes, {} of {} matches accepted{}\n", what,
             fusion::to_string(type), slam.map().cell_count(), slam.image_nodes().size(),
             st.matches_accepted, st.matches_tried, ate);
  fmt::print("outputs: {}/hex_map.svg hex_map.png trajectory.txt{} report.json\n", out.string(),
             wrote_truth ? " truth.txt" : "");
}

nlohmann::json summary_json(const TeachAndRepeatSummary& s) {
  return {{"runs", s.runs},
          {"reached_goal_cell", s.reached_goal_cell},
          {"max_final_error_m", s.max_final_error_m},
          {"max_path_ratio", s.max_path_ratio},
          {"min_ate_ratio", s.min_ate_ratio},
          {"search_trials", s.search_trials},
          {"search_successes", s.search_successes}};
}

namespace {

/// The feature path's keys of the "pair" block; returns its reason and summary.
std::pair<std::string, std::string> feature_keys(const fusion::FramePairMatch& m,
                                                 nlohmann::json& j) {
  if (!m.prev->ok() || !m.curr->ok()) {
    const bool prev_failed = !m.prev->ok();
    const fusion::NodeCreation& failed = prev_failed ? *m.prev : *m.curr;
    j["matches"] = 0;
    j["inliers"] = 0;
    return {std::string(prev_failed ? "previous" : "current") +
                " frame: " + std::string(fusion::to_string(failed.check)),
            failed.reason};
  }
  const fusion::MatchResult& f = *m.features;
  j["matches"] = f.matches;
  j["matches_3d"] = f.matches_3d;
  j["inliers"] = f.inliers;
  j["inlier_ratio"] = f.inlier_ratio;
  j["rmse_m"] = f.rmse_m;
  j["median_reprojection_px"] = f.median_reprojection_px;
  j["image_coverage"] = f.image_coverage;
  j["spread_m"] = f.spread_m;
  j["pnp_disagreement_m"] = f.pnp_disagreement_m;
  j["pnp_disagreement_deg"] = rad_to_deg(f.pnp_disagreement_rad);
  j["pnp_disagreement_chi2"] = f.pnp_disagreement_chi2;
  return {std::string(fusion::to_string(f.reason)),
          fmt::format("{} inliers of {} matches", f.inliers, f.matches)};
}

nlohmann::json depth_icp_json(const fusion::DepthIcpResult& d) {
  return {
      {"accepted", d.accepted},
      {"reason", std::string(fusion::to_string(d.reason))},
      {"reason_text", d.reason_text},
      {"points", d.points},
      {"pairs", d.pairs},
      {"overlap", d.overlap},
      {"rmse_m", d.rmse_m},
      {"rms_sigmas", d.rms_sigmas},
      {"condition_number", std::isfinite(d.condition_number) ? nlohmann::json(d.condition_number)
                                                             : nlohmann::json(nullptr)},
      {"iterations", d.iterations}};
}

}  // namespace

PairReport pair_report(const std::filesystem::path& folder, const RgbdPair& pair,
                       const fusion::FramePairMatch& m) {
  PairReport out;
  nlohmann::json& j = out.pair;
  j = {{"folder", folder.string()}};
  std::string method = "none";
  std::string reason_text;
  if (m.prev && m.curr) {
    j["nodes"] = {{"prev", node_json(*m.prev)}, {"curr", node_json(*m.curr)}};
    std::tie(out.reason, out.summary) = feature_keys(m, j);
    reason_text = m.features ? m.features->reason_text : out.summary;
    if (m.features) method = std::string(fusion::to_string(m.features->method));
  }
  if (m.depth) {
    // The depth ICP decided (issue 18 item 10); the feature path's verdict stays beside it.
    if (m.prev) j["features_reason"] = out.reason;
    j["depth_icp"] = depth_icp_json(*m.depth);
    method = "depth-icp";
    out.reason = m.depth->accepted
                     ? "accepted by depth ICP"
                     : "depth ICP: " + std::string(fusion::to_string(m.depth->reason));
    reason_text = m.depth->reason_text;
    out.summary = reason_text;
  }
  out.accepted = m.accepted;
  j["accepted"] = m.accepted;
  j["reason"] = out.reason;
  j["reason_text"] = reason_text;
  j["method"] = method;
  if (method != "none") j["T_prev_curr"] = transform_json(m.T_prev_curr);
  if (pair.has_ground_truth && m.accepted) {
    const Eigen::Isometry3d d = pair.T_prev_curr_truth().inverse() * m.T_prev_curr;
    const double rotation_deg = rad_to_deg(Eigen::AngleAxisd(d.linear()).angle());
    j["translation_error_m"] = d.translation().norm();
    j["rotation_error_deg"] = rotation_deg;
    out.summary +=
        fmt::format("; error {:.4f} m, {:.3f} deg", d.translation().norm(), rotation_deg);
  }
  if (pair.has_ground_truth)
    j["ground_truth_T_prev_curr"] = transform_json(pair.T_prev_curr_truth());
  return out;
}

nlohmann::json pair_options_json(const std::filesystem::path& folder, const RgbdPair& pair,
                                 const fusion::FramePairOptions& options) {
  const fusion::ImageNodeOptions& node_options = options.node;
  const fusion::NodeMatcherOptions& match_options = options.matcher;
  const fusion::DepthIcpOptions& icp = options.icp;
  return {{"mode", "pair"},
          {"pair_method", std::string(fusion::to_string(options.method))},
          {"pair", folder.string()},
          {"features", std::string(fusion::to_string(node_options.feature_type))},
          {"intrinsics",
           {{"fx_px", pair.prev.intrinsics.fx_px},
            {"fy_px", pair.prev.intrinsics.fy_px},
            {"cx_px", pair.prev.intrinsics.cx_px},
            {"cy_px", pair.prev.intrinsics.cy_px},
            {"source", pair.has_intrinsics_file ? "intrinsics.txt" : "TUM fr1 default"}}},
          {"max_features", node_options.max_features},
          {"min_depth_m", node_options.min_depth_m},
          {"max_depth_m", node_options.max_depth_m},
          {"ratio", match_options.ratio},
          {"mutual", match_options.mutual},
          {"inlier_threshold_m", match_options.ransac.inlier_threshold_m},
          {"min_inliers", match_options.min_inliers},
          {"min_inlier_ratio", match_options.min_inlier_ratio},
          {"min_image_coverage", match_options.min_image_coverage},
          {"min_spread_m", match_options.min_spread_m},
          {"max_median_reprojection_px", match_options.max_median_reprojection_px},
          {"pnp_fallback", match_options.pnp_fallback},
          {"depth_icp",
           {{"levels", icp.levels},
            {"finest_block_px", icp.finest_block_px},
            {"max_pair_distance_m", icp.max_pair_distance_m},
            {"min_overlap", icp.min_overlap},
            {"max_rms_sigmas", icp.max_rms_sigmas},
            {"max_condition_number", icp.max_condition_number}}}};
}

}  // namespace tessera::cli
