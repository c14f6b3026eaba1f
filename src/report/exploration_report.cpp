#include "tessera/report/exploration_report.hpp"

#include <algorithm>

#include "tessera/report/core_report.hpp"

namespace tessera {
namespace {

/// null in JSON stands for "never reached" (e.g. steps_to_99 of a run stopped early).
template <typename T>
nlohmann::json or_null(const std::optional<T>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

}  // namespace

nlohmann::json exploration_report(const ExplorationResult& r, const World& world,
                                  const ExplorationReportContext& context) {
  const ExplorationMetrics& m = r.metrics;
  // The simulator has no clock of its own: one step is one second (the trajectory's stamps).
  nlohmann::json j = core_report({"explore", context.seed, context.options, context.wall_s,
                                          static_cast<double>(m.steps)});
  j["world"] = {{"file", context.world_file},
                {"resolution_m", world.geometry().resolution_m()},
                {"width_cells", world.geometry().width()},
                {"height_cells", world.geometry().height()},
                {"free_cells", r.free_cells},
                {"reachable_free_cells", r.reachable_free_cells}};
  j["exploration"] = {{"robots", m.robots},
                      {"coverage", m.coverage},
                      {"steps", m.steps},
                      {"path_length_m", m.path_length_m},
                      {"path_length_cells", m.path_length_cells},
                      {"turns", m.turns},
                      {"steps_to_90", or_null(m.steps_to_90)},
                      {"steps_to_99", or_null(m.steps_to_99)},
                      {"path_m_to_90", or_null(m.path_m_to_90)},
                      {"path_m_to_99", or_null(m.path_m_to_99)},
                      {"refused_moves", r.refused_moves},
                      {"frontier_cells_left", r.frontier_left.size()},
                      {"unreachable_frontier_cells", r.unreachable_frontier.size()},
                      {"blacklisted_targets", r.blacklisted_targets.size()},
                      {"stop_reason", m.stop_reason}};
  j["map_accuracy"] = {{"cells_compared", r.accuracy.cells_compared},
                       {"correct", r.accuracy.correct},
                       {"empty_as_occupied", r.accuracy.empty_as_occupied},
                       {"occupied_as_empty", r.accuracy.occupied_as_empty},
                       {"success_rate", r.accuracy.success_rate}};
  j["timing"]["planning_s"] = r.planning_time_s;

  // Coverage over time, thinned evenly to at most 500 samples; the last sample is always kept.
  const auto& series = m.coverage_over_time;
  nlohmann::json step = nlohmann::json::array(), path_m = nlohmann::json::array(),
                 coverage = nlohmann::json::array();
  const std::size_t stride = std::max<std::size_t>(1, (series.size() + 499) / 500);
  for (std::size_t i = 0; i < series.size(); ++i) {
    if (i % stride != 0 && i + 1 != series.size()) continue;
    step.push_back(series[i].step);
    path_m.push_back(series[i].path_m);
    coverage.push_back(series[i].coverage);
  }
  j["coverage_over_time"] = {{"step", step}, {"path_m", path_m}, {"coverage", coverage}};
  return j;
}

}  // namespace tessera
