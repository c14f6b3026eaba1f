#pragma once
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "tessera/grid/grid_geometry.hpp"

namespace tessera {

/// Inverse sensor model for hit/miss updates. Defaults are OctoMap's, named as probabilities and
/// applied as log-odds; clamping keeps a cell able to change its mind (OctoMap's clamping policy).
struct SensorModelOptions {
  double p_hit = 0.7;
  double p_miss = 0.4;
  double p_clamp_min = 0.1192;
  double p_clamp_max = 0.971;
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const SensorModelOptions& o);

[[nodiscard]] inline float log_odds(double p) {
  return static_cast<float>(std::log(p / (1.0 - p)));
}
[[nodiscard]] inline double probability(float log_odds) {
  return 1.0 - 1.0 / (1.0 + std::exp(static_cast<double>(log_odds)));
}

/// The threshold view of a cell (lecture, "The content of the cells").
enum class CellState : std::uint8_t { kUnknown = 0, kFree = 1, kOccupied = 2 };

/// How many cells of a grid are in each state of the threshold view.
struct CellCounts {
  std::size_t free = 0;
  std::size_t occupied = 0;
  std::size_t unknown = 0;
};

/// Occupancy grid map: one float log-odds value per cell plus "unknown" as its own state (a cell no
/// sensor has reported on is not the same as p = 0.5). Offers the probability view and the
/// threshold view of the lecture: with threshold 0.5 more cells count as occupied (objects look
/// bigger), with 0.7 fewer. Memory: 5 bytes per cell.
class OccupancyGrid {
 public:
  OccupancyGrid() = default;
  explicit OccupancyGrid(const GridGeometry& geometry)
      : geometry_(geometry), log_odds_(geometry.size(), 0.0f), known_(geometry.size(), 0) {}

  [[nodiscard]] const GridGeometry& geometry() const { return geometry_; }

  /// Precondition for every per-cell call: geometry().contains(c).
  [[nodiscard]] bool known(Cell c) const { return known_[geometry_.index_of(c)] != 0; }
  /// Log-odds of occupancy; 0 for an unknown cell.
  [[nodiscard]] float log_odds_at(Cell c) const { return log_odds_[geometry_.index_of(c)]; }
  /// Occupancy probability; nullopt for an unknown cell.
  [[nodiscard]] std::optional<double> probability_at(Cell c) const {
    const std::size_t i = geometry_.index_of(c);
    return known_[i] ? std::optional<double>{probability(log_odds_[i])} : std::nullopt;
  }
  /// Threshold view: kOccupied when p >= occupied_threshold, kFree below it, kUnknown if never
  /// seen.
  [[nodiscard]] CellState state(Cell c, double occupied_threshold = 0.5) const {
    const std::size_t i = geometry_.index_of(c);
    if (!known_[i]) return CellState::kUnknown;
    return log_odds_[i] >= log_odds(occupied_threshold) ? CellState::kOccupied : CellState::kFree;
  }
  /// True when the cell is known and p < low (the frontier algorithm's "grid(c) < low").
  [[nodiscard]] bool is_free_below(Cell c, float low_log_odds) const {
    const std::size_t i = geometry_.index_of(c);
    return known_[i] && log_odds_[i] < low_log_odds;
  }

  /// Sets a cell's probability outright (map files, the lecture's worked grids).
  /// p is clamped into [1e-4, 1 - 1e-4] so that log-odds stay finite.
  void set_probability(Cell c, double p);
  /// Forgets what is known about a cell.
  void set_unknown(Cell c);
  /// Adds log-odds evidence and clamps to the model's range; the cell becomes known.
  void add_log_odds(Cell c, float delta, float clamp_min, float clamp_max) {
    const std::size_t i = geometry_.index_of(c);
    const float v = log_odds_[i] + delta;
    log_odds_[i] = v < clamp_min ? clamp_min : (v > clamp_max ? clamp_max : v);
    known_[i] = 1;
  }
  void apply_hit(Cell c, const SensorModelOptions& model);
  void apply_miss(Cell c, const SensorModelOptions& model);

  [[nodiscard]] std::size_t known_count() const;
  /// Cells per state of the threshold view state(c, occupied_threshold). Cost: O(cells).
  [[nodiscard]] CellCounts count_states(double occupied_threshold = 0.5) const;
  /// Every cell's log-odds and known flag in index_of order (row-major), for whole-map passes
  /// such as a message conversion, without a bounds check per cell.
  [[nodiscard]] std::span<const float> log_odds_values() const { return log_odds_; }
  [[nodiscard]] std::span<const std::uint8_t> known_flags() const { return known_; }
  /// Bytes the cells take (5 per cell).
  [[nodiscard]] std::size_t memory_bytes() const {
    return log_odds_.size() * sizeof(float) + known_.size();
  }

 private:
  friend OccupancyGrid known_part(const OccupancyGrid& map);  // copies rows of the two arrays

  GridGeometry geometry_;
  std::vector<float> log_odds_;
  std::vector<std::uint8_t> known_;
};

/// The smallest box of cells that holds every known cell of `map` (what a robot sends of its
/// map); nullopt when nothing is known. Cost: O(cells), a row at a time.
[[nodiscard]] std::optional<CellBox> known_box(const OccupancyGrid& map);

/// The cells of known_box(map) as a grid of their own, each where it was in space (a map cut to
/// what it knows); an empty grid when nothing is known. Cost: O(cells).
[[nodiscard]] OccupancyGrid known_part(const OccupancyGrid& map);

}  // namespace tessera
