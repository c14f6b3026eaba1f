#pragma once
// Where a simulated BOBMapping run (mission/bob_mission.hpp) gets its decisions from: the
// freestanding bob::Explorer in this process, or the same explorer running as firmware on a
// microcontroller (an emulated Cortex-M4 across a serial link, io/bob_firmware_link.hpp). The
// simulator owns the world, the body and the sensors; the port owns the robot's map. It lives in
// sim beside the sensing it carries (bob_sensing.hpp), so that the mission and the serial link in
// io both reach it without io depending on mission.
#include <cstdint>
#include <vector>

#include "tessera/bob/explorer.hpp"
#include "tessera/core/cell.hpp"
#include "tessera/core/result.hpp"
#include "tessera/sim/bob_sensing.hpp"

namespace tessera {

/// What the explorer holds when it stops.
struct BobExplorerSummary {
  bob::StopReason stop_reason = bob::StopReason::kNone;
  std::uint32_t moves = 0;             // bob::Explorer::moves()
  std::uint32_t turns = 0;             // bob::Explorer::turns()
  std::uint32_t resensed = 0;          // bob::Explorer::resensed()
  std::uint32_t ignored_readings = 0;  // bob::Explorer::ignored_readings()
  std::vector<std::uint8_t> packed_map;  // bob::PackedMap layout (4 bits a cell)
  std::vector<std::uint8_t> final_map;   // bob::FinalMap layout (1 bit a cell)
};

/// The explorer's side of a run, in the order run_bob calls it: begin(), report() the readings at
/// the start pose, start(); if that is refused, begin() again with the next start cell; then
/// { next_move(); report() what the step saw, or blocked() } until next_move() is kFinished;
/// then summary(). Errors are the link's (kRuntime); the explorer's own answers are bob::Status.
class BobExplorerPort {
 public:
  virtual ~BobExplorerPort() = default;
  /// A fresh explorer (bob::Explorer::init) on a width x height grid.
  [[nodiscard]] virtual Result<bob::Status> begin(const bob::ExplorerOptions& options, int width,
                                                  int height) = 0;
  /// One step's readings: bob::Explorer::report_target for each seen target cell,
  /// report_detection for each other detection (cells outside the grid are ignored).
  [[nodiscard]] virtual Result<bob::Status> report(const StepSensing& step) = 0;
  /// bob::Explorer::start(cell, North).
  [[nodiscard]] virtual Result<bob::Status> start(Cell cell) = 0;
  [[nodiscard]] virtual Result<bob::Status> next_move(bob::Direction& move) = 0;
  [[nodiscard]] virtual Result<bob::Status> blocked() = 0;
  /// After next_move() returned kFinished.
  [[nodiscard]] virtual Result<BobExplorerSummary> summary() = 0;
  /// The maps as they stand after the last report() or blocked() (the firmware streams them after
  /// every step, as the paper's robot fed its monitor, Figure 5a); counters may be 0 until the end.
  [[nodiscard]] virtual Result<BobExplorerSummary> snapshot() = 0;
};

}  // namespace tessera
