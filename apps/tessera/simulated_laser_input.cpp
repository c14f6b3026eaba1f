// The simulated run's options on the command line (simulated_laser_input.hpp).
#include "simulated_laser_input.hpp"

#include "cli_support.hpp"

namespace tessera::cli {

void SimulatedLaserInput::add_options(CLI::App& command) {
  command.add_option("--seed", seed, "Simulated run: seed of the start, odometry and range noise")
      ->capture_default_str();
  command
      .add_option("--duration-s", duration_s,
                  "Simulated run: stop the covering tour after this many seconds (0: no limit)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  command.add_option("--scan-rate-hz", scan_rate_hz, "Simulated run: scans per second")
      ->check(CLI::Range(0.1, 1000.0))
      ->capture_default_str();
  command
      .add_option("--lidar-sweep-s", lidar_sweep_s,
                  "Simulated run: seconds the lidar takes to sweep one scan, beam by beam while "
                  "the robot moves (a 5 Hz spinning lidar: 0.2; at most one scan period); 0: all "
                  "beams at once")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  command.add_option("--start", start,
                     "Simulated run: start position X,Y in metres (default: random)");
}

Result<LaserRunOptions> SimulatedLaserInput::options() const {
  LaserRunOptions o;
  o.max_duration_s = duration_s;
  o.scan_rate_hz = scan_rate_hz;
  o.lidar_sweep_s = lidar_sweep_s;
  if (lidar_sweep_s > 1.0 / scan_rate_hz) {
    return usage_error("--lidar-sweep-s must be at most one scan period (1 / --scan-rate-hz)");
  }
  if (start) {
    Result<Vec2> p = parse_point(*start, "--start");
    if (!p) return p.error();
    o.start = Pose2{p->x, p->y, 0.0};
  }
  return o;
}

Result<SimulatedLaserRun> SimulatedLaserInput::simulate(const World& world,
                                                        const LaserRunOptions& options) const {
  Result<SimulatedLaserRun> run = simulate_laser_run(world, options, seed);
  if (!run && !world.name().empty()) {
    Error e = run.error();
    e.message = world.name() + ": " + e.message;
    return e;
  }
  return run;
}

}  // namespace tessera::cli
