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

/// report.json of an exploration run, with the core keys of DESIGN.md ("tessera_version",
/// "command", "seed", "options", "world", "exploration", "map_accuracy", "timing") and the coverage
/// time series under "coverage_over_time" (at most 500 samples, always including the last).
[[nodiscard]] nlohmann::json exploration_report(const ExplorationResult& result, const World& world,
                                                const ExplorationReportContext& context);

}  // namespace tessera
