#include "tessera/eval/map_accuracy.hpp"

namespace tessera {

MapAccuracy compare_to_truth(const OccupancyGrid& map, const World& truth,
                             double occupied_threshold) {
  const GridGeometry& g = map.geometry();
  TESSERA_ASSERT(g.width() == truth.geometry().width() && g.height() == truth.geometry().height());
  const float threshold_lo = log_odds(occupied_threshold);
  MapAccuracy a;
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) {
      const Cell c{x, y};
      if (!map.known(c)) continue;
      ++a.cells_compared;
      const bool map_occupied = map.log_odds_at(c) >= threshold_lo;
      const bool truth_occupied = truth.solid(c);
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

}  // namespace tessera
