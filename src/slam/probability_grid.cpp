#include "tessera/slam/probability_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

#include "tessera/grid/ray_cast.hpp"

namespace tessera::slam {
namespace {

constexpr std::uint16_t kUpdateMarker = 32768;
constexpr double kValueStep = (kMaxProbability - kMinProbability) / (kMaxCellValue - 1.0);

std::vector<float> make_probability_table() {
  std::vector<float> table(kMaxCellValue + 1u);
  table[kUnknownCellValue] = static_cast<float>(kMinProbability);
  for (std::size_t v = 1; v <= kMaxCellValue; ++v) {
    table[v] = static_cast<float>(kMinProbability + static_cast<double>(v - 1) * kValueStep);
  }
  return table;
}

double odds(double p) { return p / (1.0 - p); }
double probability_from_odds(double o) { return o / (1.0 + o); }

}  // namespace

std::uint16_t probability_to_value(double p) {
  const double clamped = std::clamp(p, kMinProbability, kMaxProbability);
  return static_cast<std::uint16_t>(std::lround((clamped - kMinProbability) / kValueStep) + 1);
}

const std::vector<float>& value_to_probability_table() {
  static const std::vector<float> table = make_probability_table();
  return table;
}

float value_to_probability(std::uint16_t value) {
  return value_to_probability_table()[value & (kUpdateMarker - 1u)];
}

UpdateTable make_update_table(double p) {
  UpdateTable t;
  t.after.resize(kUpdateMarker);
  t.after[kUnknownCellValue] = static_cast<std::uint16_t>(probability_to_value(p) | kUpdateMarker);
  const double update_odds = odds(p);
  for (std::size_t v = 1; v < kUpdateMarker; ++v) {
    const double before = kMinProbability + static_cast<double>(v - 1) * kValueStep;
    const double after = probability_from_odds(odds(before) * update_odds);
    t.after[v] = static_cast<std::uint16_t>(probability_to_value(after) | kUpdateMarker);
  }
  return t;
}

ProbabilityGrid::ProbabilityGrid(const GridGeometry& geometry)
    : geometry_(geometry), values_(geometry.size(), kUnknownCellValue) {}

void ProbabilityGrid::set_probability(Cell c, double p) {
  values_[geometry_.index_of(c)] = probability_to_value(p);
}

void ProbabilityGrid::grow_to_include(Vec2 p_m, int margin_cells) {
  TESSERA_ASSERT(updated_.empty());
  const double res = geometry_.resolution_m();
  if (geometry_.width() == 0 || geometry_.height() == 0) {
    const int side = 2 * margin_cells + 64;
    const Vec2 origin{p_m.x - side / 2 * res, p_m.y - side / 2 * res};
    *this = ProbabilityGrid(GridGeometry(origin, res, side, side));
  }
  for (;;) {
    const Cell c = geometry_.cell_at_unchecked(p_m);
    const bool inside_x = c.x >= margin_cells && c.x < geometry_.width() - margin_cells;
    const bool inside_y = c.y >= margin_cells && c.y < geometry_.height() - margin_cells;
    if (inside_x && inside_y) return;
    // Double the grid along each axis that is too small, keeping the old cells in the middle.
    const int add_x = inside_x ? 0 : geometry_.width();
    const int add_y = inside_y ? 0 : geometry_.height();
    const int shift_x = add_x / 2, shift_y = add_y / 2;
    const GridGeometry grown(
        {geometry_.origin().x - shift_x * res, geometry_.origin().y - shift_y * res}, res,
        geometry_.width() + add_x, geometry_.height() + add_y);
    std::vector<std::uint16_t> values(grown.size(), kUnknownCellValue);
    for (int y = 0; y < geometry_.height(); ++y) {
      const auto src = values_.begin() + static_cast<std::ptrdiff_t>(geometry_.index_of({0, y}));
      std::copy(
          src, src + geometry_.width(),
          values.begin() + static_cast<std::ptrdiff_t>(grown.index_of({shift_x, y + shift_y})));
    }
    geometry_ = grown;
    values_ = std::move(values);
  }
}

bool ProbabilityGrid::apply(Cell c, const UpdateTable& table) {
  const std::size_t i = geometry_.index_of(c);
  std::uint16_t& v = values_[i];
  if (v >= kUpdateMarker) return false;
  v = table.after[v];
  updated_.push_back(i);
  return true;
}

void ProbabilityGrid::finish_update() {
  for (const std::size_t i : updated_)
    values_[i] = static_cast<std::uint16_t>(values_[i] & ~kUpdateMarker);
  updated_.clear();
}

std::optional<ProbabilityGrid::Box> ProbabilityGrid::known_box() const {
  static_assert(kUnknownCellValue == 0, "nonzero_box finds the known cells");
  return nonzero_box(geometry_, std::span<const std::uint16_t>(values_));
}

OccupancyGrid ProbabilityGrid::to_occupancy_grid(int padding_cells) const {
  const std::optional<Box> box = known_box();
  const double res = geometry_.resolution_m();
  if (!box) return OccupancyGrid(GridGeometry(geometry_.origin(), res, 0, 0));
  const Cell lo{box->min.x - padding_cells, box->min.y - padding_cells};
  const Cell hi{box->max.x + padding_cells, box->max.y + padding_cells};
  const GridGeometry out_geometry(
      {geometry_.origin().x + lo.x * res, geometry_.origin().y + lo.y * res}, res, hi.x - lo.x + 1,
      hi.y - lo.y + 1);
  OccupancyGrid out(out_geometry);
  for (int y = lo.y; y <= hi.y; ++y) {
    for (int x = lo.x; x <= hi.x; ++x) {
      const Cell c{x, y};
      if (!geometry_.contains(c)) continue;
      const std::uint16_t v = value(c);
      if (v == kUnknownCellValue) continue;
      out.set_probability(c - lo, value_to_probability(v));
    }
  }
  return out;
}

std::optional<std::string> validate(const RangeInsertOptions& o) {
  if (!(o.hit_probability > 0.5 && o.hit_probability < 1.0)) {
    return "hit_probability must be in (0.5, 1)";
  }
  if (!(o.miss_probability > 0.0 && o.miss_probability < 0.5)) {
    return "miss_probability must be in (0, 0.5)";
  }
  if (!(o.miss_margin_m >= 0.0)) return "miss_margin_m must be >= 0";
  if (!(o.miss_inset_m >= 0.0)) return "miss_inset_m must be >= 0";
  if (!(o.join_returns_within_m >= 0.0)) return "join_returns_within_m must be >= 0";
  return std::nullopt;
}

RangeInserter::RangeInserter(const RangeInsertOptions& options)
    : options_(options),
      hit_(make_update_table(options.hit_probability)),
      miss_(make_update_table(options.miss_probability)) {}

namespace {

// The shallowest incidence the miss band is widened for: at 0.1 (5.7 deg) the band along the ray
// is ten times its width across the surface.
constexpr double kMinSinIncidence = 0.1;

/// The band before return i (seen from origin, range_m away) in which its ray gives no miss:
/// margin_m across the surface the return lies on, as the nearer of the neighbouring beams'
/// returns shows it (the other may lie beyond an edge), so margin_m / sin(incidence) along the ray.
/// A ray that meets a wall at a shallow angle runs through the cells along the wall's face for a
/// long way before its return: measured along the ray, the band lets it clear them. A return
/// without a neighbouring beam keeps margin_m along its ray.
double miss_band_m(const std::vector<Vec2>& returns, const std::vector<int>& beams, std::size_t i,
                   Vec2 origin, double range_m, double margin_m) {
  if (margin_m <= 0.0) return margin_m;
  Vec2 along{0.0, 0.0};
  double best2 = std::numeric_limits<double>::infinity();
  for (const std::size_t k : {i - 1, i + 1}) {  // i - 1 wraps to SIZE_MAX for i = 0
    if (k >= returns.size() || std::abs(beams[k] - beams[i]) != 1) continue;
    const Vec2 d = returns[k] - returns[i];
    if (d.dot(d) < best2) {
      best2 = d.dot(d);
      along = d;
    }
  }
  if (!(best2 > 0.0) || !std::isfinite(best2)) return margin_m;
  const double sin_incidence =
      std::abs((returns[i] - origin).cross(along)) / (range_m * std::sqrt(best2));
  return margin_m / std::max(sin_incidence, kMinSinIncidence);
}

/// A ray's test for the cells it may clear: the line from `from` to `to` must cross a cell's
/// square shrunk by inset_m on every side, i.e. pass within the shrunk square's support across the
/// line (half its width times |u.x| + |u.y|, u the unit direction) of the square's centre. The
/// line's signed distance from cell (x, y)'s centre, u x (centre - from), is linear in x and y:
/// three numbers per ray, two multiply-adds per cell. inset_m <= 0: every cell the ray visits, at
/// no cost per ray (the submaps' insertion); a ray of no length clears no cell.
class InnerCrossing {
 public:
  InnerCrossing(const GridGeometry& g, Vec2 from, Vec2 to, double inset_m)
      : every_cell_(inset_m <= 0.0) {
    if (every_cell_) return;
    const double length_m = (to - from).norm();
    if (!(length_m > 0.0)) return;  // reach_ stays negative: nothing is crossed
    const Vec2 u = (to - from) * (1.0 / length_m);
    reach_ = (0.5 * g.resolution_m() - inset_m) * (std::abs(u.x) + std::abs(u.y));
    per_x_ = -u.y * g.resolution_m();
    per_y_ = u.x * g.resolution_m();
    at_origin_ = u.cross(g.center_of({0, 0}) - from);
  }
  [[nodiscard]] bool operator()(Cell c) const {
    return every_cell_ || std::abs(at_origin_ + per_x_ * c.x + per_y_ * c.y) <= reach_;
  }

 private:
  bool every_cell_;
  double reach_ = -1.0, per_x_ = 0.0, per_y_ = 0.0, at_origin_ = 0.0;
};

}  // namespace

void RangeInserter::insert(ProbabilityGrid& grid, const Pose2& T_grid_robot,
                           const ScanPoints& points) const {
  const Vec2 origin = T_grid_robot * points.origin_m;
  std::vector<Vec2> returns = transform_points(T_grid_robot, points.returns_m);
  std::vector<Vec2> misses;
  if (options_.insert_free_space) misses = transform_points(T_grid_robot, points.misses_m);
  grid.grow_to_include(origin);
  for (const Vec2& p : returns) grid.grow_to_include(p);
  for (const Vec2& p : misses) grid.grow_to_include(p);

  const GridGeometry& g = grid.geometry();
  // Hits first, so that a ray of this scan passing through another return's cell cannot clear it.
  for (const Vec2& p : returns) grid.apply(g.cell_at_unchecked(p), hit_);
  if (options_.join_returns_within_m > 0.0 && points.return_beams.size() == returns.size()) {
    const double max_gap2 = options_.join_returns_within_m * options_.join_returns_within_m;
    for (std::size_t i = 1; i < returns.size(); ++i) {
      if (points.return_beams[i] != points.return_beams[i - 1] + 1) continue;
      const Vec2 d = returns[i] - returns[i - 1];
      if (d.dot(d) > max_gap2) continue;
      traverse_ray(g, returns[i - 1], returns[i],
                   [&](Cell c, double, double) { grid.apply(c, hit_); });
    }
  }
  if (options_.insert_free_space) {
    const double inset_m = options_.miss_inset_m;
    const bool beams_known = points.return_beams.size() == returns.size();
    for (std::size_t i = 0; i < returns.size(); ++i) {
      const Vec2& p = returns[i];
      const Cell end = g.cell_at_unchecked(p);
      const double range_m = (p - origin).norm();
      if (!(range_m > 0.0)) continue;
      const double margin_m = beams_known ? miss_band_m(returns, points.return_beams, i, origin,
                                                        range_m, options_.miss_margin_m)
                                          : options_.miss_margin_m;
      const double last_miss_m = range_m - margin_m;
      const InnerCrossing clears(g, origin, p, inset_m);
      traverse_ray(g, origin, p, [&](Cell c, double t_enter_m, double) {
        if (t_enter_m > last_miss_m) return false;  // this cell and the rest lie in the band
        if (!(c == end) && clears(c)) grid.apply(c, miss_);
        return true;
      });
    }
    for (const Vec2& p : misses) {
      const InnerCrossing clears(g, origin, p, inset_m);
      traverse_ray(g, origin, p, [&](Cell c, double, double) {
        if (clears(c)) grid.apply(c, miss_);
      });
    }
  }
  grid.finish_update();
}

}  // namespace tessera::slam
