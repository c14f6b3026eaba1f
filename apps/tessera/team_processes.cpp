// The processes of tessera team (team_processes.hpp).
#include "team_processes.hpp"

#include <fmt/format.h>

#include "tessera/nodes/sim_node.hpp"

namespace tessera::cli {
namespace {

std::string pose_text(const Pose2& p) {
  return fmt::format("{:.4f},{:.4f},{:.4f}", p.x, p.y, p.theta);
}

}  // namespace

std::vector<std::string> TeamLaunch::robot_args(int i, const std::filesystem::path& out) const {
  std::vector<std::string> args = robot;
  args.insert(args.end(), {"--ns", nodes::robot_name(i), "--out", out.string()});
  return args;
}

TeamLaunch team_launch(const TeamLaunchOptions& o, const std::vector<Pose2>& starts) {
  TeamLaunch l;
  l.sim = {"sim",
           "--robots",
           std::to_string(starts.size()),
           "--seed",
           std::to_string(o.seed),
           "--rate",
           fmt::format("{}", o.rate),
           "--resolution-m",
           fmt::format("{}", o.resolution_m),
           "--quiet"};
  l.robot = {"explore", "--ros", "--quiet"};
  for (const Pose2& s : starts) {
    l.sim.insert(l.sim.end(), {"--start", pose_text(s)});
    if (!o.starts_unknown) l.robot.insert(l.robot.end(), {"--team-start", pose_text(s)});
  }
  if (o.starts_unknown) l.robot.insert(l.robot.end(), {"--team", std::to_string(starts.size())});
  for (std::vector<std::string>* args : {&l.sim, &l.robot}) {
    args->insert(args->end(), {"--domain", std::to_string(o.domain)});
    if (o.network) args->push_back("--network");
  }
  if (o.world.file) {
    l.sim.insert(l.sim.end(), {"--world", o.world.file->string()});
  } else {
    l.sim.insert(l.sim.end(), {"--builtin", o.world.builtin});
  }
  if (o.world.map_resolution_m) {
    l.sim.insert(l.sim.end(), {"--map-resolution-m", fmt::format("{}", *o.world.map_resolution_m)});
  }
  if (o.world.crop) l.sim.insert(l.sim.end(), {"--crop", *o.world.crop});
  return l;
}

bool team_finished(const std::map<std::string, nodes::TeamObserverRobot>& robots,
                   const std::vector<RobotEvents>& events) {
  std::size_t i = 0;
  for (const auto& [name, r] : robots) {
    const RobotEvents& ev = events[i++];
    const bool dead = (ev.killed_at_s && !ev.restarted_at_s) || ev.exited_at_s;
    if (dead) continue;
    const bool spoke_since_restart =
        !ev.restarted_at_s ||
        (r.status && 1e-9 * static_cast<double>(r.status->header.stamp_ns) >= *ev.restarted_at_s);
    if (!r.status || !spoke_since_restart || r.status->state != RobotStatusMessage::kFinished) {
      return false;
    }
  }
  return true;
}

}  // namespace tessera::cli
