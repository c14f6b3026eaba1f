#include "tessera/slam/correlative_scan_matcher.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <span>
#include <vector>

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

/// The largest sum that does not reach min_score: a candidate must beat it.
long sum_bound(double min_score, std::size_t points) {
  const double q = (min_score - kMinProbability) / (kMaxProbability - kMinProbability) * 255.0 *
                   static_cast<double>(points);
  if (q <= 0.0) return -1;
  return static_cast<long>(std::ceil(q - 1e-9)) - 1;
}

}  // namespace

bool ExcludedPoses::contains(const Pose2& pose) const {
  return std::any_of(around.begin(), around.end(), [&](const Pose2& p) {
    return std::hypot(pose.x - p.x, pose.y - p.y) <= linear_m &&
           std::abs(normalize_angle(pose.theta - p.theta)) <= angular_rad;
  });
}

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

  /// Running sums of a candidate's points, at the end of each of kBlocks blocks of points. A
  /// child's point never scores more than its parent's (the child's cells lie inside the
  /// parent's, whose maximum the coarser level holds), so a child whose sum so far plus its
  /// parent's over the points still to come cannot beat the bound is given up there (kGivenUp,
  /// below every bound): it would be pruned once scored. Most children are pruned, many of them
  /// after a few blocks; the answers are unchanged (decision 0045).
  static constexpr int kBlocks = 8;
  using Prefix = std::array<long, kBlocks>;
  static constexpr long kGivenUp = -1;

  /// The sum of the candidate's points at the level. With `parent` (the prefix of the candidate
  /// one level up that covers it), kGivenUp as soon as the sum cannot exceed `bound`; fills `out`.
  [[nodiscard]] long score(int level_index, const Candidate& c, const Prefix* parent = nullptr,
                           long bound = 0, Prefix* out = nullptr) const {
    const Level& level = matcher.levels_[static_cast<std::size_t>(level_index)];
    const int ox = c.x + level.offset, oy = c.y + level.offset;
    const std::vector<Cell>& scan = scans[static_cast<std::size_t>(c.angle)];
    const CellBox& box = boxes[static_cast<std::size_t>(c.angle)];
    // Inside: every point on the level, so no bounds test (the same sum).
    const bool inside = box.min.x + ox >= 0 && box.min.y + oy >= 0 &&
                        box.max.x + ox < level.width && box.max.y + oy < level.height;
    const std::size_t n = scan.size();
    const std::size_t per_block = (n + kBlocks - 1) / kBlocks;
    long sum = 0;
    std::size_t i = 0;
    for (int b = 0; b < kBlocks; ++b) {
      const std::size_t end = std::min(n, i + per_block);
      if (inside) {
        for (; i < end; ++i) {
          sum += level.cells[static_cast<std::size_t>(scan[i].y + oy) *
                                 static_cast<std::size_t>(level.width) +
                             static_cast<std::size_t>(scan[i].x + ox)];
        }
      } else {
        for (; i < end; ++i) {
          const int x = scan[i].x + ox, y = scan[i].y + oy;
          if (x < 0 || y < 0 || x >= level.width || y >= level.height) continue;
          sum += level.cells[static_cast<std::size_t>(y) * static_cast<std::size_t>(level.width) +
                             static_cast<std::size_t>(x)];
        }
      }
      if (out) (*out)[static_cast<std::size_t>(b)] = sum;
      if (parent && sum + (parent->back() - (*parent)[static_cast<std::size_t>(b)]) <= bound) {
        return kGivenUp;
      }
    }
    return sum;
  }

  /// True for a full-resolution candidate among the excluded poses.
  [[nodiscard]] bool is_excluded(const Candidate& c) const {
    if (!excluded) return false;
    return excluded->contains(pose_of(c));
  }

  static void sort(std::span<Candidate> candidates) {
    std::stable_sort(candidates.begin(), candidates.end(),
                     [](const Candidate& a, const Candidate& b) { return a.sum > b.sum; });
  }

  /// The (at most four) children of a candidate at `level`, scored one level down and sorted best
  /// first by insertion (stable: ties keep their order); on the caller's stack, since the search
  /// visits many nodes and must not allocate for each. With the candidate's prefix, children that
  /// cannot beat `bound` are given up (they sort last); their prefixes go to `prefixes`. Returns
  /// how many.
  std::size_t split(int level, const Candidate& c, const Prefix* prefix, long bound,
                    std::array<Candidate, 4>& children, std::array<Prefix, 4>& prefixes) const {
    const int half = 1 << (level - 1);
    std::size_t n = 0;
    for (const int dx : {0, half}) {
      if (c.x + dx > n_lin) break;
      for (const int dy : {0, half}) {
        if (c.y + dy > n_lin) break;
        Candidate child{c.angle, c.x + dx, c.y + dy, 0};
        Prefix child_prefix{};  // a given-up child fills only its first blocks
        child.sum = score(level - 1, child, prefix, bound, &child_prefix);
        std::size_t i = n++;
        for (; i > 0 && children[i - 1].sum < child.sum; --i) {
          children[i] = children[i - 1];
          prefixes[i] = prefixes[i - 1];
        }
        children[i] = child;
        prefixes[i] = child_prefix;
      }
    }
    return n;
  }

  /// Hess et al. 2016, Algorithm 3 (depth-first, best child first): the best candidate below
  /// `candidates` (sorted, best first; with their prefixes, or none) whose sum exceeds `bound`,
  /// or nullopt.
  std::optional<Candidate> branch(int level, std::span<const Candidate> candidates,
                                  const Prefix* prefixes, long bound) const {
    std::optional<Candidate> best;
    for (std::size_t k = 0; k < candidates.size(); ++k) {
      const Candidate& c = candidates[k];
      if (c.sum <= bound) break;  // sorted: no later candidate can do better
      if (level == 0) {
        if (is_excluded(c)) continue;
        return c;
      }
      std::array<Candidate, 4> children;
      std::array<Prefix, 4> child_prefixes;
      const std::size_t n =
          split(level, c, prefixes ? &prefixes[k] : nullptr, bound, children, child_prefixes);
      if (std::optional<Candidate> r =
              branch(level - 1, std::span<const Candidate>(children.data(), n),
                     child_prefixes.data(), bound)) {
        best = r;
        bound = r->sum;
      }
    }
    return best;
  }

  /// A candidate of match_ranked's search with its place in branch()'s order: leaves that
  /// branch() meets earlier have smaller keys (the poses around the prior first, then each root's
  /// index among the sorted roots followed by the ranks among siblings, two bits a level).
  struct Keyed {
    Candidate c;
    int level = 0;
    std::uint64_t key = 0;
  };
  static constexpr std::uint64_t kFirstRootKey = std::uint64_t{1} << 20;

  /// match_ranked's state: the best sum so far (above `best_bound`), every leaf met above the
  /// rival bound, and up to `places` leaves met so far that lie twice `distinct` apart (`apart`):
  /// an exclusion of `distinct` around a place holds for at most one of them, so each of the
  /// first `places` places scores at least the lowest of them, and the bound rises to it.
  struct Ranking {
    Rivals rivals;
    std::size_t points = 0;
    long best_bound = 0;  // the best must beat this sum (min_score)
    long bound = 0;       // a contender must beat this sum
    std::optional<long> best_sum;
    std::vector<Keyed> leaves;
    ExcludedPoses apart;
    std::vector<std::pair<long, Pose2>> tops;  // sums and poses, pairwise apart

    void meet(const Keyed& leaf, const Pose2& pose) {
      const long sum = leaf.c.sum;
      if (sum <= bound) return;
      leaves.push_back(leaf);
      if (sum > best_bound && (!best_sum || sum > *best_sum)) {
        best_sum = sum;
        bound = std::max(bound,
                         std::min(sum_bound(rivals.score(score_of(sum, points)), points), sum - 1));
      }
      keep_apart(sum, pose);
    }

    void keep_apart(long sum, const Pose2& pose) {
      if (rivals.places <= 0) return;  // no place asked for: only the rival score bounds
      std::size_t near = 0, near_count = 0;
      for (std::size_t i = 0; i < tops.size(); ++i) {
        apart.around = {tops[i].second};
        if (apart.contains(pose)) {
          near = i;
          ++near_count;
        }
      }
      const auto lowest = [this] {
        return std::min_element(tops.begin(), tops.end(),
                                [](const auto& a, const auto& b) { return a.first < b.first; });
      };
      const bool full = tops.size() == static_cast<std::size_t>(rivals.places);
      if (near_count == 0 && !full) {
        tops.emplace_back(sum, pose);
      } else if (near_count == 0 && sum > lowest()->first) {
        *lowest() = {sum, pose};
      } else if (near_count == 1 && sum > tops[near].first) {
        tops[near] = {sum, pose};
      } else {
        return;
      }
      if (tops.size() == static_cast<std::size_t>(rivals.places)) {
        // Ties with the lowest stay: the search's order decides among equal sums.
        bound = std::max(bound, lowest()->first - 1);
      }
    }
  };

  /// match_ranked's search: branch()'s depth-first order, with the bound at min_score until a
  /// best is found and at the rival bound after it. The candidates passed over before the best
  /// was found that may still hold a rival are kept in `deferred` and searched after; the keys
  /// put every leaf back in branch()'s order.
  void rank(std::span<const Keyed> candidates, const Prefix* prefixes, Ranking& r,
            std::vector<Keyed>& deferred) const {
    for (std::size_t k = 0; k < candidates.size(); ++k) {
      const Keyed& node = candidates[k];
      if (node.c.sum <= r.bound) break;
      if (!r.best_sum && node.c.sum <= r.best_bound) {
        // No best yet, and none below here: these may hold rivals of one found later.
        for (; k < candidates.size() && candidates[k].c.sum > r.bound; ++k) {
          deferred.push_back(candidates[k]);
        }
        break;
      }
      if (node.level == 0) {
        r.meet(node, pose_of(node.c));
        continue;
      }
      std::array<Candidate, 4> children;
      std::array<Prefix, 4> child_prefixes;
      const std::size_t n = split(node.level, node.c, prefixes ? &prefixes[k] : nullptr, r.bound,
                                  children, child_prefixes);
      std::array<Keyed, 4> keyed;
      for (std::size_t i = 0; i < n; ++i) {
        keyed[i] = {children[i], node.level - 1, (node.key << 2) | i};
      }
      rank(std::span<const Keyed>(keyed.data(), n), child_prefixes.data(), r, deferred);
    }
  }

  /// The top level's candidates over the whole window, scored and sorted best first.
  [[nodiscard]] std::vector<Candidate> roots() const {
    const int top = matcher.depth() - 1;
    const int step = 1 << top;
    std::vector<Candidate> all;
    for (int a = 0; a < static_cast<int>(angles.size()); ++a) {
      for (int x = -n_lin; x <= n_lin; x += step) {
        for (int y = -n_lin; y <= n_lin; y += step) {
          Candidate c{a, x, y, 0};
          c.sum = score(top, c);
          all.push_back(c);
        }
      }
    }
    sort(all);
    return all;
  }

  /// Calls f with each full-resolution candidate within kNearAngles angle steps and kNearCells
  /// cells of the prior, scored, in a fixed order: scored before branch and bound, a good
  /// estimate prunes the tree early.
  template <class F>
  void near_prior(F&& f) const {
    constexpr int kNearAngles = 3;
    constexpr int kNearCells = 2;
    const int cells = std::min(kNearCells, n_lin);
    for (int a = std::max(0, zero_angle - kNearAngles);
         a <= std::min(static_cast<int>(angles.size()) - 1, zero_angle + kNearAngles); ++a) {
      for (int x = -cells; x <= cells; ++x) {
        for (int y = -cells; y <= cells; ++y) {
          Candidate c{a, x, y, 0};
          c.sum = score(0, c);
          f(c);
        }
      }
    }
  }

  [[nodiscard]] Pose2 pose_of(const Candidate& c) const {
    const double res = matcher.geometry_.resolution_m();
    return {prior.x + c.x * res, prior.y + c.y * res,
            normalize_angle(prior.theta + angles[static_cast<std::size_t>(c.angle)])};
  }

  [[nodiscard]] ScanMatch to_match(const Candidate& c, std::size_t points) const {
    return {pose_of(c), score_of(c.sum, points)};
  }
};

std::optional<ScanMatch> BranchAndBoundMatcher::match(
    const Pose2& T_grid_robot_prior, const std::vector<Vec2>& points_robot,
    const SearchWindow& window, double min_score,
    const std::optional<ExcludedPoses>& excluded) const {
  if (points_robot.empty()) return std::nullopt;
  const Search search(*this, T_grid_robot_prior, points_robot, window, excluded);
  const std::vector<Search::Candidate> roots = search.roots();
  // A good first answer makes the bound prune most of the tree: score the poses right around the
  // prior at full resolution first (the estimate is usually close). Branch and bound then only
  // looks for strictly better poses, so the result is still the window's best.
  long bound = sum_bound(min_score, points_robot.size());
  std::optional<Search::Candidate> best;
  search.near_prior([&](const Search::Candidate& c) {
    if (c.sum > bound && !search.is_excluded(c)) {
      best = c;
      bound = c.sum;
    }
  });
  if (std::optional<Search::Candidate> better = search.branch(depth() - 1, roots, nullptr, bound)) {
    best = better;
  }
  if (!best) return std::nullopt;
  return search.to_match(*best, points_robot.size());
}

std::optional<RankedMatches> BranchAndBoundMatcher::match_ranked(
    const Pose2& T_grid_robot_prior, const std::vector<Vec2>& points_robot,
    const SearchWindow& window, double min_score, const Rivals& rivals) const {
  if (points_robot.empty()) return std::nullopt;
  const std::size_t n = points_robot.size();
  const Search search(*this, T_grid_robot_prior, points_robot, window, std::nullopt);
  const std::vector<Search::Candidate> roots = search.roots();
  Search::Ranking r;
  r.rivals = rivals;
  r.points = n;
  r.best_bound = sum_bound(min_score, n);
  // Until a best is found the rival bound is the lowest any best would set (a best scores at
  // least min_score; one less for the rounding of sums): no rival of the final best is pruned.
  r.bound = std::min(sum_bound(rivals.score(min_score), n) - 1, r.best_bound);
  r.apart = {{}, 2.0 * rivals.distinct.linear_m, 2.0 * rivals.distinct.angular_rad};
  std::uint64_t near_key = 0;
  search.near_prior([&](const Search::Candidate& c) {
    r.meet({c, 0, near_key++}, search.pose_of(c));
  });
  std::vector<Search::Keyed> keyed(roots.size());
  for (std::size_t i = 0; i < roots.size(); ++i) {
    keyed[i] = {roots[i], depth() - 1, Search::kFirstRootKey + i};
  }
  std::vector<Search::Keyed> deferred;
  search.rank(keyed, nullptr, r, deferred);
  if (!r.best_sum) return std::nullopt;
  std::vector<Search::Keyed> none;  // with a best known nothing is deferred again
  for (const Search::Keyed& node : deferred) {
    search.rank(std::span<const Search::Keyed>(&node, 1), nullptr, r, none);
  }
  // The leaves met before the bound rose are cut to it, then ranked as branch() would meet them.
  std::erase_if(r.leaves, [&r](const Search::Keyed& l) { return l.c.sum <= r.bound; });
  std::sort(r.leaves.begin(), r.leaves.end(), [](const Search::Keyed& a, const Search::Keyed& b) {
    return a.c.sum != b.c.sum ? a.c.sum > b.c.sum : a.key < b.key;
  });
  RankedMatches ranked{search.to_match(r.leaves.front().c, n), {}};
  ranked.contenders.reserve(r.leaves.size());
  for (const Search::Keyed& l : r.leaves) ranked.contenders.push_back(search.to_match(l.c, n));
  return ranked;
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
