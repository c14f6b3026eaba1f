#include "tessera/eval/map_accuracy.hpp"

namespace tessera {
namespace {

/// Counts every known cell of `map` against truth_solid(cell).
template <typename TruthSolid>
MapAccuracy count_against(const OccupancyGrid& map, double occupied_threshold,
                          const TruthSolid& truth_solid) {
  const GridGeometry& g = map.geometry();
  const float threshold_lo = log_odds(occupied_threshold);
  MapAccuracy a;
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) {
      const Cell c{x, y};
      if (!map.known(c)) continue;
      ++a.cells_compared;
      const bool map_occupied = map.log_odds_at(c) >= threshold_lo;
      const bool truth_occupied = truth_solid(c);
      if (truth_occupied) ++a.occupied_compared;
      if (map_occupied == truth_occupied) {
        ++a.correct;
      } else if (map_occupied) {
        ++a.empty_as_occupied;
      } else {
        ++a.occupied_as_empty;
      }
    }
  }
  a.success_rate = a.cells_compared == 0
                       ? 0.0
                       : static_cast<double>(a.correct) / static_cast<double>(a.cells_compared);
  return a;
}

}  // namespace

MapAccuracy compare_to_truth(const OccupancyGrid& map, const TruthGrid& truth,
                             double occupied_threshold) {
  TESSERA_ASSERT(map.geometry().width() == truth.geometry().width() &&
                 map.geometry().height() == truth.geometry().height());
  return count_against(map, occupied_threshold, [&](Cell c) { return truth.solid(c); });
}

MapAccuracy compare_to_truth_at_centres(const OccupancyGrid& map, const TruthGrid& truth,
                                        const Pose2& T_truth_map, double occupied_threshold) {
  const GridGeometry& g = map.geometry();
  const GridGeometry& w = truth.geometry();
  return count_against(map, occupied_threshold, [&](Cell c) {
    const Vec2 centre = T_truth_map * g.center_of(c);
    return truth.solid(w.cell_at_unchecked(centre));
  });
}

}  // namespace tessera
