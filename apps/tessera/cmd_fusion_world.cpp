// tessera fusion --world and --teach-and-repeat (cmd_fusion.cpp has the options): the simulated
// world's set-up (mission/teach_and_repeat_setup.hpp) and the fusion mapping run, recorded by
// sim/rgbd_run.hpp and fed to the online system by fusion/replay.hpp. Thin glue.
#include <fmt/format.h>

#include <chrono>
#include <nlohmann/json.hpp>
#include <optional>

#include "commands.hpp"
#include "fusion_report.hpp"
#include "fusion_simulated_setup.hpp"
#include "recording.hpp"
#include "tessera/fusion/replay.hpp"
#include "tessera/io/data_dir.hpp"
#include "tessera/io/tum_rgbd_sequence.hpp"
#include "tessera/mission/teach_and_repeat_setup.hpp"
#include "tessera/record/fusion_recording.hpp"
#include "tessera/render/simulated_rgbd_sequence.hpp"
#include "tessera/render/wall_textures.hpp"
#include "tessera/report/core_report.hpp"
#include "tessera/sim/rgbd_run.hpp"

namespace tessera::cli {

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
          {"route_length_m", options_.route_length_m},
          {"navigation", options_.navigation},
          {"drop_frames", options_.drop_frames},
          {"obstacles", options_.obstacles},
          {"avoidance", options_.obstacles > 0 ? options_.avoidance : "none"},
          {"candidates", options_.candidates},
          {"match_gate", options_.match_gate}};
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
  std::filesystem::path texture_folder =
      options_.textures.value_or(data_dir() / "rgbd/rtabmap_loop_samples/images");
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
  TeachAndRepeatOptions options;
  options.slam.node.feature_type = *type;
  options.slam.seed = options_.seed;
  if (options_.navigation == "thesis") options.navigation = RepeatNavigation::kThesisGreedy;
  options.frame_drop_probability = options_.drop_frames;
  if (options_.candidates == "whole-map") {
    options.slam.candidate_search = fusion::CandidateSearch::kWholeMap;
  }
  options.slam.match_gate = options_.match_gate == "on";
  if (options_.obstacles > 0) {
    ObstacleCourseOptions course;
    course.obstacles = options_.obstacles;
    course.avoid = options_.avoidance != "off";
    if (options_.avoidance == "thesis") {  // as written: every echo within range counts
      course.avoidance = ReactiveAvoidanceOptions{};
      course.only_new_obstacles = false;
    }
    options.obstacle_course = course;
  }
  Result<TeachAndRepeatScenario> scenario =
      set_up_teach_and_repeat(*world, *textures, start_xy, goal_xy, options.clearance_m,
                              options_.route_length_m, options_.seed);
  if (!scenario) return scenario.error();
  const std::size_t poster_count = scenario->posters.size();
  Result<RgbdCamera> camera = RgbdCamera::create(
      std::move(*world), RgbdCameraOptions{}, std::move(*textures), std::move(scenario->posters));
  if (!camera) return camera.error();
  return SimulatedSetup{*type,
                        std::move(texture_folder),
                        texture_files->size(),
                        poster_count,
                        std::move(*camera),
                        scenario->start,
                        scenario->goal_m,
                        options};
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
  Result<std::vector<Vec2>> waypoints = there_and_back_waypoints(
      world, {setup->start.x, setup->start.y}, setup->goal, options.clearance_m);
  if (!waypoints) return report_error(waypoints.error());
  RgbdRunOptions run_options;
  run_options.start = setup->start;
  run_options.waypoints_m = std::move(*waypoints);
  run_options.tour.clearance_m = options.clearance_m;
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
  Result<Recording> recording = Recording::open(options_.streams, "fusion");
  if (!recording) return report_error(recording.error());
  ProgressLine progress(!options_.quiet && stderr_is_terminal());
  const Result<fusion::ReplayResult> replayed = fusion::replay(
      slam, steps,
      [&](std::size_t i) -> Result<RgbdFrame> {
        return render_rgbd_run_frame(setup->camera, *run, i);
      },
      [&](std::size_t done, std::size_t total) {
        if (done % 25 == 0) {
          progress.show(fmt::format("fusion: frame {}/{}", done, total),
                        static_cast<std::int64_t>(done), static_cast<std::int64_t>(total),
                        "frames");
        }
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
  if (MessageSink* sink = recording->sink()) recording->note(record_fusion_run(*sink, slam, truth));
  if (Status s = recording->finish(); !s) return report_error(s.error());
  if (!options_.quiet) {
    print_slam_summary("world " + world_label(), setup->type, slam, report["trajectory"],
                       options_.out, !truth.empty());
    if (options_.streams.record) fmt::print("recording: {}\n", options_.streams.record->string());
  }
  recording->linger(!options_.quiet);
  return kExitOk;
}

}  // namespace tessera::cli
