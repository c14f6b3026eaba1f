#include "tessera/sensors/cell_sensor.hpp"

#include "tessera/core/assert.hpp"

namespace tessera {

void insert_cell_reading(OccupancyGrid& map, const CellReading& reading,
                         const CellSensorOptions& options, std::vector<Cell>* touched) {
  const GridGeometry& geometry = map.geometry();
  TESSERA_ASSERT(geometry.contains(reading.center));
  TESSERA_ASSERT(options.p_free > 0.0 && options.p_free < 1.0 && options.p_occupied > 0.0 &&
                 options.p_occupied < 1.0);
  // The lecture writes the probabilities outright (its figures: 0.1 open, 0.9 obstacle).
  const auto write = [&](Cell c, double p) {
    const bool was_known = map.known(c);
    const float before = map.log_odds_at(c);
    map.set_probability(c, p);
    if (touched != nullptr && (!was_known || map.log_odds_at(c) != before)) touched->push_back(c);
  };
  write(reading.center, options.p_free);  // the robot stands in it
  for (std::size_t k = 0; k < kNeighbors8.size(); ++k) {
    const Cell n = reading.center + kNeighbors8[k];
    if (!reading.inside_map[k] || !geometry.contains(n)) continue;
    write(n, reading.occupied[k] ? options.p_occupied : options.p_free);
  }
}

}  // namespace tessera
