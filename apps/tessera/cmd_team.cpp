// tessera team: a team of exploring robots as separate processes over Cyclone DDS. It starts
// `tessera explore --ros` per robot and `tessera sim` for their world, watches the robots' maps
// (nodes/team_observer.hpp) until every robot still alive has finished, optionally kills one on
// purpose (and restarts it), then stops them all and writes team_report.hpp's outputs.
#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include "child_process.hpp"
#include "commands.hpp"
#include "dds_options.hpp"
#include "team_processes.hpp"
#include "team_report.hpp"
#include "tessera/nodes/explorer_node.hpp"
#include "tessera/nodes/sim_node.hpp"
#include "tessera/report/core_report.hpp"
#include "tessera/sim/team_starts.hpp"

namespace tessera::cli {
TeamCommand::TeamCommand(CLI::App& app) {
  sub_ = app.add_subcommand(
      "team",
      "Explore a world with a team of robots, each a process of its own (tessera explore --ros) "
      "localised by its own SLAM, with the simulator as another (tessera sim), all over Cyclone "
      "DDS; writes the merged map, each robot's trajectories and report.json to --out.");
  add_world_options(*sub_, world_);
  sub_->add_option("--resolution-m", resolution_m_, "Cell size the built-in worlds are drawn at")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  sub_->add_option("--robots", robots_, "Robots")->check(CLI::Range(1, 16))->capture_default_str();
  sub_->add_option("--seed", seed_, "Seed of the simulator's noise")->capture_default_str();
  sub_->add_option("--rate", rate_, "Simulated seconds per wall-clock second")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  sub_->add_option("--max-s", max_s_, "Give up after this much simulated time")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  sub_->add_option("--kill-robot", kill_robot_, "Kill robot K's process (1 = r1) during the run")
      ->check(CLI::Range(1, 16));
  sub_->add_option("--at-coverage", kill_at_coverage_,
                   "--kill-robot: when the team's coverage reaches this share (0-1)")
      ->check(CLI::Range(0.0, 1.0));
  sub_->add_option("--at-s", kill_at_s_, "--kill-robot: at this simulated time")
      ->check(CLI::NonNegativeNumber);
  sub_->add_option("--restart-after-s", restart_after_s_,
                   "--kill-robot: start the killed robot again this much simulated time later")
      ->check(CLI::PositiveNumber);
  sub_->add_flag("--unknown-starts", unknown_starts_,
                 "Do not tell the robots where they start: they find each other by map matching");
  sub_->add_option("--out", out_, "Output folder")->capture_default_str();
  add_dds_options(*sub_, domain_, network_);
  sub_->add_flag("--quiet", quiet_, "No progress line and no summary");
}

int TeamCommand::run() const {
  if (kill_robot_ && !kill_at_coverage_ && !kill_at_s_) {
    return report_error(usage_error("--kill-robot needs --at-coverage or --at-s"));
  }
  if (kill_robot_ && *kill_robot_ > robots_) {
    return report_error(
        usage_error("--kill-robot: there is no robot " + std::to_string(*kill_robot_)));
  }
  Result<World> world = load_world(world_, resolution_m_);
  if (!world.ok()) return report_error(world.error());
  const nodes::SimNodeOptions sim_defaults;
  const nodes::ExplorerNodeOptions robot_defaults;
  const double map_cell_m = robot_defaults.slam.slam.map_resolution_m;
  Result<std::vector<Pose2>> starts =
      team_starts(*world, robots_, 2.0 * sim_defaults.robot_radius_m, 0.6, map_cell_m);
  if (!starts.ok()) return report_error(starts.error());
  std::error_code ec;
  std::filesystem::create_directories(out_ / "logs", ec);
  if (ec) return report_error(runtime_error("cannot create " + (out_ / "logs").string()));

  std::vector<nodes::TeamMember> team;
  for (int i = 0; i < robots_; ++i) {
    team.push_back({nodes::robot_name(i), (*starts)[static_cast<std::size_t>(i)]});
  }
  const TeamLaunch launch = team_launch(
      {world_, resolution_m_, seed_, rate_, domain_, network_, unknown_starts_}, *starts);

  Result<std::unique_ptr<net::Transport>> transport = open_dds(domain_, network_);
  if (!transport.ok()) return report_error(transport.error());
  Result<std::unique_ptr<nodes::TeamObserver>> observer =
      nodes::TeamObserver::create(team, map_cell_m, **transport);
  if (!observer.ok()) return report_error(observer.error());
  const auto start_robot = [&](int i) -> Result<ChildProcess> {
    const std::string name = nodes::robot_name(i);
    return ChildProcess::start(launch.robot_args(i, out_ / name), out_ / "logs" / (name + ".log"));
  };
  const StopSignals stop;
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<ChildProcess> robots;
  for (int i = 0; i < robots_; ++i) {
    Result<ChildProcess> p = start_robot(i);
    if (!p.ok()) return report_error(p.error());
    robots.push_back(std::move(*p));
  }
  // The simulator starts once every robot is listening: robots that are still starting would
  // let simulated time pass unexplored.
  const auto all_joined = [&] {
    for (const auto& [name, r] : (*observer)->robots()) {
      if (!r.status) return false;
    }
    return true;
  };
  while (!all_joined() && seconds_since(t0) < 60.0 && !StopSignals::requested()) {
    (*transport)->wait(0.05);
    (*observer)->spin_once();
  }
  if (!all_joined()) return report_error(runtime_error("robots did not start within 60 s"));
  Result<ChildProcess> sim = ChildProcess::start(launch.sim, out_ / "logs" / "sim.log");
  if (!sim.ok()) return report_error(sim.error());

  TeamRunRecord run;
  run.world = &*world;
  run.starts = *starts;
  run.events.resize(static_cast<std::size_t>(robots_));
  const Cell start_cell = *world->geometry().cell_at({(*starts)[0].x, (*starts)[0].y});
  const std::vector<std::uint8_t> reachable = world->reachable_from(start_cell);
  ProgressLine progress(!quiet_ && stderr_is_terminal());
  auto last_sample = t0;
  const int victim = kill_robot_ ? *kill_robot_ - 1 : -1;  // -1: none
  while (!StopSignals::requested()) {
    (*transport)->wait(0.05);
    (*observer)->spin_once();
    const double t = (*observer)->sim_time_s();
    if (!sim->running()) {
      run.end = "the simulator ended";
      break;
    }
    if (seconds_since(last_sample) >= 0.5 && (*observer)->take_map_update()) {
      last_sample = std::chrono::steady_clock::now();
      run.coverage.push_back(team_coverage(**observer, *world, reachable, t));
    }
    const double covered = run.coverage.empty() ? 0.0 : run.coverage.back().known;
    if (victim >= 0) {
      RobotEvents& ev = run.events[static_cast<std::size_t>(victim)];
      if (!ev.killed_at_s && ((kill_at_s_ && t >= *kill_at_s_) ||
                              (kill_at_coverage_ && covered >= *kill_at_coverage_))) {
        robots[static_cast<std::size_t>(victim)].kill();
        ev.killed_at_s = t;
      } else if (ev.killed_at_s && !ev.restarted_at_s && restart_after_s_ &&
                 t >= *ev.killed_at_s + *restart_after_s_) {
        Result<ChildProcess> p = start_robot(victim);
        if (!p.ok()) return report_error(p.error());
        robots[static_cast<std::size_t>(victim)] = std::move(*p);
        ev.restarted_at_s = t;
      }
    }
    // A robot process that ended by itself (a crash) is dead from then on, as a killed one.
    for (std::size_t k = 0; k < robots.size(); ++k) {
      RobotEvents& ev = run.events[k];
      if (!ev.killed_at_s && !ev.exited_at_s && !robots[k].running()) ev.exited_at_s = t;
    }
    const bool finished = t > 0.0 && team_finished((*observer)->robots(), run.events) &&
                          !(victim >= 0 && restart_after_s_ &&
                            !run.events[static_cast<std::size_t>(victim)].restarted_at_s);
    if (finished) {
      run.end = "every robot finished";
      break;
    }
    if (t >= max_s_) {
      run.end = "time limit";
      break;
    }
    progress.show(fmt::format("team: {:.0f} s simulated, coverage {:.1f} %", t, 100.0 * covered));
  }
  if (run.end.empty()) run.end = "stopped";
  progress.finish();
  run.sim_s = (*observer)->sim_time_s();
  for (ChildProcess& r : robots) r.stop(30.0);
  sim->stop(10.0);
  // The robots' last maps and statuses (published as they shut down) are in by now.
  for (int k = 0; k < 10; ++k) {
    (*transport)->wait(0.05);
    (*observer)->spin_once();
  }
  run.coverage.push_back(team_coverage(**observer, *world, reachable, run.sim_s));
  run.wall_s = seconds_since(t0);
  for (int i = 0; i < robots_; ++i) {
    // A robot killed and not restarted wrote none; one that did wrote it whole (atomically).
    std::ifstream in(out_ / nodes::robot_name(i) / "report.json");
    nlohmann::json r = nlohmann::json::parse(in, nullptr, false);
    run.robot_reports.push_back(r.is_discarded() ? nlohmann::json(nullptr) : r);
  }
  nlohmann::json options = {{"world", world_.file ? world_.file->string() : world_.builtin},
                            {"robots", robots_},
                            {"rate", rate_},
                            {"max_s", max_s_},
                            {"resolution_m", resolution_m_},
                            {"domain", domain_},
                            {"unknown_starts", unknown_starts_}};
  if (victim >= 0) {
    options["kill_robot"] = *kill_robot_;
    options["at_coverage"] =
        kill_at_coverage_ ? nlohmann::json(*kill_at_coverage_) : nlohmann::json(nullptr);
    options["at_s"] = kill_at_s_ ? nlohmann::json(*kill_at_s_) : nlohmann::json(nullptr);
    options["restart_after_s"] =
        restart_after_s_ ? nlohmann::json(*restart_after_s_) : nlohmann::json(nullptr);
  }
  nlohmann::json report = core_report({"team", seed_, options, run.wall_s, run.sim_s});
  if (Status s = write_team_outputs(out_, **observer, run, report); !s) {
    return report_error(s.error());
  }
  if (run.end == "the simulator ended") {
    return report_error(runtime_error("the simulator ended before the team finished: see " +
                                      (out_ / "logs" / "sim.log").string()));
  }
  if (!quiet_) {
    const CoverageSample& c = run.coverage.back();
    fmt::print(
        "team: {} robots, {}, {:.1f} s simulated in {:.1f} s; the merged map knows {:.2f} % of the "
        "reachable free space ({:.2f} % shown free)\n",
        robots_, run.end, run.sim_s, run.wall_s, 100.0 * c.known, 100.0 * c.free);
    fmt::print("outputs: {}/map.yaml map.pgm map.png rN_truth.txt rN_slam.txt report.json\n",
               out_.string());
  }
  return kExitOk;
}

}  // namespace tessera::cli
