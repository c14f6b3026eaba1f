#pragma once
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "tessera/mission/exploration_mission.hpp"
#include "tessera/sim/world.hpp"

namespace tessera {

/// What a report needs besides the run itself.
struct ExplorationReportContext {
  std::uint64_t seed = 0;
  std::string world_file;
  nlohmann::json options =
      nlohmann::json::object();  // the effective options, as the user sees them
  double wall_s = 0.0;
};

/// report.json of an exploration run: the core keys (report/core_report.hpp; data_duration_s is
/// one second per step, the trajectory's stamps, and timing adds planning_s), "world",
/// "exploration", "map_accuracy" and the coverage time series under "coverage_over_time" (at most 500 samples, always including the last).
[[nodiscard]] nlohmann::json exploration_report(const ExplorationResult& result, const World& world,
                                                const ExplorationReportContext& context);

}  // namespace tessera
