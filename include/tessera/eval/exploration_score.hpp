#pragma once
// Scores an exploration while it runs (DESIGN.md report.json "exploration"): the coverage of the
// truth's reachable free cells after every step, the 90 % / 99 % milestones and the coverage time
// series. The robots' side (mission/exploration_mission.hpp) produces the map and the paths; this
// holds the truth and never influences the run.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "tessera/core/cell.hpp"
#include "tessera/eval/coverage.hpp"
#include "tessera/eval/exploration_metrics.hpp"
#include "tessera/grid/occupancy_grid.hpp"

namespace tessera {

class ExplorationScorer {
 public:
  /// The series keeps every step up to this many samples, then doubles its stride (bounded memory
  /// on long runs): samples stay on multiples of the stride, step 0 included.
  static constexpr std::size_t kMaxSeriesSamples = 8192;

  /// `reachable`: one byte per cell of the map's geometry, 1 = free cell of the truth that the
  /// robots can reach (World::reachable_from of the first start). `robots`: the team's size.
  ExplorationScorer(std::vector<std::uint8_t> reachable, int robots);

  /// The map after `step` steps (0: the readings at the starts), the cells changed since the last
  /// observe() (all of them at step 0) and the robots' total path. Feed every step, in order.
  /// Cost: O(changed).
  void observe(std::int64_t step, double path_m, const OccupancyGrid& map,
               std::span<const Cell> changed);

  [[nodiscard]] double coverage() const { return coverage_.coverage(); }
  [[nodiscard]] std::size_t reachable_cells() const { return coverage_.reachable_cells(); }
  /// The metrics so far (the series and milestones up to the last observe()).
  [[nodiscard]] const ExplorationMetrics& metrics() const { return metrics_; }

  /// The run's figures once it stopped after `steps` steps: the path and turn counts of the
  /// robots' trip log, and the last sample added to the series if it is not there.
  /// Precondition: observe() was called at least once.
  [[nodiscard]] ExplorationMetrics finish(std::int64_t steps, double path_m,
                                          std::int64_t path_length_cells, std::int64_t turns,
                                          const std::string& stop_reason) const;

 private:
  CoverageTracker coverage_;
  ExplorationMetrics metrics_;
  std::int64_t series_stride_ = 1;
};

}  // namespace tessera
