#include "tessera/eval/coverage.hpp"

#include <algorithm>

namespace tessera {

double coverage(const OccupancyGrid& map, std::span<const std::uint8_t> reachable,
                double free_below) {
  const GridGeometry& g = map.geometry();
  TESSERA_ASSERT(reachable.size() == g.size());
  const float lo = log_odds(free_below);
  std::size_t total = 0, covered = 0;
  for (std::size_t i = 0; i < reachable.size(); ++i) {
    if (reachable[i] == 0) continue;
    ++total;
    if (map.is_free_below(g.cell_of(i), lo)) ++covered;
  }
  return total == 0 ? 0.0 : static_cast<double>(covered) / static_cast<double>(total);
}

CoverageTracker::CoverageTracker(std::vector<std::uint8_t> reachable, double free_below)
    : reachable_(std::move(reachable)),
      covered_(reachable_.size(), 0),
      free_below_log_odds_(log_odds(free_below)),
      reachable_count_(static_cast<std::size_t>(std::count_if(
          reachable_.begin(), reachable_.end(), [](std::uint8_t r) { return r != 0; }))) {}

void CoverageTracker::reset(const OccupancyGrid& map) {
  const GridGeometry& g = map.geometry();
  TESSERA_ASSERT(g.size() == reachable_.size());
  covered_count_ = 0;
  for (std::size_t i = 0; i < reachable_.size(); ++i) {
    covered_[i] = reachable_[i] != 0 && map.is_free_below(g.cell_of(i), free_below_log_odds_);
    covered_count_ += covered_[i];
  }
}

void CoverageTracker::update(const OccupancyGrid& map, std::span<const Cell> touched) {
  const GridGeometry& g = map.geometry();
  TESSERA_ASSERT(g.size() == reachable_.size());
  for (const Cell c : touched) {
    if (!g.contains(c)) continue;
    const std::size_t i = g.index_of(c);
    if (reachable_[i] == 0) continue;
    const std::uint8_t now = map.is_free_below(c, free_below_log_odds_) ? 1 : 0;
    if (now == covered_[i]) continue;
    covered_[i] = now;
    if (now != 0) {
      ++covered_count_;
    } else {
      --covered_count_;
    }
  }
}

}  // namespace tessera
