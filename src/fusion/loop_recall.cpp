#include "tessera/fusion/loop_recall.hpp"

#include <algorithm>

#include "tessera/core/assert.hpp"

namespace tessera::fusion {

RecallAtFullPrecision recall_at_full_precision(std::span<const ScoredHypothesis> hypotheses,
                                               int positives) {
  TESSERA_ASSERT(positives >= 0);
  RecallAtFullPrecision r;
  r.positives = positives;
  double highest_wrong = -std::numeric_limits<double>::infinity();
  for (const ScoredHypothesis& h : hypotheses) {
    if (!h.correct) highest_wrong = std::max(highest_wrong, h.score);
  }
  for (const ScoredHypothesis& h : hypotheses) {
    if (h.correct && h.score > highest_wrong) r.threshold = std::min(r.threshold, h.score);
  }
  for (const ScoredHypothesis& h : hypotheses) {
    if (h.score >= r.threshold) {
      ++r.accepted;
      if (h.correct) ++r.found;
    }
  }
  r.recall = positives > 0 ? static_cast<double>(r.found) / positives : 0.0;
  return r;
}

}  // namespace tessera::fusion
