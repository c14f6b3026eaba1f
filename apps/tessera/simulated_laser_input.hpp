#pragma once
// A simulated laser run on the command line (`slam` without --log or --bag): a robot with a lidar
// drives a covering tour of the world (sim/laser_run.hpp), seeded, for so long, from a start, with
// a lidar that takes its scans at once or sweeps them beam by beam.
#include <CLI/CLI.hpp>
#include <cstdint>
#include <optional>
#include <string>

#include "tessera/core/result.hpp"
#include "tessera/sim/laser_run.hpp"
#include "tessera/sim/world.hpp"

namespace tessera::cli {

struct SimulatedLaserInput {
  std::uint64_t seed = 1;
  double duration_s = 300.0;
  double scan_rate_hz = 10.0;
  double lidar_sweep_s = 0.0;
  std::optional<std::string> start;  // "X,Y" in metres

  void add_options(CLI::App& command);
  /// The run's options. Usage error for a sweep longer than a scan period or a bad --start.
  [[nodiscard]] Result<LaserRunOptions> options() const;
  /// Drives the run in `world`; errors name the world.
  [[nodiscard]] Result<SimulatedLaserRun> simulate(const World& world,
                                                   const LaserRunOptions& options) const;
};

}  // namespace tessera::cli
