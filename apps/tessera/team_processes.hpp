#pragma once
// The processes of `tessera team`: the command lines of the simulator and of each robot, and when
// the team has finished.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "team_report.hpp"
#include "tessera/core/pose2.hpp"
#include "tessera/nodes/team_observer.hpp"

namespace tessera::cli {

struct TeamLaunchOptions {
  WorldSource world;
  double resolution_m = 0.05;  // the built-in worlds' cells
  std::uint64_t seed = 1;
  double rate = 1.0;
  std::uint32_t domain = 0;
  bool network = false;
  bool starts_unknown = false;  // the robots are not told where they start (--team N)
};

/// Arguments (without the program) of `tessera sim` and of each `tessera explore --ros`.
struct TeamLaunch {
  std::vector<std::string> sim;
  std::vector<std::string> robot;  // without --ns and --out
  /// Robot i's arguments, its outputs in `out`.
  [[nodiscard]] std::vector<std::string> robot_args(int i, const std::filesystem::path& out) const;
};

/// One robot per start, robot i named nodes::robot_name(i).
[[nodiscard]] TeamLaunch team_launch(const TeamLaunchOptions& o, const std::vector<Pose2>& starts);

/// True when every robot that is alive has said it finished: a robot killed (and not restarted)
/// or that ended by itself does not count, one restarted counts once it has spoken since.
/// `events` is in the order of `robots` (by name: r1, r2, ...).
[[nodiscard]] bool team_finished(const std::map<std::string, nodes::TeamObserverRobot>& robots,
                                 const std::vector<RobotEvents>& events);

}  // namespace tessera::cli
