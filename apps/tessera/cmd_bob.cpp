#include <fmt/format.h>

#include <array>
#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bob_emulator.hpp"
#include "bob_step_outputs.hpp"
#include "commands.hpp"
#include "recording.hpp"
#include "tessera/io/atomic_file.hpp"
#include "tessera/io/bob_firmware_link.hpp"
#include "tessera/io/bob_map_file.hpp"
#include "tessera/report/bob_monitor.hpp"
#include "tessera/report/bob_report.hpp"
#include "tessera/io/image_file.hpp"
#include "tessera/io/json_file.hpp"
#include "tessera/eval/bob_table.hpp"
#include "tessera/mission/bob_mission.hpp"

namespace tessera::cli {
namespace {

// Built-in worlds are drawn at this resolution, finer than the robot's cells, so that their
// obstacles straddle cell boundaries as real ones do.
constexpr double kBuiltinResolutionM = 0.05;

}  // namespace

BobCommand::BobCommand(CLI::App& app) {
  sub_ = app.add_subcommand(
      "bob",
      "Simulate the BOBMapping robot (one cell per move, five IR sensors, wheel encoders and "
      "ceiling beacons) on a world; writes monitor.png, map.bob and report.json to --out.");
  add_world_options(*sub_, world_);
  sub_->add_option("--cell", cell_m_,
                   "Side of the robot's cells in metres, laid over the world from its origin")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  sub_->add_option("--variant", variant_,
                   "trail (the paper's backtracking) or map-aware (shortest known path)")
      ->check(CLI::IsMember({"trail", "map-aware"}))
      ->capture_default_str();
  sub_->add_option("--noise", noise_, "Noise of the IR sensors, encoders and beacons: on or off")
      ->check(CLI::IsMember({"on", "off"}))
      ->capture_default_str();
  sub_->add_option("--resense", resense_,
                   "BOBMapping 3.4 re-sensing: on (a later reading changes a sensed cell) or off "
                   "(the first reading of a cell stays)")
      ->check(CLI::IsMember({"on", "off"}))
      ->capture_default_str();
  sub_->add_option("--localisation", localisation_,
                   "beacons (encoders between ultrasonic fixes, BOBMapping 3.3) or perfect "
                   "(exact motion, the true pose known)")
      ->check(CLI::IsMember({"beacons", "perfect"}))
      ->capture_default_str();
  sub_->add_option("--seed", seed_, "Seed for every random draw")->capture_default_str();
  sub_->add_option("--start", start_,
                   "Start X,Y in metres: the robot starts in the cell holding it, facing North, "
                   "whose cell must be free. Default: in the largest free area, the first cell "
                   "with a free cell North of it");
  sub_->add_option("--firmware", firmware_,
                   "Run the explorer as this firmware image (firmware/bob, make bob-firmware) on "
                   "an emulated Cortex-M4 (QEMU mps2-an386) fed by this simulator over its serial "
                   "port; the run fails unless its final map and route are the host build's")
      ->check(CLI::ExistingFile);
  sub_->add_option("--qemu", qemu_, "QEMU for --firmware")->capture_default_str();
  sub_->add_option("--firmware-timeout", firmware_timeout_s_,
                   "Seconds --firmware waits for any one answer of the firmware")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  sub_->add_option("--monitor-dir", monitor_dir_,
                   "Write the monitor picture (map and route so far) after every step as "
                   "step_NNNNN.png in this folder");
  sub_->add_option("--out", out_, "Output folder")->capture_default_str();
  add_output_stream_options(*sub_, streams_);
  sub_->add_flag("--quiet", quiet_, "No summary");
}

int BobCommand::run() const {
  const auto t0 = std::chrono::steady_clock::now();
  Result<World> loaded = load_world(world_, kBuiltinResolutionM);
  if (!loaded) return report_error(loaded.error());
  const World cropped = std::move(loaded).value();
  const std::string world_name = world_.file ? world_.file->string() : "builtin:" + world_.builtin;
  // With --crop the grid covers the rectangle and the sensors see the whole floor plan around it
  // (BobMissionOptions::grid_rect_m): an open configuration has no wall on the grid's edge.
  World whole;
  if (world_.crop) {
    WorldSource uncropped = world_;
    uncropped.crop.reset();
    Result<World> w = load_world(uncropped, kBuiltinResolutionM);
    if (!w) return report_error(w.error());
    whole = std::move(w).value();
  }
  const World& world = world_.crop ? whole : cropped;

  BobMissionOptions options;
  options.variant = variant_ == "map-aware" ? BobVariant::kMapAware : BobVariant::kTrail;
  options.noise = noise_ == "on";
  options.resense = resense_ == "on";
  options.seed = seed_;
  options.cell_m = cell_m_;
  options.perfect_localisation = localisation_ == "perfect";
  if (world_.crop) {
    const GridGeometry& c = cropped.geometry();
    options.grid_rect_m = std::array<Vec2, 2>{
        c.origin(), c.origin() + Vec2{c.width() * c.resolution_m(), c.height() * c.resolution_m()}};
  }
  // The robot's grid and its ground truth, made once for the run(s) and the scoring.
  Result<World> grid_truth = bob_grid_truth(world, options);
  if (!grid_truth) return report_error(grid_truth.error());
  const World& truth = *grid_truth;
  if (start_) {
    Result<Vec2> p = parse_point(*start_, "--start");
    if (!p) return report_error(p.error());
    options.start = truth.geometry().cell_at_unchecked(*p);
  }

  // --monitor-dir: a picture of the robot's map and route after every step (BOBMapping Figure 5a's
  // monitor), and --record: the same as ROS 2 messages; from the firmware's run with --firmware.
  Result<Recording> recording = Recording::open(streams_, "bob");
  if (!recording) return report_error(recording.error());
  BobStepOutputs step_outputs(monitor_dir_, recording->sink(), truth.geometry());
  if (Status s = step_outputs.prepare(); !s) return report_error(s.error());
  options.on_step = recording->paced(step_outputs.on_step());
  // --firmware: the explorer runs as firmware on the emulated board; the host build's own run of
  // the same world and seed must give the same final map, byte for byte.
  std::optional<Result<BobResult>> firmware_result;
  Emulator emulator;
  if (firmware_) {
    Result<std::unique_ptr<BobFirmwareLink>> link =
        BobFirmwareLink::listen(std::chrono::milliseconds(
            static_cast<long long>(std::lround(firmware_timeout_s_ * 1000.0))));
    if (!link) return report_error(link.error());
    if (Result<bool> up = emulator.start(qemu_, firmware_->string(), (*link)->port()); !up) {
      return report_error(up.error());
    }
    if (Result<bool> ok = (*link)->accept(); !ok) {
      return report_error(runtime_error(qemu_ + " -M mps2-an386 -kernel " + firmware_->string() +
                                        ": " + ok.error().message));
    }
    const bob::ExplorerOptions fw = (*link)->firmware_options();
    const bool fw_map_aware = fw.backtrack == bob::Backtrack::kShortestKnownPath;
    if (fw_map_aware != (options.variant == BobVariant::kMapAware) ||
        fw.resense != options.resense) {
      return report_error(usage_error(
          firmware_->string() + ": the firmware runs the " + (fw_map_aware ? "map-aware" : "trail") +
          " variant with re-sensing " + (fw.resense ? "on" : "off") + "; pass the same --variant "
          "and --resense"));
    }
    firmware_result = run_bob(world, truth, options, **link);
    emulator.stop();
    if (!*firmware_result) return report_error(firmware_result->error());
    options.on_step = nullptr;  // the monitor shows the firmware's run
  }
  const std::unique_ptr<BobExplorerPort> host_explorer = local_bob_explorer();
  Result<BobResult> result = run_bob(world, truth, options, *host_explorer);
  if (!step_outputs.status()) return report_error(step_outputs.status().error());
  if (!result) {
    Error e = result.error();
    if (e.kind == ErrorKind::kInput) e.message = world_name + ": " + e.message;
    return report_error(e);
  }
  if (firmware_result) {
    const BobResult& f = **firmware_result;
    if (f.final_map != result->final_map || f.route != result->route) {
      return report_error(runtime_error(
          "the firmware's run differs from the host's: final map " +
          std::string(f.final_map == result->final_map ? "identical" : "different") + ", route " +
          (f.route == result->route ? "identical" : "different") + " (" +
          std::to_string(f.route.size()) + " vs " + std::to_string(result->route.size()) +
          " cells)"));
    }
  }
  const BobResult& r = firmware_result ? **firmware_result : *result;
  const BobTableRow row = score_bob_table(
      {r.sensed, r.occupied, r.route, r.moves, r.turns, r.resensed, r.ignored_readings},
      TruthGrid(world.geometry(), world.solid_cells()),
      TruthGrid(truth.geometry(), truth.solid_cells()), options.boundary_tolerance_m);

  BobMapFile map_file;
  map_file.width = r.width;
  map_file.height = r.height;
  map_file.cell_mm = static_cast<int>(std::lround(cell_m_ * 1000.0));
  map_file.rows = r.final_map;
  Result<std::string> map_bytes = encode_bob_map(map_file);
  if (!map_bytes) return report_error(runtime_error(map_bytes.error().message));
  Result<std::string> png = encode_png(render_bob_monitor(r));
  if (!png) return report_error(png.error());

  BobReportContext context;
  context.run = {"bob",
                 seed_,
                 {{"cell_m", cell_m_},
                  {"variant", variant_},
                  {"noise", noise_},
                  {"resense", resense_},
                  {"start", {r.start.x, r.start.y}},
                  {"localisation", localisation_}},
                 seconds_since(t0),
                 std::nullopt};
  context.world_file = world_name;
  context.world_resolution_m = world.geometry().resolution_m();
  context.variant = variant_;
  nlohmann::json report = bob_report(r, row, context);
  if (firmware_) {
    report["firmware"] = {{"elf", firmware_->string()},
                          {"board", "mps2-an386 (QEMU)"},
                          {"final_map_identical_to_host", true},
                          {"route_identical_to_host", true}};
  }
  const std::string json = encode_json(report);

  if (Status s = ensure_directory(out_); !s) return report_error(s.error());
  const std::array<PendingFile, 3> files{
      {{out_ / "monitor.png", *png}, {out_ / "map.bob", *map_bytes}, {out_ / "report.json", json}}};
  if (Status s = write_files_atomic(files); !s) return report_error(s.error());
  if (Status s = step_outputs.finish(r); !s) return report_error(s.error());
  if (Status s = recording->finish(); !s) return report_error(s.error());

  if (!quiet_) {
    const BobTableRow& t = row;
    fmt::print(
        "bob: {} x {} cells, {} ({}), path {} cells, {} turns, re-sensed {}, "
        "empty-as-occupied {}, occupied-as-empty {}, success {:.2f}%\n",
        r.width, r.height, variant_, stop_reason_name(r.stop_reason), t.path_cells, t.turns,
        t.resensed, t.empty_as_occupied, t.occupied_as_empty, 100.0 * t.success_rate);
    const BobLocalisationStats& l = r.localisation;
    fmt::print("localisation: {}, {} fixes, {} repositionings, {} bumps, worst error {:.3f} m\n",
               localisation_, l.fixes, l.repositionings, l.bumps, l.max_position_error_m);
    if (firmware_) {
      fmt::print("firmware: {} on mps2-an386, final map and route identical to the host's\n",
                 firmware_->string());
    }
    fmt::print("outputs: {}/monitor.png map.bob report.json\n", out_.string());
    if (streams_.record) fmt::print("recording: {}\n", streams_.record->string());
  }
  recording->linger(!quiet_);
  return kExitOk;
}

}  // namespace tessera::cli
