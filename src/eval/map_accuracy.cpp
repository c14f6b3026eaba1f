#include "tessera/eval/map_accuracy.hpp"

#include <optional>

namespace tessera {
namespace {

/// Counts every cell of `map` that map_occupied(cell) classifies (nullopt: not compared) against
/// truth_solid(cell).
template <typename MapOccupied, typename TruthSolid>
MapAccuracy count_cells(const OccupancyGrid& map, const MapOccupied& map_occupied_of,
                        const TruthSolid& truth_solid) {
  const GridGeometry& g = map.geometry();
  MapAccuracy a;
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) {
      const Cell c{x, y};
      const std::optional<bool> occupied = map_occupied_of(c);
      if (!occupied) continue;
      ++a.cells_compared;
      const bool map_occupied = *occupied;
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

/// Counts every known cell of `map` against truth_solid(cell), occupied from occupied_threshold.
template <typename TruthSolid>
MapAccuracy count_against(const OccupancyGrid& map, double occupied_threshold,
                          const TruthSolid& truth_solid) {
  const float threshold_lo = log_odds(occupied_threshold);
  return count_cells(
      map,
      [&](Cell c) -> std::optional<bool> {
        if (!map.known(c)) return std::nullopt;
        return map.log_odds_at(c) >= threshold_lo;
      },
      truth_solid);
}

}  // namespace

MapAccuracy compare_to_truth(const OccupancyGrid& map, const TruthGrid& truth,
                             double occupied_threshold) {
  TESSERA_ASSERT(map.geometry().width() == truth.geometry().width() &&
                 map.geometry().height() == truth.geometry().height());
  return count_against(map, occupied_threshold, [&](Cell c) { return truth.solid(c); });
}

MapAccuracy compare_to_truth_as_shown(const OccupancyGrid& map, const TruthGrid& truth,
                                      double free_at_most, double occupied_from) {
  TESSERA_ASSERT(map.geometry().width() == truth.geometry().width() &&
                 map.geometry().height() == truth.geometry().height());
  TESSERA_ASSERT(free_at_most < occupied_from);
  return count_cells(
      map,
      [&](Cell c) -> std::optional<bool> {
        const std::optional<double> p = map.probability_at(c);
        if (!p || (*p > free_at_most && *p < occupied_from)) return std::nullopt;
        return *p >= occupied_from;
      },
      [&](Cell c) { return truth.solid(c); });
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
