#include "tessera/grid/occupancy_grid.hpp"

#include <algorithm>
#include <numeric>
#include <span>

namespace tessera {

std::optional<std::string> validate(const SensorModelOptions& o) {
  const auto in_open_unit = [](double p) { return p > 0.0 && p < 1.0; };
  if (!in_open_unit(o.p_hit) || o.p_hit <= 0.5) return "p_hit must be in (0.5, 1)";
  if (!in_open_unit(o.p_miss) || o.p_miss >= 0.5) return "p_miss must be in (0, 0.5)";
  if (!in_open_unit(o.p_clamp_min) || !in_open_unit(o.p_clamp_max) ||
      o.p_clamp_min >= o.p_clamp_max) {
    return "p_clamp_min and p_clamp_max must satisfy 0 < min < max < 1";
  }
  return std::nullopt;
}

void OccupancyGrid::set_probability(Cell c, double p) {
  const std::size_t i = geometry_.index_of(c);
  log_odds_[i] = log_odds(std::clamp(p, 1e-4, 1.0 - 1e-4));
  known_[i] = 1;
}

void OccupancyGrid::set_unknown(Cell c) {
  const std::size_t i = geometry_.index_of(c);
  log_odds_[i] = 0.0f;
  known_[i] = 0;
}

void OccupancyGrid::apply_hit(Cell c, const SensorModelOptions& model) {
  add_log_odds(c, log_odds(model.p_hit), log_odds(model.p_clamp_min), log_odds(model.p_clamp_max));
}

void OccupancyGrid::apply_miss(Cell c, const SensorModelOptions& model) {
  add_log_odds(c, log_odds(model.p_miss), log_odds(model.p_clamp_min), log_odds(model.p_clamp_max));
}

std::size_t OccupancyGrid::known_count() const {
  return static_cast<std::size_t>(std::count(known_.begin(), known_.end(), std::uint8_t{1}));
}

CellCounts OccupancyGrid::count_states(double occupied_threshold) const {
  const float threshold = log_odds(occupied_threshold);
  CellCounts counts;
  for (std::size_t i = 0; i < known_.size(); ++i) {
    if (known_[i] == 0) {
      ++counts.unknown;
    } else if (log_odds_[i] >= threshold) {
      ++counts.occupied;
    } else {
      ++counts.free;
    }
  }
  return counts;
}

std::optional<CellBox> known_box(const OccupancyGrid& map) {
  return nonzero_box(map.geometry(), map.known_flags());
}

OccupancyGrid known_part(const OccupancyGrid& map) {
  const std::optional<CellBox> box = known_box(map);
  if (!box) return OccupancyGrid{};
  const GridGeometry& g = map.geometry();
  const double r = g.resolution_m();
  const int w = box->max.x - box->min.x + 1;
  OccupancyGrid out(GridGeometry({g.origin().x + box->min.x * r, g.origin().y + box->min.y * r}, r,
                                 w, box->max.y - box->min.y + 1));
  // Row by row: the same cells, the same values (an unknown cell's log-odds are 0 in both).
  for (int y = box->min.y; y <= box->max.y; ++y) {
    const auto from = static_cast<std::ptrdiff_t>(g.index_of({box->min.x, y}));
    const auto to = static_cast<std::ptrdiff_t>(out.geometry().index_of({0, y - box->min.y}));
    std::copy_n(map.log_odds_.begin() + from, w, out.log_odds_.begin() + to);
    std::copy_n(map.known_.begin() + from, w, out.known_.begin() + to);
  }
  return out;
}

}  // namespace tessera
