// tessera sim: the simulator node (nodes/sim_node.hpp) in a process of its own, on Cyclone DDS.
#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <thread>

#include "commands.hpp"
#include "dds_options.hpp"
#include "tessera/core/rng.hpp"
#include "tessera/nodes/sim_node.hpp"
#include "tessera/sim/tour.hpp"

namespace tessera::cli {
namespace {

// One random start per robot with room around it, at least a metre from the others.
Result<std::vector<Pose2>> random_starts(const World& world, int robots, double clearance_m,
                                         std::uint64_t seed) {
  Rng rng = Rng(seed).fork(1000);
  std::vector<Pose2> starts;
  for (int attempt = 0; static_cast<int>(starts.size()) < robots; ++attempt) {
    if (attempt > 1000 * robots) {
      return input_error("no room for " + std::to_string(robots) +
                         " robots a metre apart in the world");
    }
    Result<Pose2> p = random_start_pose(world, clearance_m, rng);
    if (!p.ok()) return p.error();
    const bool apart = std::all_of(starts.begin(), starts.end(), [&](const Pose2& q) {
      return std::hypot(q.x - p->x, q.y - p->y) >= 1.0;
    });
    if (apart) starts.push_back(*p);
  }
  return starts;
}

}  // namespace

SimCommand::SimCommand(CLI::App& app) {
  sub_ = app.add_subcommand(
      "sim",
      "Run the simulator as a ROS 2 node on Cyclone DDS: robots r1..rN with a lidar and drifting "
      "odometry publish /rN/scan, /rN/odom, /tf, /tf_static, /clock and /sim/rN/ground_truth "
      "and obey /rN/cmd_vel, until --duration-s of simulated time or Ctrl-C.");
  add_world_options(*sub_, world_);
  sub_->add_option("--resolution-m", resolution_m_, "Cell size the built-in worlds are drawn at")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  sub_->add_option("--robots", robots_, "Robots")->check(CLI::Range(1, 64))->capture_default_str();
  sub_->add_option("--start", starts_,
                   "Start of each robot, X,Y[,THETA] in metres and radians, once per robot "
                   "(default: random places with room, a metre apart, drawn from --seed)");
  sub_->add_option("--seed", seed_, "Seed for the starts and every noise draw")
      ->capture_default_str();
  sub_->add_option("--rate", rate_,
                   "Simulated seconds per wall-clock second (0: as fast as the machine goes)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  sub_->add_option("--duration-s", duration_s_, "Simulated time to run (0: until stopped)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  add_dds_options(*sub_, domain_, network_);
  sub_->add_flag("--quiet", quiet_, "No summary line");
}

int SimCommand::run() const {
  Result<World> world = load_world(world_, resolution_m_);
  if (!world.ok()) return report_error(world.error());
  nodes::SimNodeOptions options;
  if (!starts_.empty()) {
    if (static_cast<int>(starts_.size()) != robots_) {
      return report_error(usage_error("--start: given " + std::to_string(starts_.size()) +
                                      " times for " + std::to_string(robots_) + " robots"));
    }
    for (const std::string& text : starts_) {
      Result<Pose2> start = parse_pose(text, "--start");
      if (!start.ok()) return report_error(start.error());
      options.starts.push_back(*start);
    }
  } else {
    Result<std::vector<Pose2>> starts =
        random_starts(*world, robots_, 2.0 * options.robot_radius_m, seed_);
    if (!starts.ok()) return report_error(starts.error());
    options.starts = std::move(*starts);
  }
  Result<std::unique_ptr<net::Transport>> transport = open_dds(domain_, network_);
  if (!transport.ok()) return report_error(transport.error());
  Result<std::unique_ptr<nodes::SimNode>> sim =
      nodes::SimNode::create(*world, options, seed_, **transport);
  if (!sim.ok()) return report_error(sim.error());

  const StopSignals stop;
  ProgressLine progress(!quiet_ && stderr_is_terminal());
  const auto t0 = std::chrono::steady_clock::now();
  const double step_s = options.physics_step_s;
  std::int64_t steps = 0;
  while (!StopSignals::requested() && (duration_s_ <= 0.0 || (*sim)->time_s() < duration_s_)) {
    if (Status s = (*sim)->step(); !s.ok()) return report_error(s.error());
    ++steps;
    if (rate_ > 0.0) {
      std::this_thread::sleep_until(
          t0 + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                   std::chrono::duration<double>(static_cast<double>(steps) * step_s / rate_)));
    }
    if (steps % 100 == 0) {
      progress.show(fmt::format("sim: {:.1f} s simulated, {:.1f}x real time", (*sim)->time_s(),
                                (*sim)->time_s() / std::max(seconds_since(t0), 1e-9)));
    }
  }
  progress.finish();
  if (!quiet_) {
    std::uint64_t stalls = 0;
    for (int i = 0; i < (*sim)->robot_count(); ++i) stalls += (*sim)->stalls(i);
    const double wall_s = seconds_since(t0);
    fmt::print(
        "sim: {} robots, {:.1f} s simulated in {:.1f} s ({:.1f}x real time), {} wall "
        "stalls, {} bad commands dropped\n",
        (*sim)->robot_count(), (*sim)->time_s(), wall_s, (*sim)->time_s() / std::max(wall_s, 1e-9),
        stalls, (*sim)->dropped_commands());
  }
  return kExitOk;
}

}  // namespace tessera::cli
