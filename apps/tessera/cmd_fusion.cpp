// tessera fusion: the thesis' Fusion SLAM on RGB-D data (issue 5). --pair DIR estimates one frame
// pair's motion (fusion/node_matcher.hpp) or says why it refuses, into report.json under "pair".
// --world FILE maps a simulated run (start -> goal -> start) with the online system
// (fusion/fusion_slam.hpp, fed by fusion/replay.hpp) and scores it against the run's ground truth;
// --teach-and-repeat --world FILE [--runs N] runs the thesis' two-stage experiment (Table 5.1,
// mission/teach_and_repeat.hpp), with the hex-map pictures, TUM trajectories and the per-run table
// in report.json; --sequence DIR feeds a TUM RGB-D folder to the online system along its
// odometry.txt, the same way as --world feeds the simulated run. Thin glue:
// read every input first, so that bad input writes nothing; run the library; write the outputs;
// print one summary line per run.
#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "tessera/io/data_dir.hpp"
#include "tessera/report/core_report.hpp"
#include "tessera/core/angle.hpp"
#include "tessera/core/rng.hpp"
#include "tessera/fusion/feature_type.hpp"
#include "tessera/fusion/image_node.hpp"
#include "tessera/fusion/node_matcher.hpp"
#include "tessera/io/atomic_file.hpp"
#include "tessera/io/json_file.hpp"
#include "tessera/io/rgbd_pair_folder.hpp"
// --world / --teach-and-repeat
#include <cstdlib>

#include "tessera/eval/trajectory_error.hpp"
#include "tessera/fusion/fusion_slam.hpp"
#include "tessera/fusion/replay.hpp"
#include "tessera/io/tum_rgbd_sequence.hpp"
#include "tessera/io/tum_trajectory.hpp"
#include "tessera/mission/teach_and_repeat.hpp"
#include "tessera/render/hex_map_svg.hpp"
#include "tessera/render/simulated_rgbd_sequence.hpp"
#include "tessera/render/wall_textures.hpp"
#include "tessera/sim/poster.hpp"
#include "tessera/sim/rgbd_run.hpp"
#include "tessera/sim/wall_faces.hpp"

namespace tessera::cli {
namespace {

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

}  // namespace

FusionCommand::FusionCommand(CLI::App& app) {
  sub_ = app.add_subcommand(
      "fusion",
      "Fusion SLAM on RGB-D data (thesis chapters 4-6). --pair DIR: estimate one frame pair's "
      "motion (img_prev.png, img_curr.png, dep_prev.png, dep_curr.png, optional pose_prev.txt, "
      "pose_curr.txt, intrinsics.txt) or say why it is refused; writes report.json to --out");
  sub_->add_option("--pair", options_.pair,
                   "Frame pair folder (layout of ../shared/data/rgbd/tum_fr1_xyz_pairs/case_1)");
  sub_->add_option("--features", options_.features,
                   "Feature type: orb, sift or akaze (SURF is not in Debian's OpenCV)")
      ->capture_default_str();
  sub_->add_option("--out", options_.out, "Output folder")->capture_default_str();
  sub_->add_option("--seed", options_.seed, "Seed of the RANSAC sampling")->capture_default_str();
  sub_->add_flag("--quiet", options_.quiet, "No summary line");
  // --world / --teach-and-repeat: simulated runs (mission/teach_and_repeat.hpp).
  add_world_options(*sub_, world_);
  sub_->add_flag("--teach-and-repeat", options_.teach_and_repeat,
                 "The thesis' two-stage experiment (Table 5.1) in the simulated --world: teach the "
                 "route start -> goal -> start, then navigate to the goal cell and find the goal "
                 "node; report.json gets the per-run table");
  sub_->add_option("--sequence", options_.sequence,
                   "TUM RGB-D sequence folder (rgb.txt, depth.txt; its odometry.txt drives the "
                   "map, neck.txt the camera pan; groundtruth.txt scores the trajectory)");
  sub_->add_option("--runs", options_.runs, "Teach-and-repeat runs (seeds --seed, --seed + 1, ...)")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  sub_->add_option("--textures", options_.textures,
                   "Folder of photos hung on the walls as posters (default: "
                   "the data folder, $TESSERA_DATA_DIR or ../shared/data beside the sources, "
                   "then rgbd/rtabmap_loop_samples/images)");
  sub_->add_option("--start", options_.start, "Start x,y in metres (default: chosen by --seed)");
  sub_->add_option("--goal", options_.goal, "Goal x,y in metres (default: chosen by --seed)");
  sub_->add_option("--duration-s", options_.duration_s,
                   "--world: the mapping run ends here if it has not returned to the start")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  sub_->add_option("--neck-sweep-rad", options_.neck_sweep_rad,
                   "--world: the neck pans +-this while the robot drives (at most pi/2)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.5707963267948966));
  sub_->add_option("--neck-period-s", options_.neck_period_s,
                   "--world: one sweep of the neck, there and back")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  sub_->add_option("--save-sequence", options_.save_sequence,
                   "--world: also write the mapping run as a TUM RGB-D sequence folder (rgb/, "
                   "depth/, groundtruth.txt, odometry.txt, neck.txt) for --sequence");
  sub_->add_option("--route-length-m", options_.route_length_m,
                   "Route length wanted when the goal is chosen (the thesis' route: 9.7 m)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
}

FusionCommand::Mode FusionCommand::mode() const {
  if (options_.pair) return Mode::kPair;
  if (options_.teach_and_repeat) return Mode::kTeachAndRepeat;
  if (options_.sequence) return Mode::kSequence;
  if (world_.file || sub_->get_option("--builtin")->count() > 0) return Mode::kWorld;
  return Mode::kNone;
}

int FusionCommand::run() const {
  switch (mode()) {
    case Mode::kPair:
      return run_pair();
    case Mode::kWorld:
      return run_mapping();
    case Mode::kTeachAndRepeat:
      return run_teach_and_repeat_table();
    case Mode::kSequence:
      return run_sequence();
    case Mode::kNone:
      break;
  }
  return report_error(
      usage_error("fusion: give --pair DIR, --sequence DIR, --world FILE or --teach-and-repeat "
                  "--world FILE"));
}

int FusionCommand::run_pair() const {
  const Result<fusion::FeatureType> type = fusion::parse_feature_type(options_.features);
  if (!type) return report_error(type.error());
  fusion::ImageNodeOptions node_options;
  node_options.feature_type = *type;
  const fusion::NodeMatcherOptions match_options;

  // Input first: a bad folder must leave nothing behind.
  const Result<RgbdPair> pair = read_rgbd_pair_folder(*options_.pair);
  if (!pair) return report_error(pair.error());

  const auto t0 = std::chrono::steady_clock::now();
  const fusion::NodeCreation prev = fusion::create_image_node(pair->prev, {}, node_options);
  const fusion::NodeCreation curr = fusion::create_image_node(pair->curr, {}, node_options);
  nlohmann::json pair_json = {{"folder", options_.pair->string()},
                              {"nodes", {{"prev", node_json(prev)}, {"curr", node_json(curr)}}}};
  bool accepted = false;
  std::string reason;
  std::string summary;
  if (!prev.ok() || !curr.ok()) {
    const bool prev_failed = !prev.ok();
    reason = std::string(prev_failed ? "previous" : "current") +
             " frame: " + std::string(fusion::to_string(prev_failed ? prev.check : curr.check));
    pair_json["accepted"] = false;
    pair_json["reason"] = reason;
    pair_json["reason_text"] = prev_failed ? prev.reason : curr.reason;
    pair_json["method"] = "none";
    pair_json["matches"] = 0;
    pair_json["inliers"] = 0;
    summary = pair_json["reason_text"].get<std::string>();
  } else {
    Rng rng(options_.seed);
    const fusion::MatchResult m = fusion::match_nodes(prev.node, curr.node, match_options, rng);
    accepted = m.accepted;
    reason = std::string(fusion::to_string(m.reason));
    pair_json["accepted"] = m.accepted;
    pair_json["reason"] = reason;
    pair_json["reason_text"] = m.reason_text;
    pair_json["method"] = std::string(fusion::to_string(m.method));
    pair_json["matches"] = m.matches;
    pair_json["matches_3d"] = m.matches_3d;
    pair_json["inliers"] = m.inliers;
    pair_json["inlier_ratio"] = m.inlier_ratio;
    pair_json["rmse_m"] = m.rmse_m;
    pair_json["median_reprojection_px"] = m.median_reprojection_px;
    pair_json["image_coverage"] = m.image_coverage;
    pair_json["spread_m"] = m.spread_m;
    pair_json["pnp_disagreement_m"] = m.pnp_disagreement_m;
    pair_json["pnp_disagreement_deg"] = rad_to_deg(m.pnp_disagreement_rad);
    pair_json["pnp_disagreement_chi2"] = m.pnp_disagreement_chi2;
    if (m.method != fusion::MatchMethod::kNone) {
      pair_json["T_prev_curr"] = transform_json(m.T_prev_curr);
    }
    summary = fmt::format("{} inliers of {} matches", m.inliers, m.matches);
    if (pair->has_ground_truth && m.accepted) {
      const Eigen::Isometry3d d = pair->T_prev_curr_truth().inverse() * m.T_prev_curr;
      pair_json["translation_error_m"] = d.translation().norm();
      pair_json["rotation_error_deg"] = rad_to_deg(Eigen::AngleAxisd(d.linear()).angle());
      summary += fmt::format("; error {:.4f} m, {:.3f} deg", d.translation().norm(),
                             rad_to_deg(Eigen::AngleAxisd(d.linear()).angle()));
    }
  }
  if (pair->has_ground_truth) {
    pair_json["ground_truth_T_prev_curr"] = transform_json(pair->T_prev_curr_truth());
  }
  const double wall_s = seconds_since(t0);

  nlohmann::json report = {
      {"options",
       {{"mode", "pair"},
        {"pair", options_.pair->string()},
        {"features", std::string(fusion::to_string(*type))},
        {"intrinsics",
         {{"fx_px", pair->prev.intrinsics.fx_px},
          {"fy_px", pair->prev.intrinsics.fy_px},
          {"cx_px", pair->prev.intrinsics.cx_px},
          {"cy_px", pair->prev.intrinsics.cy_px},
          {"source", pair->has_intrinsics_file ? "intrinsics.txt" : "TUM fr1 default"}}},
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
        {"pnp_fallback", match_options.pnp_fallback}}},
      {"pair", pair_json}};
  // One frame pair has no data clock: data_duration_s is null.
  report.update(core_report({"fusion", options_.seed, report["options"], wall_s, std::nullopt}));

  if (Status s = ensure_directory(options_.out); !s) return report_error(s.error());
  if (Status s = write_json_atomic(options_.out / "report.json", report); !s) {
    return report_error(s.error());
  }
  if (!options_.quiet) {
    fmt::print("fusion: pair {} ({}): {} ({}); {}\n", options_.pair->string(),
               fusion::to_string(*type), accepted ? "accepted" : "rejected", reason, summary);
    fmt::print("outputs: {}/report.json\n", options_.out.string());
  }
  return kExitOk;
}

// --- --world and --teach-and-repeat: simulated runs (mission/teach_and_repeat.hpp) -----------

namespace {

std::filesystem::path default_textures() {
  return data_dir() / "rgbd/rtabmap_loop_samples/images";
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
                        {"true_offset_m", s.true_offset_m}});
  }
  nlohmann::json row = {
      {"seed", r.seed},
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
      {"odometry_error_at_goal_m", r.odometry_error_at_goal_m},
      {"estimate_error_at_goal_m", r.estimate_error_at_goal_m},
      {"ate_corrected_m", r.ate_corrected_m},
      {"ate_odometry_m", r.ate_odometry_m},
      {"ate_ratio", r.ate_corrected_m > 0.0 ? r.ate_odometry_m / r.ate_corrected_m : 0.0},
      {"search_trials", r.search_trials},
      {"search_successes", r.search_successes},
      {"searches", searches},
      {"cells", r.cells},
      {"image_nodes", r.image_nodes},
      {"pose_nodes", r.pose_nodes},
      {"frames", r.slam.frames},
      {"simulated_s", r.duration_s}};
  row.update(statistics_json(r.slam));
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
/// the pose-graph nodes, when there is ground truth (robot poses, world frame).
nlohmann::json trajectory_json(const fusion::FusionSlam& slam,
                               const std::vector<StampedPose2>& truth) {
  const std::vector<StampedPose2> corrected = slam.corrected_trajectory();
  nlohmann::json trajectory = {{"poses", corrected.size()}};
  if (truth.empty()) return trajectory;
  const Result<AbsoluteTrajectoryError> ate_c = absolute_trajectory_error(corrected, truth);
  const Result<AbsoluteTrajectoryError> ate_o =
      absolute_trajectory_error(slam.odometry_trajectory(), truth);
  if (ate_c && ate_o) {
    trajectory["ate_rmse_m"] = ate_c->trans_m.rmse;
    trajectory["ate_odometry_rmse_m"] = ate_o->trans_m.rmse;
    trajectory["ate_ratio"] =
        ate_c->trans_m.rmse > 0.0 ? ate_o->trans_m.rmse / ate_c->trans_m.rmse : 0.0;
    trajectory["ate_pairs"] = ate_c->trans_m.count;
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

}  // namespace

// Everything a simulated run needs, read and checked before anything runs or is written.
struct FusionCommand::SimulatedSetup {
  fusion::FeatureType type;
  std::filesystem::path texture_folder;
  std::size_t textures_loaded = 0;
  std::size_t posters = 0;
  RgbdCamera camera;  // holds the world
  Pose2 start;
  Vec2 goal;
  TeachAndRepeatOptions options;
};

std::string FusionCommand::world_label() const {
  return world_.file ? world_.file->string() : "builtin:" + world_.builtin;
}

nlohmann::json FusionCommand::simulated_options_json(const SimulatedSetup& setup,
                                                     const std::string& mode) const {
  const TeachAndRepeatOptions& options = setup.options;
  return {{"mode", mode},
          {"features", std::string(fusion::to_string(setup.type))},
          {"runs", mode == "world" ? 1 : options_.runs},
          {"textures", setup.texture_folder.string()},
          {"textures_loaded", setup.textures_loaded},
          {"posters", setup.posters},
          {"cell_radius_m", options.slam.map.cell_radius_m},
          {"firing_field_radius_m", options.slam.map.firing_field_radius_m},
          {"capture_neck_angles_rad", options.capture_neck_angles_rad},
          {"odometry", "thesis_fusion_odometry (Table 5.4)"},
          {"route_length_m", options_.route_length_m}};
}

nlohmann::json FusionCommand::world_json(const World& world) const {
  const GridGeometry& g = world.geometry();
  return {{"file", world_label()},
          {"resolution_m", g.resolution_m()},
          {"free_cells", world.free_count()}};
}

Result<FusionCommand::SimulatedSetup> FusionCommand::load_simulated_setup() const {
  const Result<fusion::FeatureType> type = fusion::parse_feature_type(options_.features);
  if (!type) return type.error();
  Result<World> world = load_world(world_, 0.05);
  if (!world) return world.error();
  std::filesystem::path texture_folder = options_.textures.value_or(default_textures());
  const Result<std::vector<std::filesystem::path>> texture_files =
      list_texture_images(texture_folder);
  if (!texture_files) return texture_files.error();
  Result<std::vector<WallTexture>> textures = read_wall_textures(*texture_files);
  if (!textures) return textures.error();
  std::optional<Vec2> start_xy, goal_xy;
  if (options_.start) {
    const Result<Vec2> p = parse_point(*options_.start, "--start");
    if (!p) return p.error();
    start_xy = *p;
  }
  if (options_.goal) {
    const Result<Vec2> p = parse_point(*options_.goal, "--goal");
    if (!p) return p.error();
    goal_xy = *p;
  }
  if (start_xy.has_value() != goal_xy.has_value()) {
    return usage_error("fusion: give both --start and --goal, or neither");
  }

  TeachAndRepeatOptions options;
  options.slam.node.feature_type = *type;
  options.slam.seed = options_.seed;
  // The same world for every run: posters placed by --seed, start and goal fixed (the thesis
  // repeated one route); runs differ in their seed (odometry noise, depth noise, RANSAC).
  const std::vector<WallFace> faces = find_wall_faces(*world).faces;
  PosterPlacementOptions placement;
  placement.probability = 0.9;
  std::vector<Poster> posters = place_poster_layers(faces, *textures, placement, options_.seed, 3);
  const std::size_t poster_count = posters.size();
  Pose2 start;
  Vec2 goal;
  if (start_xy) {
    const Result<std::vector<Vec2>> route =
        plan_route(*world, *start_xy, *goal_xy, options.clearance_m);
    if (!route) return route.error();
    const Vec2 first = (*route)[1];
    start = {start_xy->x, start_xy->y, std::atan2(first.y - start_xy->y, first.x - start_xy->x)};
    goal = *goal_xy;
  } else {
    Rng rng(options_.seed);
    const Result<StartAndGoal> sg =
        choose_start_and_goal(*world, options.clearance_m, options_.route_length_m, rng);
    if (!sg) return sg.error();
    start = sg->start;
    goal = sg->goal_m;
  }
  Result<RgbdCamera> camera = RgbdCamera::create(std::move(*world), RgbdCameraOptions{},
                                                 std::move(*textures), std::move(posters));
  if (!camera) return camera.error();
  return SimulatedSetup{*type,
                        std::move(texture_folder),
                        texture_files->size(),
                        poster_count,
                        std::move(*camera),
                        start,
                        goal,
                        options};
}

int FusionCommand::run_teach_and_repeat_table() const {
  Result<SimulatedSetup> setup = load_simulated_setup();
  if (!setup) return report_error(setup.error());
  const World& world = setup->camera.world();
  const TeachAndRepeatOptions& options = setup->options;
  const fusion::FeatureType type = setup->type;

  const int runs = options_.runs;
  const auto t0 = std::chrono::steady_clock::now();
  ProgressLine progress(!options_.quiet && stderr_is_terminal());
  std::vector<TeachAndRepeatResult> results;
  for (int k = 0; k < runs; ++k) {
    const std::uint64_t seed = options_.seed + static_cast<std::uint64_t>(k);
    Result<TeachAndRepeatResult> r = run_teach_and_repeat(
        setup->camera, options, setup->start, setup->goal, seed, [&](const std::string& stage) {
          progress.show(fmt::format("fusion: run {}/{}: {}", k + 1, runs, stage));
        });
    if (!r) {
      progress.finish();
      return report_error(r.error());
    }
    results.push_back(std::move(*r));
  }
  progress.finish();
  const double wall_s = seconds_since(t0);

  // Pictures and trajectories, rendered in memory before anything is written.
  std::vector<std::pair<std::string, std::string>> files;  // name, bytes
  for (std::size_t k = 0; k < results.size(); ++k) {
    const std::string suffix = fmt::format("_run{}", k + 1);
    const HexMapPicture picture = picture_of(results[k], world);
    Result<std::string> svg = render_hex_map_svg(picture);
    if (!svg) return report_error(svg.error());
    files.emplace_back("hex_map" + suffix + ".svg", std::move(*svg));
    files.emplace_back("trajectory" + suffix + ".txt",
                       encode_tum_trajectory(results[k].run.corrected_trajectory));
  }

  nlohmann::json run_rows = nlohmann::json::array();
  int reached = 0, searches = 0, found = 0;
  double worst_error_m = 0.0, worst_ratio = 0.0, worst_ate_ratio = 1e300;
  for (const TeachAndRepeatResult& r : results) {
    run_rows.push_back(run_json(r.run));
    reached += r.run.reached_goal_cell ? 1 : 0;
    searches += r.run.search_trials;
    found += r.run.search_successes;
    worst_error_m = std::max(worst_error_m, r.run.final_error_m);
    worst_ratio = std::max(worst_ratio, r.run.path_ratio);
    worst_ate_ratio =
        std::min(worst_ate_ratio,
                 r.run.ate_corrected_m > 0.0 ? r.run.ate_odometry_m / r.run.ate_corrected_m : 0.0);
  }
  const nlohmann::json summary = {{"runs", runs},
                                  {"reached_goal_cell", reached},
                                  {"max_final_error_m", worst_error_m},
                                  {"max_path_ratio", worst_ratio},
                                  {"min_ate_ratio", worst_ate_ratio},
                                  {"search_trials", searches},
                                  {"search_successes", found}};
  nlohmann::json report = {
      {"options", simulated_options_json(*setup, "teach-and-repeat")},
      {"world", world_json(world)},
      {"trajectory",
       {{"poses", results.front().run.corrected_trajectory.size()},
        {"ate_rmse_m", results.front().run.ate_corrected_m},
        {"ate_odometry_rmse_m", results.front().run.ate_odometry_m}}}};
  report.update(core_report({"fusion", options_.seed, report["options"], wall_s, results.front().run.duration_s}));
  report["teach_and_repeat"] = {{"summary", summary}, {"runs", run_rows}};

  if (Status s = ensure_directory(options_.out); !s) return report_error(s.error());
  for (const auto& [name, bytes] : files) {
    if (Status s = write_file_atomic(options_.out / name, bytes); !s)
      return report_error(s.error());
  }
  for (std::size_t k = 0; k < results.size(); ++k) {
    if (Status s = write_hex_map_png(options_.out / fmt::format("hex_map_run{}.png", k + 1),
                                     picture_of(results[k], world));
        !s) {
      return report_error(s.error());
    }
  }
  if (Status s = write_json_atomic(options_.out / "report.json", report); !s) {
    return report_error(s.error());
  }
  if (!options_.quiet) {
    for (std::size_t k = 0; k < results.size(); ++k) {
      const TeachAndRepeatRun& r = results[k].run;
      fmt::print(
          "fusion: run {} ({}): goal cell {}, final error {:.3f} m, path ratio {:.2f}, ATE {:.3f} "
          "m "
          "(odometry {:.3f} m), node search {}/{}\n",
          k + 1, fusion::to_string(type), r.reached_goal_cell ? "reached" : "NOT reached",
          r.final_error_m, r.path_ratio, r.ate_corrected_m, r.ate_odometry_m, r.search_successes,
          r.search_trials);
    }
    std::string names;
    for (const auto& file : files) names += file.first + " ";
    for (std::size_t k = 0; k < results.size(); ++k)
      names += fmt::format("hex_map_run{}.png ", k + 1);
    fmt::print("outputs: {}/{}report.json\n", options_.out.string(), names);
  }
  return kExitOk;
}

// --world without --teach-and-repeat: one mapping run, recorded first and then fed to the online
// system exactly as a TUM sequence is (fusion/replay.hpp), so that the simulator and real data take
// the same path. The robot drives the teach stage's route start -> goal -> start (closing a loop)
// with its neck sweeping, and the result is scored against the run's ground truth.
int FusionCommand::run_mapping() const {
  Result<SimulatedSetup> setup = load_simulated_setup();
  if (!setup) return report_error(setup.error());
  // Said before the run rather than after it (write_tum_rgbd_sequence would refuse it too).
  if (options_.save_sequence && std::filesystem::exists(*options_.save_sequence) &&
      !std::filesystem::is_directory(*options_.save_sequence)) {
    return report_error(runtime_error(options_.save_sequence->string() +
                                      ": cannot write a sequence: a file is in the way"));
  }
  const World& world = setup->camera.world();
  const TeachAndRepeatOptions& options = setup->options;
  const Result<std::vector<Vec2>> route =
      plan_route(world, {setup->start.x, setup->start.y}, setup->goal, options.clearance_m);
  if (!route) return report_error(route.error());
  RgbdRunOptions run_options;
  run_options.start = setup->start;
  run_options.waypoints_m.assign(route->begin() + 1, route->end());
  run_options.waypoints_m.insert(run_options.waypoints_m.end(), route->rbegin() + 1, route->rend());
  // plan_route keeps clearance_m at the cells it strings together; a straight leg between them can
  // pass up to about half a world cell closer, which simulate_rgbd_run would refuse: 5 cm slack.
  run_options.tour.clearance_m = options.clearance_m - 0.05;
  run_options.max_speed_m_per_s = options.max_speed_m_per_s;
  run_options.max_turn_rate_rad_per_s = options.max_turn_rate_rad_per_s;
  run_options.neck_sweep_amplitude_rad = options_.neck_sweep_rad;
  run_options.neck_sweep_period_s = options_.neck_period_s;
  run_options.odometry = options.odometry;
  run_options.max_duration_s = options_.duration_s;
  const Result<SimulatedRgbdRun> run = simulate_rgbd_run(world, run_options, options_.seed);
  if (!run) return report_error(run.error());

  std::vector<fusion::ReplayStep> steps;
  std::vector<StampedPose2> truth;
  std::vector<Vec2> true_path;
  for (const RgbdRunFrame& f : run->frames) {
    steps.push_back({f.t_s, f.odometry, f.neck_pan_rad});
    truth.push_back({f.t_s, f.truth});
    true_path.push_back({f.truth.x, f.truth.y});
  }
  fusion::FusionSlam slam(options.slam);
  const auto t0 = std::chrono::steady_clock::now();
  ProgressLine progress(!options_.quiet && stderr_is_terminal());
  const Result<fusion::ReplayResult> replayed = fusion::replay(
      slam, steps,
      [&](std::size_t i) -> Result<RgbdFrame> {
        return render_rgbd_run_frame(setup->camera, *run, i);
      },
      [&](std::size_t done, std::size_t total) {
        if (done % 25 == 0) progress.show(fmt::format("fusion: frame {}/{}", done, total));
      });
  progress.finish();
  if (!replayed) return report_error(replayed.error());
  const double wall_s = seconds_since(t0);

  HexMapPicture picture = picture_of_slam(slam, &world);
  picture.taught_path_m = replayed->path_m;
  picture.true_path_m = true_path;
  Result<std::string> svg = render_hex_map_svg(picture);
  if (!svg) return report_error(svg.error());
  nlohmann::json report = {{"options", simulated_options_json(*setup, "world")},
                           {"world", world_json(world)},
                           {"run",
                            {{"start", pose_json(setup->start)},
                             {"goal_m", {setup->goal.x, setup->goal.y}},
                             {"route", "start -> goal -> start"},
                             {"neck_sweep_amplitude_rad", options_.neck_sweep_rad},
                             {"neck_sweep_period_s", options_.neck_period_s},
                             {"path_length_m", run->path_length_m},
                             {"completed", run->completed}}},
                           {"fusion", slam_json(slam, steps.size(), replayed->frames_loaded)},
                           {"trajectory", trajectory_json(slam, truth)}};
  report.update(core_report({"fusion", options_.seed, report["options"], wall_s, run->duration_s}));

  // The sequence first: it is the largest output and the likeliest to fail (a full disk, a file
  // in the way); it is written to a temporary folder and renamed, so a failure leaves nothing.
  if (options_.save_sequence) {
    progress.show(fmt::format("fusion: writing {} frames to {}", run->frames.size(),
                              options_.save_sequence->string()));
    const Status saved = write_simulated_rgbd_run(*options_.save_sequence, setup->camera, *run);
    progress.finish();
    if (!saved) return report_error(saved.error());
  }
  if (Status s = write_slam_outputs(options_.out, *svg, picture, slam, truth, report); !s) {
    return report_error(s.error());
  }
  if (!options_.quiet)
    print_slam_summary("world " + world_label(), setup->type, slam, report["trajectory"],
                       options_.out, !truth.empty());
  return kExitOk;
}

int FusionCommand::run_sequence() const {
  const Result<fusion::FeatureType> type = fusion::parse_feature_type(options_.features);
  if (!type) return report_error(type.error());
  const Result<TumRgbdSequence> sequence = TumRgbdSequence::open(*options_.sequence);
  if (!sequence) return report_error(sequence.error());
  // The hex-cell map grows with the robot's odometry (thesis 4.3.2); a sequence without it has no
  // robot motion to map with.
  std::vector<fusion::ReplayStep> steps;
  std::vector<std::size_t> entry_of_step;
  std::vector<StampedPose2> truth;
  for (std::size_t i = 0; i < sequence->size(); ++i) {
    const TumRgbdEntry& e = sequence->entry(i);
    if (!e.has_odometry) continue;
    const double neck = e.has_neck ? e.neck_pan_rad : 0.0;
    steps.push_back({e.t_s, e.odometry, neck});
    entry_of_step.push_back(i);
    if (e.has_truth) {
      truth.push_back({e.t_s, robot_pose_from_optical_frame(e.T_world_camera, neck)});
    }
  }
  if (steps.empty()) {
    return report_error(input_error(
        (*options_.sequence / "odometry.txt").string() +
        ": no such file or no stamp within 0.02 s of a frame (the fusion SLAM maps along the "
        "robot's wheel odometry)"));
  }

  fusion::FusionSlamOptions options;
  options.node.feature_type = *type;
  options.seed = options_.seed;
  fusion::FusionSlam slam(options);
  const auto t0 = std::chrono::steady_clock::now();
  ProgressLine progress(!options_.quiet && stderr_is_terminal());
  const Result<fusion::ReplayResult> replayed = fusion::replay(
      slam, steps, [&](std::size_t step) { return sequence->load(entry_of_step[step]); },
      [&](std::size_t done, std::size_t total) {
        if (done % 25 == 0) progress.show(fmt::format("fusion: frame {}/{}", done, total));
      });
  progress.finish();
  if (!replayed) return report_error(replayed.error());
  const double wall_s = seconds_since(t0);

  HexMapPicture picture = picture_of_slam(slam, nullptr);
  picture.taught_path_m = replayed->path_m;
  Result<std::string> svg = render_hex_map_svg(picture);
  if (!svg) return report_error(svg.error());
  const double duration_s =
      sequence->size() > 1 ? sequence->entries().back().t_s - sequence->entries().front().t_s : 0.0;
  nlohmann::json fusion_block = slam_json(slam, sequence->size(), replayed->frames_loaded);
  fusion_block["frames_with_odometry"] = steps.size();
  nlohmann::json report = {{"options",
                                  {{"mode", "sequence"},
                                   {"sequence", options_.sequence->string()},
                                   {"features", std::string(fusion::to_string(*type))},
                                   {"cell_radius_m", options.map.cell_radius_m},
                                   {"firing_field_radius_m", options.map.firing_field_radius_m}}},
                                 {"fusion", fusion_block},
                                 {"trajectory", trajectory_json(slam, truth)}};
  report.update(core_report({"fusion", options_.seed, report["options"], wall_s, duration_s}));

  if (Status s = write_slam_outputs(options_.out, *svg, picture, slam, truth, report); !s) {
    return report_error(s.error());
  }
  if (!options_.quiet) {
    print_slam_summary("sequence " + options_.sequence->string(), *type, slam, report["trajectory"],
                       options_.out, !truth.empty());
  }
  return kExitOk;
}

}  // namespace tessera::cli
