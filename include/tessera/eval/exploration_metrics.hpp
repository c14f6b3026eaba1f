#pragma once
// The figures of an exploration run (DESIGN.md report.json "exploration"), and the coverage time
// series they come from.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace tessera {

/// One point of the coverage curve: after `step` steps the robots had driven `path_m` metres in
/// total and the map covered `coverage` of the reachable free cells.
struct CoverageSample {
  std::int64_t step = 0;
  double path_m = 0.0;
  double coverage = 0.0;
};

struct ExplorationMetrics {
  int robots = 0;
  double coverage = 0.0;               // final, in [0, 1]
  std::int64_t steps = 0;              // rounds in which every robot with a path moved one cell
  double path_length_m = 0.0;          // summed over robots
  std::int64_t path_length_cells = 0;  // moves, summed over robots
  std::int64_t turns = 0;              // heading changes between consecutive moves, summed
  /// First step / total path at which coverage reached 90 % and 99 %; nullopt when never reached.
  std::optional<std::int64_t> steps_to_90;
  std::optional<std::int64_t> steps_to_99;
  std::optional<double> path_m_to_90;
  std::optional<double> path_m_to_99;
  std::string stop_reason;  // "no reachable frontier" or "step limit"
  /// Step 0 first, then every stride-th step and the last one; run_exploration keeps every step up
  /// to 8192 samples and doubles the stride beyond (bounded memory on long runs).
  std::vector<CoverageSample> coverage_over_time;
};

/// Sets `coverage` and fills the 90 % / 99 % milestones the first time `sample` reaches them,
/// without touching the series. Feed every step, in step order.
void record_milestones(ExplorationMetrics& metrics, const CoverageSample& sample);

/// record_milestones() and appends `sample` to the series.
void add_sample(ExplorationMetrics& metrics, const CoverageSample& sample);

}  // namespace tessera
