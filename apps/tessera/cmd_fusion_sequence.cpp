// tessera fusion --sequence DIR: a TUM RGB-D folder fed to the online Fusion SLAM along its
// odometry.txt (fusion/replay.hpp), scored against its groundtruth.txt when there is one. Thin
// glue.
#include <fmt/format.h>

#include <chrono>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "recording.hpp"
#include "tessera/record/fusion_recording.hpp"
#include "tessera/report/core_report.hpp"
#include "fusion_report.hpp"
#include "tessera/fusion/replay.hpp"
#include "tessera/io/tum_rgbd_sequence.hpp"

namespace tessera::cli {

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
  Result<Recording> recording = Recording::open(options_.streams, "fusion");
  if (!recording) return report_error(recording.error());
  ProgressLine progress(!options_.quiet && stderr_is_terminal());
  const Result<fusion::ReplayResult> replayed = fusion::replay(
      slam, steps, [&](std::size_t step) { return sequence->load(entry_of_step[step]); },
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
  if (MessageSink* sink = recording->sink()) recording->note(record_fusion_run(*sink, slam, truth));
  if (Status s = recording->finish(); !s) return report_error(s.error());
  if (!options_.quiet) {
    print_slam_summary("sequence " + options_.sequence->string(), *type, slam, report["trajectory"],
                       options_.out, !truth.empty());
    if (options_.streams.record) fmt::print("recording: {}\n", options_.streams.record->string());
  }
  recording->linger(!options_.quiet);
  return kExitOk;
}

}  // namespace tessera::cli
