// tessera team's outputs (team_report.hpp).
#include "team_report.hpp"

#include <fmt/format.h>

#include "slam_report.hpp"
#include "tessera/core/angle.hpp"
#include "tessera/eval/coverage.hpp"
#include "tessera/eval/map_accuracy.hpp"
#include "tessera/eval/trajectory_error.hpp"
#include "tessera/eval/truth_grid.hpp"
#include "tessera/io/json_file.hpp"
#include "tessera/io/map_yaml.hpp"
#include "tessera/io/tum_trajectory.hpp"
#include "tessera/nodes/sim_node.hpp"
#include "tessera/render/render.hpp"

namespace tessera::cli {
namespace {

std::optional<double> first_time_at(const std::vector<CoverageSample>& series, double share,
                                    bool known) {
  for (const CoverageSample& s : series) {
    if ((known ? s.known : s.free) >= share) return s.t_s;
  }
  return std::nullopt;
}

nlohmann::json or_null(const std::optional<double>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

// Position error of the SLAM poses against the truth at the same stamps (no alignment: the team
// frame is the world frame, the starts being known).
nlohmann::json slam_error_json(const nodes::TeamObserverRobot& r) {
  std::vector<double> truth_s, slam_s;
  for (const StampedPose2& p : r.truth) truth_s.push_back(p.t_s);
  for (const StampedPose2& p : r.slam) slam_s.push_back(p.t_s);
  std::vector<double> errors;
  for (const StampMatch& m : associate_stamps(truth_s, slam_s, 0.011)) {
    const Pose2& a = r.truth[m.reference].pose;
    const Pose2& b = r.slam[m.estimate].pose;
    errors.push_back(std::hypot(a.x - b.x, a.y - b.y));
  }
  if (errors.empty()) return nullptr;
  const ErrorStatistics s = error_statistics(errors);
  return {{"poses", s.count}, {"rmse_m", s.rmse}, {"max_m", s.max}};
}

// What a robot sent on the team's map topics (its own map and its merged map) and on the claims,
// per simulated second of the run, and its scan-to-map latency, from its own report.
// Unknown starts: where robot `i` placed its teammates (its report), each with the error against
// where the truth puts the teammate's start in the robot's own start frame.
nlohmann::json placements_json(const nlohmann::json& robot_report, const TeamRunRecord& run,
                               std::size_t i) {
  nlohmann::json out = nlohmann::json::array();
  if (robot_report.is_null() || !robot_report.contains("explorer")) return out;
  for (const nlohmann::json& p : robot_report["explorer"].value("placements", nlohmann::json())) {
    nlohmann::json j = p;
    const std::string robot = p.value("robot", "");
    for (std::size_t k = 0; k < run.starts.size(); ++k) {
      if (nodes::robot_name(static_cast<int>(k)) != robot) continue;
      const Pose2 truth = run.starts[i].inverse() * run.starts[k];
      j["error_m"] = std::hypot(p.value("x_m", 0.0) - truth.x, p.value("y_m", 0.0) - truth.y);
      j["error_rad"] = std::abs(normalize_angle(p.value("theta_rad", 0.0) - truth.theta));
    }
    out.push_back(j);
  }
  return out;
}

nlohmann::json traffic_json(const nlohmann::json& robot_report, const std::string& name,
                            double sim_s) {
  if (robot_report.is_null() || !robot_report.contains("traffic")) return nullptr;
  const nlohmann::json& t = robot_report["traffic"];
  const auto rates = [&](std::initializer_list<std::string> topics) {
    double messages = 0.0, bytes = 0.0;
    for (const std::string& topic : topics) {
      if (!t.contains(topic)) continue;
      messages += t[topic]["messages_sent"].get<double>();
      bytes += t[topic]["bytes_sent"].get<double>();
    }
    return nlohmann::json{{"messages_per_s", sim_s > 0.0 ? messages / sim_s : 0.0},
                          {"bytes_per_s", sim_s > 0.0 ? bytes / sim_s : 0.0}};
  };
  return {{"per", "simulated second"},
          {"maps", rates({"/" + name + "/map", "/team/map"})},
          {"claims", rates({"/team/claims"})},
          {"map_latency", robot_report.value("map_latency", nlohmann::json(nullptr))}};
}

}  // namespace

CoverageSample team_coverage(const nodes::TeamObserver& observer, const World& world,
                             const std::vector<std::uint8_t>& reachable, double t_s) {
  const OccupancyGrid merged = observer.merged(world.geometry());
  return {t_s, coverage(merged, reachable, 1.0), coverage(merged, reachable)};
}

Status write_team_outputs(const std::filesystem::path& out, const nodes::TeamObserver& observer,
                          const TeamRunRecord& run, nlohmann::json report) {
  const World& world = *run.world;
  const OccupancyGrid merged = observer.merged(world.geometry());
  // The merged map as map.pgm shows it (free, occupied, grey between), and as its probabilities
  // cut at 0.5 would (every known cell free or occupied).
  const TruthGrid truth(world.geometry(), world.solid_cells());
  const MapSaveOptions shown;
  const MapAccuracy accuracy =
      compare_to_truth_as_shown(merged, truth, shown.free_thresh, shown.occupied_thresh);
  const MapAccuracy at_half = compare_to_truth(merged, truth);
  nlohmann::json robots = nlohmann::json::array();
  RenderLayers layers;
  layers.map = &merged;
  layers.truth = &world;
  int i = 0;
  for (const auto& [name, r] : observer.robots()) {
    const RobotEvents& ev = run.events[static_cast<std::size_t>(i)];
    nlohmann::json j = {
        {"name", name},
        {"start",
         {run.starts[static_cast<std::size_t>(i)].x, run.starts[static_cast<std::size_t>(i)].y,
          run.starts[static_cast<std::size_t>(i)].theta}},
        {"killed_at_s", or_null(ev.killed_at_s)},
        {"restarted_at_s", or_null(ev.restarted_at_s)},
        {"exited_at_s", or_null(ev.exited_at_s)},
        {"maps_received", r.maps_received},
        {"map_bytes_received", r.map_bytes_received},
        {"slam_position_error", slam_error_json(r)},
        {"traffic", traffic_json(run.robot_reports.size() > static_cast<std::size_t>(i)
                                     ? run.robot_reports[static_cast<std::size_t>(i)]
                                     : nlohmann::json(nullptr),
                                 name, run.sim_s)}};
    if (i < static_cast<int>(run.robot_reports.size())) {
      j["placements"] = placements_json(run.robot_reports[static_cast<std::size_t>(i)], run,
                                        static_cast<std::size_t>(i));
    }
    if (r.status) {
      j["state"] = r.status->state;
      j["reason"] = r.status->reason;
      j["messages_sent"] = r.status->messages_sent;
      j["bytes_sent"] = r.status->bytes_sent;
      j["messages_dropped"] = r.status->messages_dropped;
      j["explored_area_m2"] = r.status->explored_area_m2;
    }
    robots.push_back(j);
    std::vector<Vec2> path;
    for (const StampedPose2& p : r.truth) path.push_back({p.pose.x, p.pose.y});
    layers.paths_m.push_back(std::move(path));
    if (Status s = write_tum_trajectory(out / (name + "_truth.txt"), r.truth); !s) return s;
    if (Status s = write_tum_trajectory(out / (name + "_slam.txt"), r.slam); !s) return s;
    ++i;
  }
  nlohmann::json series = nlohmann::json::array();
  for (const CoverageSample& s : run.coverage) series.push_back({s.t_s, s.known, s.free});
  const CoverageSample last = run.coverage.empty() ? CoverageSample{} : run.coverage.back();
  report["team"] = {
      {"robots", robots},
      {"end", run.end},
      {"simulated_s", run.sim_s},
      {"coverage", last.known},
      {"coverage_free", last.free},
      {"time_to_90_s", or_null(first_time_at(run.coverage, 0.90, true))},
      {"time_to_99_s", or_null(first_time_at(run.coverage, 0.99, true))},
      {"time_to_99_free_s", or_null(first_time_at(run.coverage, 0.99, false))},
      {"coverage_series", {{"columns", {"t_s", "known", "known_free"}}, {"rows", series}}},
      {"maps_dropped", observer.maps_dropped()}};
  report["map_accuracy"] = map_accuracy_json(accuracy, Pose2{});
  report["map_accuracy"]["truth"] = fmt::format(
      "each truth cell against the merged map as map.pgm shows it: free p <= {}, occupied p >= "
      "{}, grey between (not compared); the team frame is the world frame",
      shown.free_thresh, shown.occupied_thresh);
  report["map_accuracy"]["threshold_view"] = {
      {"occupied_threshold", 0.5},
      {"cells_compared", at_half.cells_compared},
      {"occupied_as_empty", at_half.occupied_as_empty},
      {"empty_as_occupied", at_half.empty_as_occupied},
      {"occupied_as_empty_share", at_half.occupied_as_empty_share()}};
  if (Status s = write_map_yaml(merged, out / "map.yaml"); !s) return s;
  if (Status s = write_png(out / "map.png", layers); !s) return s;
  return write_json_atomic(out / "report.json", report);
}

}  // namespace tessera::cli
