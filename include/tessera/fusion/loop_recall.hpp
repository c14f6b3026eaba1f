#pragma once
// "Recall at 100% precision" of a loop-closure detector, as RTAB-Map reports it on its sample set
// (Labbe & Michaud 2013, "Appearance-Based Loop Closure Detection for Online Large-Scale and
// Long-Term Operation", IEEE T-RO 29(3), section V; tools/ConsoleApp/main.cpp): every processed
// query yields at most one hypothesis with a score and whether the ground truth calls it a loop;
// a threshold accepts the hypotheses scoring at or above it; recall is the share of the queries
// that have a true loop whose hypothesis is accepted and correct, at the lowest threshold at
// which no accepted hypothesis is wrong.
#include <limits>
#include <span>

namespace tessera::fusion {

struct ScoredHypothesis {
  double score = 0.0;
  bool correct = false;  // the ground truth holds a loop between the query and this hypothesis
};

struct RecallAtFullPrecision {
  /// found / positives; 0 when positives is 0.
  double recall = 0.0;
  int found = 0;      // correct hypotheses accepted at `threshold`
  int accepted = 0;   // all hypotheses accepted at `threshold` (== found: precision is 100%)
  int positives = 0;  // queries with at least one true loop (the denominator)
  /// Accept score >= threshold: the lowest correct score above every wrong score. +infinity when
  /// no correct hypothesis scores above every wrong one (nothing is accepted, recall 0).
  double threshold = std::numeric_limits<double>::infinity();
};

/// The sweep over thresholds: a wrong hypothesis with score w forces threshold > w, so the best
/// threshold is the lowest correct score above the highest wrong score; ties between a correct
/// and a wrong score are not accepted. Precondition: positives >= 0 (found may not exceed it if
/// the hypotheses come from distinct queries). Cost: O(n).
[[nodiscard]] RecallAtFullPrecision recall_at_full_precision(
    std::span<const ScoredHypothesis> hypotheses, int positives);

}  // namespace tessera::fusion
