#include "tessera/slam/correlative_scan_matcher.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <span>

#include "tessera/grid/grid_geometry.hpp"

namespace tessera::slam {
namespace {

double max_range_of(const std::vector<Vec2>& points) {
  double r = 0.0;
  for (const Vec2& p : points) r = std::max(r, p.norm());
  return r;
}

/// Heading offsets of a search: k * step for |k * step| <= window, or an even split of the full
/// turn when the window reaches pi.
std::vector<double> angle_offsets(double angular_window_rad, double step_rad) {
  std::vector<double> out;
  constexpr double kPi = std::numbers::pi;
  if (angular_window_rad >= kPi) {
    const int m = std::max(1, static_cast<int>(std::ceil(2.0 * kPi / step_rad)));
    const double step = 2.0 * kPi / m;
    for (int k = -m / 2; k < m - m / 2; ++k) out.push_back(k * step);
  } else {
    const int n = static_cast<int>(std::ceil(angular_window_rad / step_rad));
    for (int k = -n; k <= n; ++k) out.push_back(k * step_rad);
  }
  return out;
}

/// The cells the points fall in when the robot is at (prior translation, prior heading + angle).
void discretize(const GridGeometry& g, const Pose2& prior, double angle_offset_rad,
                const std::vector<Vec2>& points, std::vector<Cell>& cells) {
  cells.clear();
  const Pose2 T{prior.x, prior.y, normalize_angle(prior.theta + angle_offset_rad)};
  const double c = std::cos(T.theta), s = std::sin(T.theta);
  for (const Vec2& p : points) {
    cells.push_back(g.cell_at_unchecked({T.x + c * p.x - s * p.y, T.y + s * p.x + c * p.y}));
  }
}

/// The smallest box (grid_geometry.hpp's CellBox) that holds a non-empty list of cells.
CellBox bounding_box(const std::vector<Cell>& cells) {
  CellBox box{cells.front(), cells.front()};
  for (const Cell c : cells) {
    box.min = {std::min(box.min.x, c.x), std::min(box.min.y, c.y)};
    box.max = {std::max(box.max.x, c.x), std::max(box.max.y, c.y)};
  }
  return box;
}

}  // namespace

double angular_search_step_rad(double resolution_m, double max_point_range_m) {
  const double d = std::max(max_point_range_m, resolution_m);
  const double x = 1.0 - resolution_m * resolution_m / (2.0 * d * d);
  return std::acos(std::clamp(x, -1.0, 1.0));
}

std::optional<std::string> validate(const RealTimeMatcherOptions& o) {
  if (!(o.linear_window_m >= 0.0)) return "linear_window_m must be >= 0";
  if (!(o.angular_window_rad >= 0.0)) return "angular_window_rad must be >= 0";
  if (!(o.translation_delta_cost_weight >= 0.0))
    return "translation_delta_cost_weight must be >= 0";
  if (!(o.rotation_delta_cost_weight >= 0.0)) return "rotation_delta_cost_weight must be >= 0";
  if (!(o.angular_step_range_m > 0.0)) return "angular_step_range_m must be > 0";
  return std::nullopt;
}

ScanMatch match_real_time(const ProbabilityGrid& grid, const Pose2& T_grid_robot_prior,
                          const std::vector<Vec2>& points_robot,
                          const RealTimeMatcherOptions& options) {
  ScanMatch best{T_grid_robot_prior, -1.0};
  if (points_robot.empty()) return {T_grid_robot_prior, 0.0};
  const GridGeometry& g = grid.geometry();
  const double res = g.resolution_m();
  const std::vector<double> angles = angle_offsets(
      options.angular_window_rad,
      angular_search_step_rad(res, std::min(max_range_of(points_robot),
                                            options.angular_step_range_m)));
  const int n_lin = static_cast<int>(std::ceil(options.linear_window_m / res - 1e-9));
  const std::vector<float>& table = value_to_probability_table();
  const std::vector<std::uint16_t>& values = grid.values();
  const int w = g.width(), h = g.height();
  const auto outside = static_cast<float>(kMinProbability);
  const double inv_n = 1.0 / static_cast<double>(points_robot.size());
  std::vector<Cell> cells;
  std::vector<std::size_t> indices;
  for (const double a : angles) {
    discretize(g, T_grid_robot_prior, a, points_robot, cells);
    // When the whole window stays on the grid (nearly always), the points are summed by index
    // without a bounds test; the sums, and so the result, are the same either way.
    const CellBox box = bounding_box(cells);
    const bool inside = box.min.x - n_lin >= 0 && box.max.x + n_lin < w && box.min.y - n_lin >= 0 &&
                        box.max.y + n_lin < h;
    if (inside) {
      indices.clear();
      for (const Cell c : cells) {
        indices.push_back(static_cast<std::size_t>(c.y) * static_cast<std::size_t>(w) +
                          static_cast<std::size_t>(c.x));
      }
    }
    for (int dx = -n_lin; dx <= n_lin; ++dx) {
      for (int dy = -n_lin; dy <= n_lin; ++dy) {
        float sum = 0.0f;
        if (inside) {
          const std::ptrdiff_t shift = static_cast<std::ptrdiff_t>(dy) * w + dx;
          for (const std::size_t i : indices) {
            sum += table[values[static_cast<std::size_t>(static_cast<std::ptrdiff_t>(i) + shift)]];
          }
        } else {
          for (const Cell c : cells) {
            const int x = c.x + dx, y = c.y + dy;
            sum += (x >= 0 && x < w && y >= 0 && y < h)
                       ? table[values[static_cast<std::size_t>(y) * static_cast<std::size_t>(w) +
                                      static_cast<std::size_t>(x)]]
                       : outside;
          }
        }
        const double penalty = options.translation_delta_cost_weight * res * std::hypot(dx, dy) +
                               options.rotation_delta_cost_weight * std::abs(a);
        const double score = static_cast<double>(sum) * inv_n * std::exp(-penalty * penalty);
        if (score > best.score) {
          best.score = score;
          best.T_grid_robot = {T_grid_robot_prior.x + dx * res, T_grid_robot_prior.y + dy * res,
                               normalize_angle(T_grid_robot_prior.theta + a)};
        }
      }
    }
  }
  return best;
}

// ---------------------------------------------------------------------------------------------
// Branch and bound

namespace {

std::uint8_t quantize_probability(double p) {
  return static_cast<std::uint8_t>(std::lround(
      255.0 * std::clamp((p - kMinProbability) / (kMaxProbability - kMinProbability), 0.0, 1.0)));
}

/// quantize_probability(value_to_probability(v)) for every cell value v.
const std::vector<std::uint8_t>& quantized_value_table() {
  static const std::vector<std::uint8_t> table = [] {
    std::vector<std::uint8_t> t(std::size_t{kMaxCellValue} + 1);
    for (std::size_t v = 0; v < t.size(); ++v) {
      t[v] = quantize_probability(value_to_probability(static_cast<std::uint16_t>(v)));
    }
    return t;
  }();
  return table;
}

double score_of(long sum, std::size_t points) {
  return kMinProbability + (kMaxProbability - kMinProbability) * static_cast<double>(sum) /
                               (255.0 * static_cast<double>(points));
}

}  // namespace

BranchAndBoundMatcher::BranchAndBoundMatcher(const ProbabilityGrid& grid, int depth,
                                             double unknown_probability)
    : geometry_(grid.geometry()) {
  TESSERA_ASSERT(depth >= 1);
  const int w = geometry_.width(), h = geometry_.height();
  Level base;
  base.width = w;
  base.height = h;
  base.offset = 0;
  base.cells.resize(geometry_.size());
  const std::uint8_t unknown = quantize_probability(unknown_probability);
  const std::vector<std::uint8_t>& quantized = quantized_value_table();
  for (std::size_t i = 0; i < base.cells.size(); ++i) {
    const std::uint16_t value = grid.values()[i];
    // (The mask is value_to_probability's: a cell marked during an update reads as its value.)
    base.cells[i] = value == kUnknownCellValue ? unknown : quantized[value & kMaxCellValue];
  }
  levels_.push_back(std::move(base));
  for (int d = 1; d < depth; ++d) {
    const Level& finer = levels_.back();
    const int half = 1 << (d - 1);
    Level level;
    level.offset = (1 << d) - 1;
    level.width = w + level.offset;
    level.height = h + level.offset;
    // Level d at (x, y) covers [x, x + 2^d): the four level d-1 cells at offsets 0 and half. In
    // the levels' own (padded) coordinates those are the finer cells (xx - half, yy - half) to
    // (xx, yy); cells off the finer level count 0. The maximum is taken along each finer row into
    // level row fy + half, then, in place, along the columns: row yy becomes the maximum of rows
    // yy and yy + half (the latter not yet overwritten). No scratch grid: the levels are large
    // and fresh memory is what costs.
    const int fw = finer.width, fh = finer.height, lw = level.width, lh = level.height;
    level.cells.resize(static_cast<std::size_t>(lw) * static_cast<std::size_t>(lh));
    const auto row = [&level, lw](int yy) {
      return level.cells.data() + static_cast<std::size_t>(yy) * static_cast<std::size_t>(lw);
    };
    for (int fy = 0; fy < fh; ++fy) {
      const std::uint8_t* f =
          finer.cells.data() + static_cast<std::size_t>(fy) * static_cast<std::size_t>(fw);
      std::uint8_t* r = row(fy + half);
      for (int xx = 0; xx < std::min(half, fw); ++xx) r[xx] = f[xx];
      for (int xx = half; xx < fw; ++xx) r[xx] = std::max(f[xx - half], f[xx]);
      for (int xx = std::max(half, fw); xx < lw; ++xx) r[xx] = f[xx - half];
    }
    for (int yy = 0; yy < lh; ++yy) {
      if (yy + half >= lh) break;  // rows from here on keep their own value (row yy + half is 0)
      std::uint8_t* out = row(yy);
      const std::uint8_t* next = row(yy + half);
      for (int xx = 0; xx < lw; ++xx) out[xx] = std::max(out[xx], next[xx]);
    }
    levels_.push_back(std::move(level));
  }
}

std::size_t BranchAndBoundMatcher::memory_bytes() const {
  std::size_t n = 0;
  for (const Level& l : levels_) n += l.cells.size();
  return n;
}

/// One search: the scan discretised at every heading, the window in cells, and scoring.
struct BranchAndBoundMatcher::Search {
  struct Candidate {
    int angle = 0;  // index into angles
    int x = 0;      // cell offset from the prior
    int y = 0;
    long sum = 0;  // sum of quantised cell values
  };

  const BranchAndBoundMatcher& matcher;
  Pose2 prior;
  std::optional<ExcludedPoses> excluded;
  std::vector<double> angles;
  std::vector<std::vector<Cell>> scans;
  std::vector<CellBox> boxes;  // per angle, of scans
  int n_lin = 0;
  int zero_angle = 0;  // index of the smallest |angle|

  Search(const BranchAndBoundMatcher& m, const Pose2& prior_pose, const std::vector<Vec2>& points,
         const SearchWindow& window, const std::optional<ExcludedPoses>& excluded_poses)
      : matcher(m), prior(prior_pose), excluded(excluded_poses) {
    const double res = m.geometry_.resolution_m();
    angles = angle_offsets(window.angular_rad, angular_search_step_rad(res, max_range_of(points)));
    n_lin = static_cast<int>(std::ceil(window.linear_m / res - 1e-9));
    scans.resize(angles.size());
    boxes.resize(angles.size());
    for (std::size_t a = 0; a < angles.size(); ++a) {
      discretize(m.geometry_, prior, angles[a], points, scans[a]);
      boxes[a] = bounding_box(scans[a]);
      if (std::abs(angles[a]) < std::abs(angles[static_cast<std::size_t>(zero_angle)])) {
        zero_angle = static_cast<int>(a);
      }
    }
  }

  [[nodiscard]] long score(int level_index, const Candidate& c) const {
    const Level& level = matcher.levels_[static_cast<std::size_t>(level_index)];
    long sum = 0;
    const int ox = c.x + level.offset, oy = c.y + level.offset;
    const std::vector<Cell>& scan = scans[static_cast<std::size_t>(c.angle)];
    const CellBox& box = boxes[static_cast<std::size_t>(c.angle)];
    if (box.min.x + ox >= 0 && box.min.y + oy >= 0 && box.max.x + ox < level.width &&
        box.max.y + oy < level.height) {
      // Every point on the level: no bounds test (the same sum).
      for (const Cell cell : scan) {
        sum += level.cells[static_cast<std::size_t>(cell.y + oy) *
                               static_cast<std::size_t>(level.width) +
                           static_cast<std::size_t>(cell.x + ox)];
      }
      return sum;
    }
    for (const Cell cell : scan) {
      const int x = cell.x + ox, y = cell.y + oy;
      if (x < 0 || y < 0 || x >= level.width || y >= level.height) continue;
      sum += level.cells[static_cast<std::size_t>(y) * static_cast<std::size_t>(level.width) +
                         static_cast<std::size_t>(x)];
    }
    return sum;
  }

  /// True for a full-resolution candidate among the excluded poses.
  [[nodiscard]] bool is_excluded(const Candidate& c) const {
    if (!excluded) return false;
    const double res = matcher.geometry_.resolution_m();
    const double x = prior.x + c.x * res, y = prior.y + c.y * res;
    const double theta = prior.theta + angles[static_cast<std::size_t>(c.angle)];
    return std::any_of(excluded->around.begin(), excluded->around.end(), [&](const Pose2& p) {
      return std::hypot(x - p.x, y - p.y) <= excluded->linear_m &&
             std::abs(normalize_angle(theta - p.theta)) <= excluded->angular_rad;
    });
  }

  static void sort(std::span<Candidate> candidates) {
    std::stable_sort(candidates.begin(), candidates.end(),
                     [](const Candidate& a, const Candidate& b) { return a.sum > b.sum; });
  }

  /// Hess et al. 2016, Algorithm 3 (depth-first, best child first): the best candidate below
  /// `candidates` (sorted, best first) whose sum exceeds `bound`, or nullopt.
  std::optional<Candidate> branch(int level, std::span<const Candidate> candidates,
                                  long bound) const {
    std::optional<Candidate> best;
    for (const Candidate& c : candidates) {
      if (c.sum <= bound) break;  // sorted: no later candidate can do better
      if (level == 0) {
        if (is_excluded(c)) continue;
        return c;
      }
      const int half = 1 << (level - 1);
      // At most four children, sorted best first by insertion (stable: ties keep their order),
      // on the stack: the search visits many nodes and must not allocate for each.
      std::array<Candidate, 4> children;
      std::size_t n = 0;
      for (const int dx : {0, half}) {
        if (c.x + dx > n_lin) break;
        for (const int dy : {0, half}) {
          if (c.y + dy > n_lin) break;
          Candidate child{c.angle, c.x + dx, c.y + dy, 0};
          child.sum = score(level - 1, child);
          std::size_t i = n++;
          for (; i > 0 && children[i - 1].sum < child.sum; --i) children[i] = children[i - 1];
          children[i] = child;
        }
      }
      if (std::optional<Candidate> r =
              branch(level - 1, std::span<const Candidate>(children.data(), n), bound)) {
        best = r;
        bound = r->sum;
      }
    }
    return best;
  }

  [[nodiscard]] ScanMatch to_match(const Candidate& c, std::size_t points) const {
    const double res = matcher.geometry_.resolution_m();
    return {{prior.x + c.x * res, prior.y + c.y * res,
             normalize_angle(prior.theta + angles[static_cast<std::size_t>(c.angle)])},
            score_of(c.sum, points)};
  }
};

namespace {

/// The neighbourhood of the prior scored before branch and bound: +-kNearAngles angle steps,
/// +-kNearCells cells.
constexpr int kNearAngles = 3;
constexpr int kNearCells = 2;

/// The largest sum that does not reach min_score: a candidate must beat it.
long sum_bound(double min_score, std::size_t points) {
  const double q = (min_score - kMinProbability) / (kMaxProbability - kMinProbability) * 255.0 *
                   static_cast<double>(points);
  if (q <= 0.0) return -1;
  return static_cast<long>(std::ceil(q - 1e-9)) - 1;
}

}  // namespace

std::optional<ScanMatch> BranchAndBoundMatcher::match(
    const Pose2& T_grid_robot_prior, const std::vector<Vec2>& points_robot,
    const SearchWindow& window, double min_score,
    const std::optional<ExcludedPoses>& excluded) const {
  if (points_robot.empty()) return std::nullopt;
  const Search search(*this, T_grid_robot_prior, points_robot, window, excluded);
  const int top = depth() - 1;
  const int step = 1 << top;
  std::vector<Search::Candidate> roots;
  for (int a = 0; a < static_cast<int>(search.angles.size()); ++a) {
    for (int x = -search.n_lin; x <= search.n_lin; x += step) {
      for (int y = -search.n_lin; y <= search.n_lin; y += step) {
        Search::Candidate c{a, x, y, 0};
        c.sum = search.score(top, c);
        roots.push_back(c);
      }
    }
  }
  Search::sort(roots);
  // A good first answer makes the bound prune most of the tree: score the poses right around the
  // prior at full resolution first (the estimate is usually close). Branch and bound then only
  // looks for strictly better poses, so the result is still the window's best.
  long bound = sum_bound(min_score, points_robot.size());
  std::optional<Search::Candidate> best;
  const int zero = search.zero_angle;
  for (int a = std::max(0, zero - kNearAngles);
       a <= std::min(static_cast<int>(search.angles.size()) - 1, zero + kNearAngles); ++a) {
    for (int x = -std::min(kNearCells, search.n_lin); x <= std::min(kNearCells, search.n_lin);
         ++x) {
      for (int y = -std::min(kNearCells, search.n_lin); y <= std::min(kNearCells, search.n_lin);
           ++y) {
        Search::Candidate c{a, x, y, 0};
        c.sum = search.score(0, c);
        if (c.sum > bound && !search.is_excluded(c)) {
          best = c;
          bound = c.sum;
        }
      }
    }
  }
  if (std::optional<Search::Candidate> better = search.branch(top, roots, bound)) best = better;
  if (!best) return std::nullopt;
  return search.to_match(*best, points_robot.size());
}

std::optional<ScanMatch> BranchAndBoundMatcher::match_exhaustive(
    const Pose2& T_grid_robot_prior, const std::vector<Vec2>& points_robot,
    const SearchWindow& window, double min_score) const {
  if (points_robot.empty()) return std::nullopt;
  const Search search(*this, T_grid_robot_prior, points_robot, window, std::nullopt);
  std::optional<Search::Candidate> best;
  long bound = sum_bound(min_score, points_robot.size());
  for (int a = 0; a < static_cast<int>(search.angles.size()); ++a) {
    for (int x = -search.n_lin; x <= search.n_lin; ++x) {
      for (int y = -search.n_lin; y <= search.n_lin; ++y) {
        Search::Candidate c{a, x, y, 0};
        c.sum = search.score(0, c);
        if (c.sum > bound) {
          best = c;
          bound = c.sum;
        }
      }
    }
  }
  if (!best) return std::nullopt;
  return search.to_match(*best, points_robot.size());
}

}  // namespace tessera::slam
