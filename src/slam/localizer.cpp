// Localization in a frozen map: tracking by scan-to-map matching, loss detection, and global
// relocalization by branch and bound with an ambiguity test (localizer.hpp; Hess et al. 2016).
#include "tessera/slam/localizer.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <deque>

#include "tessera/core/assert.hpp"
#include "tessera/grid/cell_region.hpp"
#include "tessera/slam/scan_agreement.hpp"

namespace tessera::slam {
namespace {

constexpr double kPi = 3.14159265358979323846;

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// Gauss-Newton's covariance at the refined pose: the residual variance times (J^T J)^-1.
/// `points`: how many residuals there were.
Eigen::Matrix3d covariance_of(const RefinedPose& refined, std::size_t points) {
  const double dof = std::max(1.0, static_cast<double>(points) - 3.0);
  const double variance = refined.final_cost / dof;
  // A floor on the curvature keeps a direction the map does not pin (a corridor's axis) finite.
  const Eigen::Matrix3d h = refined.hessian + 1e-9 * Eigen::Matrix3d::Identity();
  return variance * h.inverse();
}

/// The map with a cell's slack: every cell at the highest probability within one cell of it (and
/// an unknown cell beside a wall at the wall's). The global search scores views in it: it tries
/// whole cells and angle steps that move the farthest point by a cell, so at the best pose it
/// tries, a return lies up to about a cell from its wall; in the map itself that is often the
/// free cell beside the wall (0.1 instead of 0.9), and the true pose of a view then scores hardly
/// more than a look-alike (on Intel 0.52-0.60 at the tracked pose). Scored so, a return counts on
/// its wall's cell or beside it, as fit_of counts it from the same grid.
ProbabilityGrid with_slack(const ProbabilityGrid& map) {
  const GridGeometry& g = map.geometry();
  ProbabilityGrid out(g);
  const std::uint16_t half = probability_to_value(0.5);
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) {
      std::uint16_t best = kUnknownCellValue;
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const Cell c{x + dx, y + dy};
          if (g.contains(c)) best = std::max(best, map.value(c));
        }
      }
      if (map.known({x, y}) || best > half) out.set_probability({x, y}, value_to_probability(best));
    }
  }
  return out;
}

}  // namespace

std::optional<std::string> validate(const LocalizerOptions& o) {
  if (auto p = validate(o.points)) return "points." + *p;
  if (auto p = validate(o.tracking)) return "tracking." + *p;
  if (auto p = validate(o.refiner)) return "refiner." + *p;
  if (auto p = validate(o.view_insert)) return "view_insert." + *p;
  if (!(o.min_tracking_score > kMinProbability && o.min_tracking_score < kMaxProbability)) {
    return "min_tracking_score must be in (0.1, 0.9)";
  }
  if (!(o.min_confident_fit >= o.min_tracking_score && o.min_confident_fit < kMaxProbability)) {
    return "min_confident_fit must be in [min_tracking_score, 0.9)";
  }
  if (!(o.min_map_share > 0.0 && o.min_map_share <= 1.0)) return "min_map_share must be in (0, 1]";
  if (!(o.lost_after_s >= 0.0)) return "lost_after_s must be >= 0";
  if (!(o.min_scan_agreement >= 0.0 && o.min_scan_agreement <= 1.0)) {
    return "min_scan_agreement must be in [0, 1]";
  }
  if (o.min_scan_compared < 1) return "min_scan_compared must be >= 1";
  if (!(o.max_glitch_s >= 0.0)) return "max_glitch_s must be >= 0";
  if (!(o.max_untrusted_travel_m > 0.0)) return "max_untrusted_travel_m must be > 0";
  if (!(o.scan_agreement.agreement_m >= 0.0) || !(o.scan_agreement.agreement_share >= 0.0)) {
    return "scan_agreement must be >= 0";
  }
  if (!(o.view_s > 0.0)) return "view_s must be > 0";
  if (!(o.search_every_s >= 0.0)) return "search_every_s must be >= 0";
  if (o.search_points.min_num_points < 1 || !(o.search_points.max_length_m > 0.0) ||
      !(o.search_points.max_range_m > 0.0)) {
    return "search_points must keep at least one point (> 0 sizes)";
  }
  if (!(o.refine_voxel_m >= 0.0)) return "refine_voxel_m must be >= 0";
  if (o.branch_and_bound_depth < 1 || o.branch_and_bound_depth > 12) {
    return "branch_and_bound_depth must be in [1, 12]";
  }
  if (!(o.min_relocalize_score > kMinProbability && o.min_relocalize_score < kMaxProbability)) {
    return "min_relocalize_score must be in (0.1, 0.9)";
  }
  if (!(o.min_search_score > kMinProbability && o.min_search_score < kMaxProbability)) {
    return "min_search_score must be in (0.1, 0.9)";
  }
  if (!(o.unknown_score >= kMinProbability && o.unknown_score <= kMaxProbability)) {
    return "unknown_score must be in [0.1, 0.9]";
  }
  if (!(o.ambiguity_ratio > 0.0 && o.ambiguity_ratio <= 1.0)) {
    return "ambiguity_ratio must be in (0, 1]";
  }
  if (o.confirmations < 1) return "confirmations must be >= 1";
  if (o.max_runner_ups < 0) return "max_runner_ups must be >= 0";
  if (!(o.max_free_conflict >= 0.0 && o.max_free_conflict <= 1.0)) {
    return "max_free_conflict must be in [0, 1]";
  }
  if (!(o.agreement.linear_m > 0.0) || !(o.agreement.angular_rad > 0.0)) {
    return "agreement must be > 0";
  }
  if (!(o.new_view_motion.linear_m >= 0.0) || !(o.new_view_motion.angular_rad >= 0.0)) {
    return "new_view_motion must be >= 0";
  }
  if (!(o.max_idle_search_s >= 0.0)) return "max_idle_search_s must be >= 0";
  if (!(o.distinct.linear_m > 0.0) || !(o.distinct.angular_rad > 0.0)) {
    return "distinct must be > 0";
  }
  return std::nullopt;
}

const char* to_string(LocalizationState state) {
  switch (state) {
    case LocalizationState::kLost:
      return "lost";
    case LocalizationState::kTracking:
      return "tracking";
    case LocalizationState::kRelocalized:
      return "relocalized";
  }
  return "?";
}

struct Localizer::Impl {
  /// A scan of the relocalization view: its odometry, its pose in the view's own frame (from
  /// matching it against the view's earlier scans) and its points.
  struct ViewScan {
    double t_s = 0.0;
    Pose2 odometry;
    Pose2 T_view_robot;
    ScanPoints points;
  };

  Impl(ProbabilityGrid m, const LocalizerOptions& o)
      : options(o),
        map(std::move(m)),
        slack(with_slack(map)),
        search(slack, o.branch_and_bound_depth, o.unknown_score) {
    const auto box = map.known_box();
    known_lo = map.geometry().center_of(box->min);
    known_hi = map.geometry().center_of(box->max);
  }

  LocalizerOptions options;
  ProbabilityGrid map;
  ProbabilityGrid slack;  // the map with a cell's slack (with_slack)
  BranchAndBoundMatcher search;
  Vec2 known_lo, known_hi;  // the box of the map's known cells: the poses a search tries
  LocalizerStats stats;

  std::optional<Pose2> pose;  // T_map_robot of the last scan, while there is one
  Pose2 last_odometry;
  bool have_odometry = false;
  std::optional<double> unexplained_since_s;  // first scan of the current run of unexplained ones
  /// The last scan with a pose, to compare the next one with: its points, pose and beam spacing.
  struct Previous {
    ScanPoints points;
    Pose2 T_map_robot;
    double beam_rad = 0.0;
  };
  std::optional<Previous> previous;
  /// The scans jumped (a kidnapping?) at since_s, or the pose strayed (max_untrusted_travel_m),
  /// and no global search has placed the robot since: the tracked pose is not trusted, and
  /// searches run as if lost (a stray's only while its scans see the map). before_jump is the
  /// last scan before a jump while a scan agreeing with it again would show a glitch
  /// (max_glitch_s).
  struct Doubt {
    double since_s = 0.0;
    std::optional<Previous> before_jump;
    bool strayed = false;
  };
  std::optional<Doubt> doubt;
  double untrusted_travel_m = 0.0;            // odometry travel since the last confident scan
  std::deque<ViewScan> view;                  // the scans since tracking failed (view_s of them)
  ProbabilityGrid view_grid;                  // the view's scans at their view poses
  std::optional<double> last_search_s;
  Pose2 odometry_at_last_search;    // where the last search saw the view from
  bool last_search_placed = false;  // it left a pose waiting for confirmation (or accepted one)
  /// A match of the view that waits for the next searches to agree with it.
  struct Candidate {
    Pose2 T_map_view;
    int matches = 0;
  };
  std::optional<Candidate> candidate;

  /// Tracks the scan from the prior; fills `out` (state kTracking). Returns whether the map
  /// contradicts the pose: enough of the scan falls on known cells, and those points do not land
  /// on the map's walls.
  bool track(const Pose2& prior, const std::vector<Vec2>& points, LocalizedScan& out) {
    const Pose2 start = match_real_time(map, prior, points, options.tracking).T_grid_robot;
    const RefinedPose refined = refine_scan(map, prior, start, points, options.refiner);
    out.state = LocalizationState::kTracking;
    out.T_map_robot = refined.T_grid_robot;
    out.score = std::clamp(refined.mean_probability, kMinProbability, kMaxProbability);
    out.covariance = covariance_of(refined, points.size());
    const MapFit f = fit_of(out.T_map_robot, points);
    out.map_share = f.map_share;
    out.map_fit = f.fit;
    return f.map_share >= options.min_map_share && f.fit < options.min_tracking_score;
  }

  /// How the map sees points at a pose: the share on known cells and their mean probability, each
  /// point at the best cell within one cell of it (a return lands on its wall's cell or beside
  /// it). A scan that sees beyond the map is not evidence against the pose; one whose points lie
  /// in the map's free space is.
  struct MapFit {
    double map_share = 0.0;
    double fit = 0.0;
  };
  [[nodiscard]] MapFit fit_of(const Pose2& T_map_robot, const std::vector<Vec2>& points) const {
    const GridGeometry& g = map.geometry();
    int known = 0;
    double sum = 0.0;
    for (const Vec2& p : points) {
      const Cell c = g.cell_at_unchecked(T_map_robot * p);
      if (!g.contains(c) || !map.known(c)) continue;
      ++known;
      sum += slack.probability(c);
    }
    if (points.empty()) return {};
    return {static_cast<double>(known) / static_cast<double>(points.size()),
            sum / std::max(known, 1)};
  }

  /// Whether `points` tracked at T_map_robot agree with an earlier scan (scan_agreement.hpp): true
  /// or false when enough returns could be compared, nullopt when too few.
  [[nodiscard]] std::optional<bool> agree(const Previous& earlier, const ScanPoints& points,
                                          const Pose2& T_map_robot) const {
    const ScanAgreement a =
        scan_agreement(earlier.points, points, between(earlier.T_map_robot, T_map_robot),
                       earlier.beam_rad, options.scan_agreement);
    if (a.compared < options.min_scan_compared) return std::nullopt;
    return a.share() >= options.min_scan_agreement;
  }

  /// Adds a scan to the relocalization view. Odometry alone does not join scans well enough (on
  /// the Intel log two scans with the same stamp differ by 3 degrees of odometry heading), so the
  /// view is a small local SLAM: each scan is matched against the view's earlier ones, from the
  /// odometry prior, as local SLAM matches against its submap.
  void add_to_view(double t_s, const Pose2& odometry, ScanPoints points) {
    Pose2 T_view_robot;
    if (!view.empty()) {
      const ViewScan& last = view.back();
      const Pose2 prior = last.T_view_robot * between(last.odometry, odometry);
      T_view_robot = prior;
      if (!points.returns_m.empty()) {
        const Pose2 start =
            match_real_time(view_grid, prior, points.returns_m, options.tracking).T_grid_robot;
        T_view_robot =
            refine_scan(view_grid, prior, start, points.returns_m, options.refiner).T_grid_robot;
      }
    }
    view.push_back({t_s, odometry, T_view_robot, std::move(points)});
    bool dropped = false;
    while (view.size() > 1 && t_s - view.front().t_s > options.view_s) {
      view.pop_front();
      dropped = true;
    }
    const RangeInserter inserter(options.view_insert);
    if (dropped || view.size() == 1) {
      view_grid = view_sized_grid(view.front().T_view_robot.translation());
      for (const ViewScan& v : view) inserter.insert(view_grid, v.T_view_robot, v.points);
    } else {
      inserter.insert(view_grid, view.back().T_view_robot, view.back().points);
    }
  }

  /// The share of a view's free space that the map, with `view_map` at T_map_view, calls wall:
  /// of the view's free cells well inside its free space (all eight neighbours free too, so a
  /// cell's offset along a wall does not count) that fall on cells the map knows, those where
  /// the map is occupied. Seeing through where the map has a wall contradicts a pose even
  /// where every return lands on a wall; a mirrored place in the building does exactly that.
  [[nodiscard]] double free_space_conflict(const ProbabilityGrid& view_map,
                                           const Pose2& T_map_view) const {
    const GridGeometry& v = view_map.geometry();
    const GridGeometry& g = map.geometry();
    const auto free = [&](Cell c) {
      return v.contains(c) && view_map.known(c) && view_map.probability(c) < 0.5f;
    };
    int on_map = 0, conflicts = 0;
    for (int y = 1; y + 1 < v.height(); ++y) {
      for (int x = 1; x + 1 < v.width(); ++x) {
        if (!inside_region_8({x, y}, free)) continue;
        const Cell c = g.cell_at_unchecked(T_map_view * v.center_of({x, y}));
        if (!g.contains(c) || !map.known(c)) continue;
        ++on_map;
        if (map.probability(c) >= 0.6f) ++conflicts;
      }
    }
    return on_map == 0 ? 0.0 : static_cast<double>(conflicts) / static_cast<double>(on_map);
  }

  /// An empty 20 m square at the map's resolution centred on `centre`: room for a view's scans.
  [[nodiscard]] ProbabilityGrid view_sized_grid(const Vec2& centre) const {
    const double res = map.geometry().resolution_m();
    const int side = static_cast<int>(std::ceil(20.0 / res));
    return ProbabilityGrid(GridGeometry({centre.x - 10.0, centre.y - 10.0}, res, side, side));
  }

  /// The newest scan alone as a view: its points and its free space in its own frame.
  [[nodiscard]] ProbabilityGrid newest_scan_grid() const {
    ProbabilityGrid grid = view_sized_grid({0.0, 0.0});
    RangeInserter(options.view_insert).insert(grid, Pose2{}, view.back().points);
    return grid;
  }

  /// The view's points in the frame of its newest scan.
  [[nodiscard]] std::vector<Vec2> view_points() const {
    std::vector<Vec2> all;
    const Pose2 T_now_view = view.back().T_view_robot.inverse();
    for (const ViewScan& s : view) {
      const Pose2 T_now_then = T_now_view * s.T_view_robot;
      for (const Vec2& p : s.points.returns_m) all.push_back(T_now_then * p);
    }
    return all;
  }

  [[nodiscard]] Pose2 search_centre() const {
    return {0.5 * (known_lo.x + known_hi.x), 0.5 * (known_lo.y + known_hi.y), 0.0};
  }
  [[nodiscard]] SearchWindow search_window() const {
    const double res = map.geometry().resolution_m();
    return {0.5 * std::max(known_hi.x - known_lo.x, known_hi.y - known_lo.y) + res, kPi};
  }

  /// How a search for one view ended: no pose good enough, a best pose that does not fit the map
  /// once refined, one that sees through the map's walls, or a pose (yet to be judged against
  /// the other places').
  enum class Outcome { kNoMatch, kUnfit, kSeeThrough, kPlaced };
  /// A searched pose, refined and judged.
  struct Judgement {
    Outcome outcome = Outcome::kNoMatch;
    RefinedPose refined;
    MapFit fit;
  };
  /// A view searched over the whole map: its points, its free space, and its best pose judged.
  struct Placement {
    std::vector<Vec2> search_points, refine_points;
    const ProbabilityGrid* free_view = nullptr;  // the view's grid (its free space)
    Pose2 T_robot_view;                          // the view's frame seen from the newest scan
    ScanMatch best;
    std::vector<ScanMatch> contenders;  // the poses that rival it (RankedMatches)
    Judgement judged;
  };

  /// Judges a searched pose of p's view: refined, does it fit the map, and does the view see
  /// through the map's walls there?
  [[nodiscard]] Judgement judge(const ScanMatch& match, const Placement& p) const {
    Judgement j;
    // The refinement may only polish the searched pose (the loop closer's weak ties).
    j.refined = refine_scan(map, match.T_grid_robot, match.T_grid_robot, p.refine_points,
                            {1.0, 1.0, 1.0, 20});
    const double shift_m =
        (j.refined.T_grid_robot.translation() - match.T_grid_robot.translation()).norm();
    j.fit = fit_of(j.refined.T_grid_robot, p.refine_points);
    if (j.fit.map_share < options.min_map_share || j.fit.fit < options.min_relocalize_score ||
        shift_m > 2.0 * map.geometry().resolution_m()) {
      j.outcome = Outcome::kUnfit;
    } else if (free_space_conflict(*p.free_view, j.refined.T_grid_robot * p.T_robot_view) >
               options.max_free_conflict) {
      j.outcome = Outcome::kSeeThrough;
    } else {
      j.outcome = Outcome::kPlaced;
    }
    return j;
  }

  /// Searches `points` (in the newest scan's frame) over the whole map and a full turn, and
  /// judges the best pose.
  [[nodiscard]] Placement place(const std::vector<Vec2>& points, const ProbabilityGrid& free_view,
                                const Pose2& T_robot_view) const {
    Placement p;
    p.search_points = adaptive_voxel_filter(points, options.search_points);
    p.refine_points = voxel_filter(points, options.refine_voxel_m);
    p.free_view = &free_view;
    p.T_robot_view = T_robot_view;
    std::optional<RankedMatches> ranked = search.match_ranked(
        search_centre(), p.search_points, search_window(), options.min_search_score, rivals());
    if (ranked) {
      p.best = ranked->best;
      p.contenders = std::move(ranked->contenders);
      p.judged = judge(p.best, p);
    }
    return p;
  }

  /// The places that rival the best: scoring at least ambiguity_ratio of its excess over what a
  /// view that sees nothing of the map scores (unknown_score: "the robot is somewhere the map does
  /// not show" is always an answer); runner_up() looks at up to max_runner_ups + 1 of them.
  [[nodiscard]] Rivals rivals() const {
    return {options.unknown_score, options.ambiguity_ratio, options.distinct,
            options.max_runner_ups + 2};
  }

  /// The best pose of any other place than p's that rivals it (from the search's contenders). A
  /// place where the view would see through the map's walls is no rival (it would be refused as
  /// the best pose too): it is passed over for the next (at most max_runner_ups of them). Two
  /// look-alike places that differ in what stands in the open are told apart so. Nullopt when
  /// there is none.
  [[nodiscard]] std::optional<ScanMatch> runner_up(const Placement& p) const {
    ExcludedPoses seen = options.distinct;
    seen.around = {p.best.T_grid_robot};
    const auto elsewhere = [&seen](const ScanMatch& m) { return !seen.contains(m.T_grid_robot); };
    for (int n = 0;; ++n) {
      const auto other = std::find_if(p.contenders.begin(), p.contenders.end(), elsewhere);
      if (other == p.contenders.end()) return std::nullopt;
      if (n == options.max_runner_ups || judge(*other, p).outcome != Outcome::kSeeThrough) {
        return *other;
      }
      seen.around.push_back(other->T_grid_robot);
    }
  }

  /// The global search over the whole map and a full turn; fills `out` when the best pose is
  /// good enough and clearly better than every other place's.
  void relocalize(LocalizedScan& out) {
    const auto t0 = std::chrono::steady_clock::now();
    ++stats.searches;
    // The scans of the view are joined by odometry and matching against each other; where that
    // goes wrong (fast turns, Intel's odometry, or the robot came from where the map does not
    // reach) the joined view fits nowhere although the newest scan fits the map. Then the newest
    // scan alone is searched, and its own free space is what may not see through the map's walls.
    Placement p = place(view_points(), view_grid, view.back().T_view_robot.inverse());
    std::optional<ProbabilityGrid> alone;  // outlives p when p is the newest scan's
    if (p.judged.outcome != Outcome::kPlaced && view.size() > 1) {
      alone = newest_scan_grid();
      Placement q = place(view.back().points.returns_m, *alone, Pose2{});
      if (q.judged.outcome == Outcome::kPlaced) {
        ++stats.newest_scan_only;
        p = std::move(q);
      }
    }
    stats.no_match += p.judged.outcome == Outcome::kNoMatch ? 1 : 0;
    stats.unfit += p.judged.outcome == Outcome::kUnfit ? 1 : 0;
    stats.see_through += p.judged.outcome == Outcome::kSeeThrough ? 1 : 0;
    if (p.judged.outcome == Outcome::kPlaced) {
      // The runner-up: the best pose of any other place, which must score clearly less.
      const std::optional<ScanMatch> other = runner_up(p);
      // The view's frame in the map, as this match places it: the next search must agree.
      const Pose2 T_map_view = p.judged.refined.T_grid_robot * view.back().T_view_robot.inverse();
      bool agrees = false;
      if (!other && candidate) {
        const Pose2 d = between(candidate->T_map_view * view.back().T_view_robot,
                                p.judged.refined.T_grid_robot);
        agrees = std::hypot(d.x, d.y) <= options.agreement.linear_m &&
                 std::abs(d.theta) <= options.agreement.angular_rad;
      }
      if (other) {
        ++stats.ambiguous;
      } else if (agrees) {
        candidate->T_map_view = T_map_view;
        ++candidate->matches;
      } else {
        candidate = Candidate{T_map_view, 1};
      }
      if (!other && candidate->matches < options.confirmations) ++stats.unconfirmed;
      if (!other && candidate->matches >= options.confirmations) {
        ++stats.relocalizations;
        out.state = LocalizationState::kRelocalized;
        out.T_map_robot = p.judged.refined.T_grid_robot;
        out.score = std::clamp(p.judged.refined.mean_probability, kMinProbability, kMaxProbability);
        out.map_share = p.judged.fit.map_share;
        out.map_fit = p.judged.fit.fit;
        out.covariance = covariance_of(p.judged.refined, p.refine_points.size());
      }
    }
    stats.search_s += seconds_since(t0);
  }

  /// Whether a global search is due at this scan: search_every_s of data since the last one (or
  /// none yet, or the stamps went back), and, after a search that placed nothing, a view that has
  /// changed since (the odometry moved by new_view_motion) or max_idle_search_s gone by.
  [[nodiscard]] bool search_due(const StampedScan& scan) const {
    if (!last_search_s || scan.t_s < *last_search_s) return true;
    const double since_s = scan.t_s - *last_search_s;
    if (since_s < options.search_every_s) return false;
    if (last_search_placed || since_s >= options.max_idle_search_s) return true;
    const Pose2 moved = between(odometry_at_last_search, scan.odometry);
    return std::hypot(moved.x, moved.y) >= options.new_view_motion.linear_m ||
           std::abs(moved.theta) >= options.new_view_motion.angular_rad;
  }

  LocalizedScan add_scan(const StampedScan& scan) {
    ++stats.scans;
    LocalizedScan out;
    out.t_s = scan.t_s;
    out.score = kMinProbability;
    ScanPoints points = scan_to_points(scan, options.points);
    const Pose2 increment = have_odometry ? between(last_odometry, scan.odometry) : Pose2{};
    last_odometry = scan.odometry;
    have_odometry = true;

    if (pose && !points.returns_m.empty()) {
      const auto t0 = std::chrono::steady_clock::now();
      const bool contradicted = track(*pose * increment, points.returns_m, out);
      stats.tracking_s += seconds_since(t0);
      pose = out.T_map_robot;
      if (doubt && scan.t_s - doubt->since_s > options.max_glitch_s) doubt->before_jump.reset();
      if (doubt && doubt->before_jump && agree(*doubt->before_jump, points, *pose) == true) {
        // The scans are back where they were before the jump: a bad scan or something that
        // passed close to the sensor, not a kidnapping. The doubt ends.
        ++stats.glitches;
        doubt.reset();
      } else if (previous && agree(*previous, points, *pose) == false) {
        // The scans jumped. The view and the searches start again from this scan: the earlier
        // ones saw elsewhere. The doubt dates from the first jump, and so does its glitch window.
        ++stats.jumps;
        if (!doubt) {
          doubt = Doubt{scan.t_s, previous};
        } else {
          doubt->strayed = false;  // searched wherever the robot now is, map in view or not
        }
        view.clear();
        candidate.reset();
        last_search_s.reset();
      }
      if (!contradicted) {
        unexplained_since_s.reset();
        if (!doubt) {
          view.clear();
          candidate.reset();
        }
      } else if (!unexplained_since_s) {
        unexplained_since_s = scan.t_s;
      }
      if (unexplained_since_s && scan.t_s - *unexplained_since_s >= options.lost_after_s) {
        // The pose stopped explaining the scans: a kidnapping, or the map is not this place.
        pose.reset();
        doubt.reset();
        ++stats.losses;
        out = LocalizedScan{};
        out.t_s = scan.t_s;
        out.score = kMinProbability;
      }
    } else if (pose) {
      pose = *pose * increment;  // nothing to match: odometry carries the pose
      out.state = LocalizationState::kTracking;
      out.T_map_robot = *pose;
    }

    if (!pose || unexplained_since_s || doubt) {
      add_to_view(scan.t_s, scan.odometry, points);
    }
    // A stray's view is searched only while its scans see the map: beyond it every search finds
    // nothing, at the cost of a search over the whole map.
    const bool searchable =
        !pose || (doubt && (!doubt->strayed || out.map_share >= options.min_map_share));
    if (searchable && !view.empty() && search_due(scan)) {
      last_search_s = scan.t_s;
      odometry_at_last_search = scan.odometry;
      relocalize(out);
      last_search_placed = candidate.has_value() || out.state == LocalizationState::kRelocalized;
      if (out.state == LocalizationState::kRelocalized) {
        pose = out.T_map_robot;
        view.clear();
        candidate.reset();
        unexplained_since_s.reset();
        doubt.reset();
      }
    }
    if (out.state != LocalizationState::kLost) ++stats.tracked;
    // Judged on the part of the scan the map knows: a robot that sees much beyond the session's
    // map is placed by the rest as surely (unknown points would drag the mean down to 0.1).
    out.confident = out.state != LocalizationState::kLost && !unexplained_since_s && !doubt &&
                    out.map_share >= options.min_map_share &&
                    out.map_fit >= options.min_confident_fit;
    if (out.confident || !pose) {
      untrusted_travel_m = 0.0;
    } else if (!doubt) {
      untrusted_travel_m += std::hypot(increment.x, increment.y);
      if (untrusted_travel_m > options.max_untrusted_travel_m) {
        // Carried too far on odometry and loose fits to be trusted again without a search.
        ++stats.strays;
        doubt = Doubt{scan.t_s, std::nullopt, true};
        untrusted_travel_m = 0.0;
      }
    }
    if (pose && !points.returns_m.empty()) {
      previous = Previous{std::move(points), *pose, std::abs(scan.scan.angle_increment_rad)};
    } else if (!pose) {
      previous.reset();
    }
    return out;
  }
};

Localizer::Localizer(ProbabilityGrid map, const LocalizerOptions& options) {
  TESSERA_ASSERT(!validate(options));
  TESSERA_ASSERT(map.known_box().has_value());
  impl_ = std::make_unique<Impl>(std::move(map), options);
}

Localizer::~Localizer() = default;

void Localizer::set_pose(const Pose2& T_map_robot) {
  impl_->pose = T_map_robot;
  impl_->view.clear();
  impl_->candidate.reset();
  impl_->unexplained_since_s.reset();
  impl_->previous.reset();
  impl_->doubt.reset();
  impl_->untrusted_travel_m = 0.0;
}

LocalizedScan Localizer::add_scan(const StampedScan& scan) { return impl_->add_scan(scan); }

const LocalizerStats& Localizer::stats() const { return impl_->stats; }

const ProbabilityGrid& Localizer::map() const { return impl_->map; }

ProbabilityGrid frozen_map(const std::vector<const StampedScan*>& scans,
                           const std::vector<Pose2>& T_map_robot, const ScanPointsOptions& points,
                           const RangeInsertOptions& insert, double resolution_m) {
  TESSERA_ASSERT(scans.size() == T_map_robot.size());
  ProbabilityGrid map;
  const RangeInserter inserter(insert);
  for (std::size_t i = 0; i < scans.size(); ++i) {
    const Pose2& T = T_map_robot[i];
    if (map.geometry().width() == 0) {
      // On the lattice of whole cells from the map frame's origin, as LaserSlam's map.
      const int side = static_cast<int>(std::ceil(20.0 / resolution_m));
      map = ProbabilityGrid(GridGeometry({std::floor((T.x - 10.0) / resolution_m) * resolution_m,
                                          std::floor((T.y - 10.0) / resolution_m) * resolution_m},
                                         resolution_m, side, side));
    }
    inserter.insert(map, T, scan_to_points(*scans[i], points));
  }
  return map;
}

ProbabilityGrid frozen_map(const std::vector<StampedScan>& scans, const posegraph::PoseGraph& graph,
                           const std::vector<int>& vertex_scan, const ScanPointsOptions& points,
                           const RangeInsertOptions& insert, double resolution_m) {
  TESSERA_ASSERT(vertex_scan.size() == graph.poses.size());
  std::vector<const StampedScan*> node_scans;
  std::vector<Pose2> node_poses;
  for (std::size_t v = 0; v < vertex_scan.size(); ++v) {
    if (vertex_scan[v] < 0) continue;
    node_scans.push_back(&scans[static_cast<std::size_t>(vertex_scan[v])]);
    node_poses.push_back(graph.poses[v]);
  }
  return frozen_map(node_scans, node_poses, points, insert, resolution_m);
}

}  // namespace tessera::slam
