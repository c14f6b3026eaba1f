#include "tessera/eval/exploration_score.hpp"

#include <utility>

#include "tessera/core/assert.hpp"

namespace tessera {

ExplorationScorer::ExplorationScorer(std::vector<std::uint8_t> reachable, int robots)
    : coverage_(std::move(reachable)) {
  metrics_.robots = robots;
}

void ExplorationScorer::observe(std::int64_t step, double path_m, const OccupancyGrid& map,
                                std::span<const Cell> changed) {
  coverage_.update(map, changed);
  const CoverageSample sample{step, path_m, coverage_.coverage()};
  if (metrics_.coverage_over_time.empty()) {
    add_sample(metrics_, sample);
    return;
  }
  TESSERA_ASSERT(metrics_.coverage_over_time.back().step < step);
  record_milestones(metrics_, sample);
  if (step % series_stride_ != 0) return;
  metrics_.coverage_over_time.push_back(sample);
  if (metrics_.coverage_over_time.size() > kMaxSeriesSamples) {
    // Keep the samples on multiples of twice the stride (step 0 included).
    series_stride_ *= 2;
    std::erase_if(metrics_.coverage_over_time,
                  [&](const CoverageSample& x) { return x.step % series_stride_ != 0; });
  }
}

ExplorationMetrics ExplorationScorer::finish(std::int64_t steps, double path_m,
                                             std::int64_t path_length_cells, std::int64_t turns,
                                             const std::string& stop_reason) const {
  TESSERA_ASSERT(!metrics_.coverage_over_time.empty());
  ExplorationMetrics m = metrics_;
  m.steps = steps;
  m.path_length_m = path_m;
  m.path_length_cells = path_length_cells;
  m.turns = turns;
  m.stop_reason = stop_reason;
  if (m.coverage_over_time.back().step != steps) {
    m.coverage_over_time.push_back({steps, path_m, coverage_.coverage()});
  }
  return m;
}

}  // namespace tessera
