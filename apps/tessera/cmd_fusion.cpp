// tessera fusion: the thesis' Fusion SLAM on RGB-D data (issue 5). --pair DIR estimates one frame
// pair's motion (fusion/node_matcher.hpp) or says why it refuses, into report.json under "pair".
// --world FILE maps a simulated run (start -> goal -> start) with the online system
// (fusion/fusion_slam.hpp, fed by fusion/replay.hpp) and scores it against the run's ground truth;
// --teach-and-repeat --world FILE [--runs N] runs the thesis' two-stage experiment (Table 5.1,
// mission/teach_and_repeat.hpp), with the hex-map pictures, TUM trajectories and the per-run table
// in report.json; --sequence DIR feeds a TUM RGB-D folder to the online system along its
// odometry.txt, the same way as --world feeds the simulated run. Thin glue:
// read every input first, so that bad input writes nothing; run the library; write the outputs;
// print one summary line per run. --world and --teach-and-repeat are in cmd_fusion_world.cpp,
// --sequence in cmd_fusion_sequence.cpp, the report blocks in fusion_report.cpp.
#include <fmt/format.h>

#include <chrono>
#include <nlohmann/json.hpp>
#include <optional>

#include "commands.hpp"
#include "fusion_report.hpp"
#include "recording.hpp"
#include "tessera/core/rng.hpp"
#include "tessera/fusion/feature_type.hpp"
#include "tessera/fusion/frame_pair_match.hpp"
#include "tessera/io/atomic_file.hpp"
#include "tessera/io/json_file.hpp"
#include "tessera/io/rgbd_pair_folder.hpp"
#include "tessera/report/core_report.hpp"

namespace tessera::cli {

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
  sub_->add_option("--pair-method", options_.pair_method,
                   "--pair: auto (features, then the depth images alone when the colour images "
                   "hold too few features), features, or depth-icp")
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
                   "$TESSERA_DATA_DIR or ../shared/data, then rgbd/rtabmap_loop_samples/images)");
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
  add_output_stream_options(*sub_, options_.streams);
  sub_->add_option("--obstacles", options_.obstacles,
                   "--teach-and-repeat: put this many boxes on the taught route before the "
                   "repeat; the robot gets a P3DX body, sonars and bumpers (thesis chapter 5)")
      ->capture_default_str()
      ->check(CLI::Range(0, 20));
  sub_->add_option("--drop-frames", options_.drop_frames,
                   "--teach-and-repeat: lose each frame the SLAM asks for with this probability")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 0.95));
  sub_->add_option("--navigation", options_.navigation,
                   "--teach-and-repeat: ours (cell polyline, pure pursuit) or thesis (re-decide "
                   "the best neighbour at every cell border)")
      ->capture_default_str()
      ->check(CLI::IsMember({"ours", "thesis"}));
  sub_->add_option("--avoidance", options_.avoidance,
                   "--obstacles: strip (ours: only what lies ahead in the robot's width), thesis "
                   "(everything within 1 m at up to 90 degrees) or off")
      ->capture_default_str()
      ->check(CLI::IsMember({"strip", "thesis", "off"}));
  sub_->add_option("--candidates", options_.candidates,
                   "--world, --teach-and-repeat: match a new image node against the nodes of its "
                   "own and neighbouring cells (cells, the thesis) or against nodes drawn at "
                   "random from the whole map (whole-map, as an RGB-D SLAM without cells)")
      ->capture_default_str()
      ->check(CLI::IsMember({"cells", "whole-map"}));
  sub_->add_option("--match-gate", options_.match_gate,
                   "--world, --teach-and-repeat: refuse a match that disagrees with the pose graph "
                   "by over 1 m or 0.5 rad (on, ours) or keep every match (off, the thesis)")
      ->capture_default_str()
      ->check(CLI::IsMember({"on", "off"}));
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
  if ((options_.streams.record || options_.streams.serve_port) && mode() == Mode::kPair) {
    return report_error(
        usage_error("--record and --serve take a run (--world, "
                    "--teach-and-repeat, --sequence), not a --pair"));
  }
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
  const Result<fusion::PairMethod> method = fusion::parse_pair_method(options_.pair_method);
  if (!method) return report_error(method.error());
  fusion::FramePairOptions pair_options;
  pair_options.method = *method;
  pair_options.node.feature_type = *type;

  // Input first: a bad folder must leave nothing behind.
  const Result<RgbdPair> pair = read_rgbd_pair_folder(*options_.pair);
  if (!pair) return report_error(pair.error());

  const auto t0 = std::chrono::steady_clock::now();
  Rng rng(options_.seed);
  const fusion::FramePairMatch match =
      fusion::match_frame_pair(pair->prev, pair->curr, pair_options, rng);
  const PairReport outcome = pair_report(*options_.pair, *pair, match);
  const double wall_s = seconds_since(t0);

  nlohmann::json report = {{"options", pair_options_json(*options_.pair, *pair, pair_options)},
                           {"pair", outcome.pair}};
  // One frame pair has no data clock: data_duration_s is null.
  report.update(core_report({"fusion", options_.seed, report["options"], wall_s, std::nullopt}));

  if (Status s = ensure_directory(options_.out); !s) return report_error(s.error());
  if (Status s = write_json_atomic(options_.out / "report.json", report); !s) {
    return report_error(s.error());
  }
  if (!options_.quiet) {
    fmt::print("fusion: pair {} ({}): {} ({}); {}\n", options_.pair->string(),
               fusion::to_string(*type), outcome.accepted ? "accepted" : "rejected", outcome.reason,
               outcome.summary);
    fmt::print("outputs: {}/report.json\n", options_.out.string());
  }
  return kExitOk;
}

}  // namespace tessera::cli
