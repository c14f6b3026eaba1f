#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "commands.hpp"
#include "recording.hpp"
#include "tessera/io/atomic_file.hpp"
#include "tessera/report/exploration_report.hpp"
#include "tessera/io/json_file.hpp"
#include "tessera/io/map_yaml.hpp"
#include "tessera/io/tum_trajectory.hpp"
#include "tessera/mission/exploration_mission.hpp"
#include "tessera/record/exploration_recorder.hpp"
#include "tessera/render/render.hpp"

namespace tessera::cli {

ExploreCommand::ExploreCommand(CLI::App& app) {
  sub_ = app.add_subcommand(
      "explore",
      "Simulate robots exploring a world with the frontier algorithm (lecture Algo 9.1); writes "
      "map.yaml + map.pgm, map.png, trajectory.txt and report.json to --out.");
  add_world_options(*sub_, world_);
  sub_->add_option("--strategy", strategy_, "Frontier choice: nearest (Algo 9.1) or priority (a/d)")
      ->check(CLI::IsMember({"nearest", "priority"}))
      ->capture_default_str();
  sub_->add_option("--robots", robots_, "Robots sharing one map")
      ->check(CLI::Range(1, 64))
      ->capture_default_str();
  sub_->add_option("--sensor", sensor_, "cells (the lecture's 8-neighbour robot) or lidar")
      ->check(CLI::IsMember({"cells", "lidar"}))
      ->capture_default_str();
  sub_->add_option("--seed", seed_, "Seed for every random draw")->capture_default_str();
  sub_->add_option("--out", out_, "Output folder")->capture_default_str();
  sub_->add_option("--resolution-m", resolution_m_,
                   "Exploration grid cell size; a finer world is resampled to it (0: keep the "
                   "world's own)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  sub_->add_option("--start", start_,
                   "Start of the first robot, X,Y in metres (default: the free "
                   "cell nearest the centre of the largest free area)");
  sub_->add_option("--lidar-range-m", lidar_range_m_, "Lidar maximum range")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  sub_->add_option("--lidar-beams", lidar_beams_, "Lidar beams over 360 degrees")
      ->check(CLI::Range(1, 100000))
      ->capture_default_str();
  sub_->add_option("--range-noise-m", range_noise_m_, "Lidar range noise standard deviation")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  sub_->add_option("--low", low_, "Frontier cells have occupancy probability below this")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  sub_->add_option("--max-steps", max_steps_, "Stop after this many steps (0: no limit)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  add_output_stream_options(*sub_, streams_);
  add_ros_options();
  sub_->add_flag("--quiet", quiet_, "No progress line and no summary");
}

int ExploreCommand::run() const {
  if (ros_) return run_ros();
  Result<World> loaded = load_world(world_, resolution_m_ > 0.0 ? resolution_m_ : 0.1);
  if (!loaded) return report_error(loaded.error());
  World world = std::move(loaded).value();
  if (resolution_m_ > world.geometry().resolution_m() * (1.0 + 1e-9)) {
    world = world.resampled(resolution_m_);
  }

  ExplorationMissionOptions options;
  options.strategy =
      strategy_ == "priority" ? FrontierStrategy::kPriority : FrontierStrategy::kNearest;
  options.robots = robots_;
  options.sensor = sensor_ == "lidar" ? RobotKind::kLidar : RobotKind::kCell;
  options.lidar.max_range_m = lidar_range_m_;
  options.lidar.beams = lidar_beams_;
  options.lidar.range_noise_stddev_m = range_noise_m_;
  options.low = low_;
  options.seed = seed_;
  options.max_steps = max_steps_;
  if (start_) {
    Result<Vec2> p = parse_point(*start_, "--start");
    if (!p) return report_error(p.error());
    options.start = world.geometry().cell_at_unchecked(*p);
  }
  if (auto problem = validate(options)) return report_error(usage_error(*problem));

  Result<Recording> recording = Recording::open(streams_, "explore");
  if (!recording) return report_error(recording.error());
  std::optional<ExplorationRecorder> recorder;
  if (MessageSink* sink = recording->sink()) recorder.emplace(*sink);

  ProgressLine progress(!quiet_ && stderr_is_terminal());
  const auto t0 = std::chrono::steady_clock::now();
  Result<ExplorationResult> result = run_exploration(
      world, options,
      [&](const ExplorationProgress& p) {
        progress.show(fmt::format("explore: step {}  coverage {:.1f}%  frontier {} cells", p.step,
                                  100.0 * p.coverage, p.frontier_size));
      },
      [&](const ExplorationMission& mission) {
        if (recorder && !recording->failed()) recording->note(recorder->step(mission));
        recording->step_done();
      });
  progress.finish();
  const double wall_s = seconds_since(t0);
  if (!result) {
    // Name the world in input errors ("maps/lab.yaml: start (3, 4) is inside an obstacle").
    Error e = result.error();
    if (e.kind == ErrorKind::kInput) e.message = world.name() + ": " + e.message;
    return report_error(e);
  }
  const ExplorationResult& r = *result;

  if (Status s = ensure_directory(out_); !s) return report_error(s.error());
  if (Status s = write_map_yaml(r.map, out_ / "map.yaml", MapSaveOptions{}); !s) {
    return report_error(s.error());
  }
  RenderLayers layers;
  layers.map = &r.map;
  layers.truth = &world;
  layers.frontier = r.frontier_left;
  for (const auto& path : r.paths) {
    std::vector<Vec2> points;
    points.reserve(path.size());
    for (const Pose2& p : path) points.push_back(p.translation());
    if (!points.empty()) layers.robots_m.push_back(points.back());
    layers.paths_m.push_back(std::move(points));
  }
  if (Status s = write_png(out_ / "map.png", layers); !s) return report_error(s.error());
  // One pose per step, stamped at one step per second (the simulator has no clock of its own).
  for (std::size_t robot = 0; robot < r.paths.size(); ++robot) {
    std::vector<StampedPose2> poses;
    for (std::size_t k = 0; k < r.paths[robot].size(); ++k) {
      poses.push_back({static_cast<double>(k), r.paths[robot][k]});
    }
    const std::string name =
        robot == 0 ? "trajectory.txt" : fmt::format("trajectory_robot{}.txt", robot + 1);
    if (Status s = write_tum_trajectory(out_ / name, poses); !s) return report_error(s.error());
  }

  ExplorationReportContext context;
  context.seed = seed_;
  context.world_file = world_.file ? world_.file->string() : "builtin:" + world_.builtin;
  context.options = {{"strategy", strategy_},
                     {"robots", robots_},
                     {"sensor", sensor_},
                     {"resolution_m", world.geometry().resolution_m()},
                     {"low", low_},
                     {"lidar_range_m", lidar_range_m_},
                     {"lidar_beams", lidar_beams_},
                     {"range_noise_m", range_noise_m_},
                     {"max_steps", max_steps_}};
  context.wall_s = wall_s;
  if (Status s = write_json_atomic(out_ / "report.json", exploration_report(r, world, context));
      !s) {
    return report_error(s.error());
  }

  if (Status s = recording->finish(); !s) return report_error(s.error());

  if (!quiet_) {
    const auto& m = r.metrics;
    fmt::print(
        "explore: {} robot(s), {} steps, coverage {:.2f}%, path {:.1f} m, {} turns, "
        "occupied-as-empty {} ({})\n",
        m.robots, m.steps, 100.0 * m.coverage, m.path_length_m, m.turns,
        r.accuracy.occupied_as_empty, m.stop_reason);
    fmt::print("outputs: {}/map.yaml map.pgm map.png trajectory.txt report.json\n", out_.string());
    if (streams_.record) fmt::print("recording: {}\n", streams_.record->string());
  }
  recording->linger(!quiet_);
  return kExitOk;
}

}  // namespace tessera::cli
