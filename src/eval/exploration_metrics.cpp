#include "tessera/eval/exploration_metrics.hpp"

#include "tessera/core/assert.hpp"

namespace tessera {

void record_milestones(ExplorationMetrics& metrics, const CoverageSample& sample) {
  metrics.coverage = sample.coverage;
  if (!metrics.steps_to_90.has_value() && sample.coverage >= 0.9) {
    metrics.steps_to_90 = sample.step;
    metrics.path_m_to_90 = sample.path_m;
  }
  if (!metrics.steps_to_99.has_value() && sample.coverage >= 0.99) {
    metrics.steps_to_99 = sample.step;
    metrics.path_m_to_99 = sample.path_m;
  }
}

void add_sample(ExplorationMetrics& metrics, const CoverageSample& sample) {
  TESSERA_ASSERT(metrics.coverage_over_time.empty() ||
                 metrics.coverage_over_time.back().step <= sample.step);
  metrics.coverage_over_time.push_back(sample);
  record_milestones(metrics, sample);
}

}  // namespace tessera
