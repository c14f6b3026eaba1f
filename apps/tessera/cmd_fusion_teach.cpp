// tessera fusion --teach-and-repeat --world FILE [--runs N]: the thesis' two-stage experiment
// (Table 5.1, mission/teach_and_repeat.hpp) run N times in the world cmd_fusion_world.cpp sets up;
// hex-map pictures, TUM trajectories and the per-run table in report.json. Thin glue.
#include <fmt/format.h>

#include <chrono>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "tessera/report/core_report.hpp"
#include "fusion_report.hpp"
#include "fusion_simulated_setup.hpp"
#include "tessera/io/atomic_file.hpp"
#include "tessera/io/json_file.hpp"
#include "tessera/io/tum_trajectory.hpp"
#include "tessera/mission/teach_and_repeat.hpp"
#include "tessera/record/fusion_recording.hpp"
#include "tessera/record/ros_conversions.hpp"

namespace tessera::cli {

int FusionCommand::run_teach_and_repeat_table() const {
  Result<SimulatedSetup> setup = load_simulated_setup();
  if (!setup) return report_error(setup.error());
  const World& world = setup->camera.world();
  const TeachAndRepeatOptions& options = setup->options;
  const fusion::FeatureType type = setup->type;

  const int runs = options_.runs;
  Result<Recording> recording = Recording::open(options_.streams, "fusion");
  if (!recording) return report_error(recording.error());
  std::int64_t recorded_until_ns = 0;  // runs are recorded one after another
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
    // Each run is recorded (and shown live) as soon as it ends.
    if (MessageSink* sink = recording->sink(); sink && !recording->failed()) {
      recording->note(record_teach_and_repeat(*sink, *r, recorded_until_ns));
      recorded_until_ns += to_ns(r->run.duration_s) + 1'000'000'000;
    }
    recording->step_done();
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
  std::vector<TeachAndRepeatRun> runs_done;
  for (const TeachAndRepeatResult& r : results) {
    run_rows.push_back(run_json(r.run));
    runs_done.push_back(r.run);
  }
  const nlohmann::json summary = summary_json(summarize(runs_done));
  nlohmann::json report = {
      {"options", simulated_options_json(*setup, "teach-and-repeat")},
      {"world", world_json(world)},
      {"trajectory",
       {{"poses", results.front().run.corrected_trajectory.size()},
        {"ate_rmse_m", results.front().run.ate_corrected_m},
        {"ate_odometry_rmse_m", results.front().run.ate_odometry_m}}}};
  report.update(core_report(
      {"fusion", options_.seed, report["options"], wall_s, results.front().run.duration_s}));
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
  if (Status s = recording->finish(); !s) return report_error(s.error());
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
    if (options_.streams.record) fmt::print("recording: {}\n", options_.streams.record->string());
  }
  recording->linger(!options_.quiet);
  return kExitOk;
}

}  // namespace tessera::cli
