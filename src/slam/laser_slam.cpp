// The laser SLAM pipeline (Hess et al. 2016, Sec. IV-V): local SLAM matches every scan against the
// active submap; kept scans become pose-graph nodes tied to the submaps they went into; finished
// submaps are searched for older and newer nodes (loop closure); Ceres optimises the graph at fixed
// node counts and once more at the end.
#include "tessera/slam/laser_slam.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <queue>
#include <string>

#include "tessera/core/rng.hpp"

namespace tessera::slam {
namespace {

constexpr double kPi = 3.14159265358979323846;

Eigen::Matrix3d information_of(const ConstraintSigmas& s) {
  Eigen::Matrix3d info = Eigen::Matrix3d::Zero();
  info(0, 0) = info(1, 1) = 1.0 / (s.translation_m * s.translation_m);
  info(2, 2) = 1.0 / (s.rotation_rad * s.rotation_rad);
  return info;
}

/// Sigmas `base` grown by `per_m` for each metre of `distance_m`.
ConstraintSigmas grown(const ConstraintSigmas& base, const ConstraintSigmas& per_m,
                       double distance_m) {
  return {base.translation_m + per_m.translation_m * distance_m,
          base.rotation_rad + per_m.rotation_rad * distance_m};
}

std::optional<std::string> validate(const ConstraintSigmas& s, const std::string& name) {
  if (!(s.translation_m > 0.0) || !(s.rotation_rad > 0.0)) {
    return name + ": sigmas must be > 0";
  }
  return std::nullopt;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// The share of points_robot that land on known cells of `grid` with the robot at T_grid_robot.
double known_fraction(const ProbabilityGrid& grid, const Pose2& T_grid_robot,
                      const std::vector<Vec2>& points_robot) {
  if (points_robot.empty()) return 0.0;
  const GridGeometry& g = grid.geometry();
  int known = 0;
  for (const Vec2& p : points_robot) {
    const Cell c = g.cell_at_unchecked(T_grid_robot * p);
    if (g.contains(c) && grid.known(c)) ++known;
  }
  return static_cast<double>(known) / static_cast<double>(points_robot.size());
}

/// Cartographer's FixedRatioSampler: says yes to a share `ratio` of the calls, evenly spread.
class FixedRatioSampler {
 public:
  bool pulse(double ratio) {
    ++pulses_;
    if (static_cast<double>(samples_) < ratio * static_cast<double>(pulses_)) {
      ++samples_;
      return true;
    }
    return false;
  }

 private:
  long pulses_ = 0;
  long samples_ = 0;
};

}  // namespace

std::optional<std::string> validate(const LaserSlamOptions& o) {
  if (auto p = validate(o.points)) return "points." + *p;
  if (!(o.matching_voxel_m >= 0.0)) return "matching_voxel_m must be >= 0";
  if (auto p = validate(o.submaps)) return "submaps." + *p;
  if (auto p = validate(o.motion_filter)) return "motion_filter." + *p;
  if (auto p = validate(o.real_time)) return "real_time." + *p;
  if (auto p = validate(o.real_time_without_odometry)) return "real_time_without_odometry." + *p;
  if (auto p = validate(o.refiner)) return "refiner." + *p;
  if (auto p = validate(o.odometry_calibration)) return "odometry_calibration." + *p;
  if (auto p = validate(o.loop_closer)) return "loop_closer." + *p;
  if (!(o.loop_min_overlap >= 0.0 && o.loop_min_overlap <= 1.0)) {
    return "loop_min_overlap must be in [0, 1]";
  }
  if (!(o.loop_sampling_ratio > 0.0 && o.loop_sampling_ratio <= 1.0)) {
    return "loop_sampling_ratio must be in (0, 1]";
  }
  if (!(o.global_sampling_ratio >= 0.0 && o.global_sampling_ratio <= 1.0)) {
    return "global_sampling_ratio must be in [0, 1]";
  }
  if (!(o.global_min_score > kMinProbability && o.global_min_score < kMaxProbability)) {
    return "global_min_score must be in (0.1, 0.9)";
  }
  if (!(o.global_window.linear_m >= 0.0) || !(o.global_window.angular_rad >= 0.0)) {
    return "global_window must be >= 0";
  }
  if (!(o.loop_window_growth_m_per_m >= 0.0) || !(o.loop_window_growth_rad_per_m >= 0.0)) {
    return "loop_window_growth_* must be >= 0";
  }
  if (!(o.loop_window_max.linear_m >= o.loop_closer.window.linear_m) ||
      !(o.loop_window_max.angular_rad >= o.loop_closer.window.angular_rad)) {
    return "loop_window_max must be at least loop_closer.window";
  }
  if (!(o.verify_beyond >= 1.0)) return "verify_beyond must be >= 1";
  if (o.verify_span_nodes < 1) return "verify_span_nodes must be >= 1";
  if (!(o.verify_tolerance.linear_m > 0.0) || !(o.verify_tolerance.angular_rad > 0.0)) {
    return "verify_tolerance must be > 0";
  }
  if (!(o.loop_outlier_sigmas >= 0.0)) return "loop_outlier_sigmas must be >= 0";
  if (!(o.wrong_closure_share >= 0.0 && o.wrong_closure_share <= 1.0)) {
    return "wrong_closure_share must be in [0, 1]";
  }
  if (o.final_map_passes < 0 || !(o.final_map_hessian_scale >= 0.0)) {
    return "final_map_passes and final_map_hessian_scale must be >= 0";
  }
  if (auto p = validate(o.final_map_refiner)) return "final_map_refiner." + *p;
  if (o.optimize_every_n_nodes < 1) return "optimize_every_n_nodes must be >= 1";
  if (o.optimizer_iterations < 1) return "optimizer_iterations must be >= 1";
  if (auto p = validate(o.local_sigmas, "local_sigmas")) return p;
  if (!(o.local_sigmas_per_m.translation_m >= 0.0) || !(o.local_sigmas_per_m.rotation_rad >= 0.0)) {
    return "local_sigmas_per_m must be >= 0";
  }
  if (auto p = validate(o.submap_sigmas, "submap_sigmas")) return p;
  if (auto p = validate(o.loop_sigmas, "loop_sigmas")) return p;
  if (!(o.loop_hessian_scale >= 0.0)) return "loop_hessian_scale must be >= 0";
  if (!(o.huber_scale > 0.0)) return "huber_scale must be > 0";
  if (auto p = validate(o.start_sigmas, "start_sigmas")) return p;
  if (!(o.map_resolution_m > 0.0)) return "map_resolution_m must be > 0";
  if (auto p = validate(o.map_insert)) return "map_insert." + *p;
  if (auto p = validate(o.wall_direction)) return "wall_direction." + *p;
  if (o.manhattan && !(o.manhattan_sigma_rad > 0.0 && o.manhattan_rotation_weight >= 0.0 &&
                       o.manhattan_gate_rad >= 0.0)) {
    return "manhattan_sigma_rad must be > 0, manhattan_rotation_weight and manhattan_gate_rad >= 0";
  }
  return std::nullopt;
}

struct LaserSlam::Impl {
  struct ScanRecord {
    double t_s = 0.0;
    int anchor_node = 0;  // the last node at or before this scan
    Pose2 T_local_robot;
  };
  struct Node {
    int scan = 0;
    int vertex = 0;
    Pose2 T_local_robot;
    ScanPoints points;              // for the final map
    std::vector<Vec2> loop_points;  // for loop-closure searches
    std::vector<int> submaps;       // the submaps it was inserted into
    double travel_m = 0.0;          // local SLAM's path length up to this node
  };
  struct SubmapRecord {
    int vertex = 0;
    bool finished = false;
    Vec2 box_lo_m, box_hi_m;  // known cells, submap frame
    double travel_first_m = 0.0;  // path length at its first node
    FixedRatioSampler sampler;
    FixedRatioSampler global_sampler;
  };

  explicit Impl(const LaserSlamOptions& o)
      : options(o),
        submaps(o.submaps),
        filter(o.motion_filter),
        closer(o.loop_closer),
        loop_information(information_of(o.loop_sigmas)),
        wrong_closures(o.wrong_closure_seed),
        calibration(o.odometry_calibration) {}

  LaserSlamOptions options;
  ActiveSubmaps submaps;
  MotionFilter filter;
  LoopCloser closer;
  Eigen::Matrix3d loop_information;
  Rng wrong_closures;  // draws for wrong_closure_share

  posegraph::PoseGraph graph;
  /// options.manhattan: the building's axis in the local-SLAM frame, once a scan has shown it.
  std::optional<double> axis_local_rad;
  std::vector<int> vertex_scan;
  std::vector<Node> nodes;
  std::vector<SubmapRecord> submap_records;
  std::vector<ScanRecord> scans;
  Pose2 last_odometry;
  Pose2 last_T_local;
  OdometryCalibration calibration;
  double last_t_s = 0.0;
  /// The last scan's step from the one before it (use_odometry off).
  Pose2 last_step;
  /// start_trajectory's pose for the next scan, and the id of the first submap of the current
  /// trajectory (submaps of different trajectories are not joined by the path).
  // (A flag and a plain pose: see MotionFilter on GCC 12's false maybe-uninitialized.)
  bool has_pending_start = false;
  Pose2 pending_start;
  int trajectory_first_submap = 0;
  int nodes_since_optimization = 0;
  int loop_constraints_since_optimization = 0;
  std::uint64_t poses_version = 0;  // counts optimisations: node poses change only there
  // build_map()'s grid of nodes [0, map_cache_nodes) at the poses of map_cache_version.
  mutable ProbabilityGrid map_cache;
  mutable std::size_t map_cache_nodes = 0;
  mutable std::uint64_t map_cache_version = 0;
  double travel_m = 0.0;          // local SLAM's path length over the nodes so far
  /// Submaps joined by the path (consecutive ones, weighted by the travel between their first
  /// nodes) and by accepted loop closures (weighted by the travel from the node to its submap):
  /// the shortest way between two submaps is the path along which drift can have grown.
  std::vector<std::vector<std::pair<int, double>>> submap_links;
  /// Shortest distances from the submap being searched to every submap (one Dijkstra per node
  /// or finished submap; a few dozen vertices).
  std::vector<double> link_distance_m;
  /// A wide-window match waiting for another one to agree with it.
  struct Candidate {
    int node = 0;
    int submap = 0;
    LoopMatch match;
    Pose2 correction;  // T_global_global': where the match moves the node's current estimate
  };
  std::vector<Candidate> candidates;
  LaserSlamStats stats;

  int add_vertex(const Pose2& T_global, int scan) {
    const int v = static_cast<int>(graph.poses.size());
    graph.poses.push_back(T_global);
    graph.ids.push_back(v);
    vertex_scan.push_back(scan);
    return v;
  }

  /// Global pose of the local-SLAM frame as the latest optimisation sees it (through the newest
  /// node).
  [[nodiscard]] Pose2 local_to_global() const {
    if (nodes.empty()) return {};
    const Node& last = nodes.back();
    return graph.poses[static_cast<std::size_t>(last.vertex)] * last.T_local_robot.inverse();
  }

  [[nodiscard]] const Pose2& global_pose(int vertex) const {
    return graph.poses[static_cast<std::size_t>(vertex)];
  }

  void link_submaps(int a, int b, double weight_m) {
    submap_links[static_cast<std::size_t>(a)].emplace_back(b, weight_m);
    submap_links[static_cast<std::size_t>(b)].emplace_back(a, weight_m);
  }

  /// Fills link_distance_m with the shortest distances over submap_links from `from`.
  void compute_link_distances(int from) {
    link_distance_m.assign(submap_links.size(), std::numeric_limits<double>::infinity());
    using Item = std::pair<double, int>;
    std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
    link_distance_m[static_cast<std::size_t>(from)] = 0.0;
    open.emplace(0.0, from);
    while (!open.empty()) {
      const auto [d, v] = open.top();
      open.pop();
      if (d > link_distance_m[static_cast<std::size_t>(v)]) continue;
      for (const auto& [w, weight] : submap_links[static_cast<std::size_t>(v)]) {
        const double nd = d + weight;
        if (nd < link_distance_m[static_cast<std::size_t>(w)]) {
          link_distance_m[static_cast<std::size_t>(w)] = nd;
          open.emplace(nd, w);
        }
      }
    }
  }

  /// The path along which local SLAM's drift between a node and a submap can have grown: from
  /// the node to one of its own submaps, then the shortest way through submap_links (which loop
  /// closures shorten). link_distance_m must hold the distances from that submap.
  [[nodiscard]] double uncertain_path_m(const Node& node) const {
    double best = std::numeric_limits<double>::infinity();
    for (const int h : node.submaps) {
      const double to_home =
          std::abs(node.travel_m - submap_records[static_cast<std::size_t>(h)].travel_first_m);
      best = std::min(best, to_home + link_distance_m[static_cast<std::size_t>(h)]);
    }
    return std::isfinite(best) ? best : travel_m;
  }

  [[nodiscard]] SearchWindow window_for(double path_m) const {
    const SearchWindow& base = options.loop_closer.window;
    return {std::min(base.linear_m + options.loop_window_growth_m_per_m * path_m,
                     options.loop_window_max.linear_m),
            std::min(base.angular_rad + options.loop_window_growth_rad_per_m * path_m,
                     options.loop_window_max.angular_rad)};
  }

  void add_loop_constraint(int node_index, int submap_id, const LoopMatch& match,
                           const Pose2& guess) {
    const Node& node = nodes[static_cast<std::size_t>(node_index)];
    const SubmapRecord& record = submap_records[static_cast<std::size_t>(submap_id)];
    const Pose2 correction = between(guess, match.T_submap_robot);
    stats.max_loop_correction_m =
        std::max(stats.max_loop_correction_m, std::hypot(correction.x, correction.y));
    stats.max_loop_correction_rad =
        std::max(stats.max_loop_correction_rad, std::abs(correction.theta));
    Eigen::Matrix3d information = loop_information;
    if (options.loop_hessian_scale > 0.0) {
      // Plus a floor of 1 m / 1 rad sigma so that the matrix stays positive definite.
      information = options.loop_hessian_scale * match.hessian + Eigen::Matrix3d::Identity();
    }
    Pose2 T_submap_robot = match.T_submap_robot;
    if (options.wrong_closure_share > 0.0 &&
        wrong_closures.uniform(0.0, 1.0) < options.wrong_closure_share) {
      const double direction = wrong_closures.uniform(-kPi, kPi);
      const double distance_m = wrong_closures.uniform(1.0, 4.0);
      const double turn_rad = wrong_closures.uniform(0.2, 1.0) * (direction < 0.0 ? -1.0 : 1.0);
      T_submap_robot = T_submap_robot * Pose2{distance_m * std::cos(direction),
                                              distance_m * std::sin(direction), turn_rad};
      T_submap_robot.theta = normalize_angle(T_submap_robot.theta);
      ++stats.loop_wrong_injected;
    }
    graph.edges.push_back({record.vertex, node.vertex, T_submap_robot, information, true});
    ++stats.loop_closures;
    ++loop_constraints_since_optimization;
    for (const int h : node.submaps) {
      link_submaps(h, submap_id,
                   std::abs(node.travel_m -
                            submap_records[static_cast<std::size_t>(h)].travel_first_m));
    }
  }

  /// A wide-window match is kept as a candidate until another candidate of a nearby node implies
  /// the same correction of the estimate; then both become constraints.
  void verify_candidate(int node_index, int submap_id, const LoopMatch& match, const Pose2& guess) {
    ++stats.loop_candidates;
    const Node& node = nodes[static_cast<std::size_t>(node_index)];
    const SubmapRecord& record = submap_records[static_cast<std::size_t>(submap_id)];
    Candidate c{node_index, submap_id, match,
                global_pose(record.vertex) * match.T_submap_robot *
                    global_pose(node.vertex).inverse()};
    const Vec2 at = global_pose(node.vertex).translation();
    std::vector<Candidate> kept;
    bool confirmed = false;
    for (Candidate& other : candidates) {
      if (std::abs(other.node - node_index) > options.verify_span_nodes) {
        ++stats.loop_unverified;
        continue;
      }
      const Vec2 a = other.correction * at;
      const Vec2 b = c.correction * at;
      const bool agrees = other.node != node_index &&
                          (a - b).norm() <= options.verify_tolerance.linear_m &&
                          std::abs(normalize_angle(other.correction.theta - c.correction.theta)) <=
                              options.verify_tolerance.angular_rad;
      if (agrees) {
        const SubmapRecord& r = submap_records[static_cast<std::size_t>(other.submap)];
        const Node& n = nodes[static_cast<std::size_t>(other.node)];
        add_loop_constraint(other.node, other.submap, other.match,
                            between(global_pose(r.vertex), global_pose(n.vertex)));
        confirmed = true;
      } else {
        kept.push_back(std::move(other));
      }
    }
    candidates = std::move(kept);
    if (confirmed) {
      add_loop_constraint(node_index, submap_id, match, guess);
    } else {
      candidates.push_back(std::move(c));
    }
  }

  /// Searches submap `submap_id` for node `node_index` if the node lies within the submap's known
  /// box (grown by the search window) and the sampler picks the pair; adds a robust constraint on
  /// success, or a candidate for verification when the window had to be wide.
  void maybe_close_loop(int node_index, int submap_id, double path_m) {
    Node& node = nodes[static_cast<std::size_t>(node_index)];
    SubmapRecord& record = submap_records[static_cast<std::size_t>(submap_id)];
    if (std::find(node.submaps.begin(), node.submaps.end(), submap_id) != node.submaps.end()) {
      return;
    }
    const SearchWindow window = window_for(path_m);
    const bool wide = window.linear_m > options.verify_beyond * options.loop_closer.window.linear_m;
    const Pose2 guess = between(global_pose(record.vertex), global_pose(node.vertex));
    const double margin = window.linear_m;
    if (guess.x < record.box_lo_m.x - margin || guess.x > record.box_hi_m.x + margin ||
        guess.y < record.box_lo_m.y - margin || guess.y > record.box_hi_m.y + margin) {
      return;
    }
    // Only pairs that overlap: enough of the scan, placed at the estimate, falls on cells the
    // submap knows. Cheap (one look-up per point) and it spares most hopeless searches. A wide
    // window is searched because the estimate may be far off, so it skips this test.
    const ProbabilityGrid& grid = submaps.submap(submap_id).grid();
    if (!wide && known_fraction(grid, guess, node.loop_points) < options.loop_min_overlap) return;
    if (!record.sampler.pulse(options.loop_sampling_ratio)) return;
    ++stats.loop_searches;
    std::optional<LoopMatch> match = closer.match(submap_id, grid, guess, node.loop_points,
                                                  node.points.returns_m, window,
                                                  options.loop_closer.min_score);
    bool global = false;
    if (!match && options.global_sampling_ratio > 0.0 &&
        record.global_sampler.pulse(options.global_sampling_ratio)) {
      ++stats.global_searches;
      match = closer.match(submap_id, grid, guess, node.loop_points, node.points.returns_m,
                           options.global_window, options.global_min_score);
      global = true;
    }
    if (!match) return;
    if (wide || global) {
      verify_candidate(node_index, submap_id, *match, guess);
    } else {
      add_loop_constraint(node_index, submap_id, *match, guess);
    }
  }

  void on_submap_finished(int submap_id) {
    SubmapRecord& record = submap_records[static_cast<std::size_t>(submap_id)];
    record.finished = true;
    const ProbabilityGrid& grid = submaps.submap(submap_id).grid();
    if (const auto box = grid.known_box()) {
      const GridGeometry& g = grid.geometry();
      record.box_lo_m = g.center_of(box->min);
      record.box_hi_m = g.center_of(box->max);
    }
    if (!options.loop_closure) return;
    closer.add_submap(submap_id, grid);
    // Older nodes that may see this submap (Cartographer's constraints for old nodes).
    compute_link_distances(submap_id);
    for (int k = 0; k < static_cast<int>(nodes.size()); ++k) {
      maybe_close_loop(k, submap_id, uncertain_path_m(nodes[static_cast<std::size_t>(k)]));
    }
  }

  /// Removes the loop constraints the optimised graph disagrees with by more than
  /// loop_outlier_sigmas (whitened residual); returns how many.
  int switch_off_outliers() {
    if (options.loop_outlier_sigmas <= 0.0) return 0;
    const double gate = options.loop_outlier_sigmas * options.loop_outlier_sigmas;
    const std::size_t before = graph.edges.size();
    std::erase_if(graph.edges, [&](const posegraph::PoseGraphEdge& e) {
      if (!e.robust) return false;
      const Pose2 error = between(between(global_pose(e.from), global_pose(e.to)), e.measurement);
      const Eigen::Vector3d r(error.x, error.y, error.theta);
      return r.dot(e.information * r) > gate;
    });
    const int removed = static_cast<int>(before - graph.edges.size());
    stats.loop_rejected += removed;
    return removed;
  }

  /// What every optimisation of the graph is run with.
  [[nodiscard]] posegraph::OptimizeOptions optimizer_options() const {
    posegraph::OptimizeOptions o;
    o.max_iterations = options.optimizer_iterations;
    o.huber_scale = options.huber_scale;
    return o;
  }

  /// `last`: the final optimisation, the only one after which outliers are switched off (earlier,
  /// a correct closure after a long drift can still be far from a graph that has not yet taken
  /// it in).
  Status optimize_graph(bool last) {
    const auto t0 = std::chrono::steady_clock::now();
    const posegraph::OptimizeOptions o = optimizer_options();
    ++poses_version;  // every node may move: the map cache starts again
    Result<posegraph::OptimizeSummary> summary = posegraph::optimize(graph, o);
    if (summary && last && switch_off_outliers() > 0) summary = posegraph::optimize(graph, o);
    stats.optimization_s += seconds_since(t0);
    if (!summary) return summary.error();
    ++stats.optimizations;
    nodes_since_optimization = 0;
    loop_constraints_since_optimization = 0;
    return Ok{};
  }

  Status add_scan(const StampedScan& scan, int scans_total) {
    const auto t0 = std::chrono::steady_clock::now();
    const int scan_index = static_cast<int>(scans.size());
    ScanPoints points = scan_to_points(scan, options.points);
    const std::vector<Vec2> matching = voxel_filter(points.returns_m, options.matching_voxel_m);
    const std::optional<WallDirection> wall = manhattan_wall(points);

    // Prior: the last pose moved by the odometry increment (file order, whatever the stamps). The
    // first scan of a new trajectory is where start_trajectory() put it, in the local frame as
    // the graph now places it.
    const bool starts_trajectory = has_pending_start;
    // The odometry's step since the last scan (the robot frame of the last scan).
    const Pose2 odometry_step = between(last_odometry, scan.odometry);
    Pose2 T_local = options.use_odometry ? scan.odometry : Pose2{};
    if (starts_trajectory) {
      T_local = local_to_global().inverse() * pending_start;
      has_pending_start = false;
    } else if (scan_index > 0) {
      if (scan.t_s < last_t_s) ++stats.backward_stamps;
      T_local = options.use_odometry ? last_T_local * calibration.corrected(odometry_step)
                                     : last_T_local * last_step;
    }
    T_local = matched_in_submap(T_local, matching, wall);
    if (starts_trajectory) {
      calibration.break_segment();
    } else if (options.use_odometry && scan_index > 0) {
      calibration.observe(odometry_step, between(last_T_local, T_local));
    }
    if (wall && !axis_local_rad) axis_local_rad = T_local.theta + wall->angle_rad;
    last_odometry = scan.odometry;
    last_step = starts_trajectory || scan_index == 0 ? Pose2{} : between(last_T_local, T_local);
    last_T_local = T_local;
    last_t_s = scan.t_s;

    if (filter.is_similar(scan.t_s, T_local)) {
      scans.push_back({scan.t_s, static_cast<int>(nodes.size()) - 1, T_local});
      stats.matching_s += seconds_since(t0);
      report(scan_index + 1, scans_total);
      return Ok{};
    }

    // A new node: insert into the active submaps and tie it into the graph.
    const Pose2 correction = local_to_global();
    const int submaps_before = submaps.size();
    const ActiveSubmaps::Insertion insertion = submaps.insert(points, T_local);
    // The step from the previous node: it lengthens the path and loosens the local constraints
    // (a scan matched a metre after the last one is less certain than one matched 0.2 m after it).
    const double step_m =
        nodes.empty() || starts_trajectory
            ? 0.0
            : (T_local.translation() - nodes.back().T_local_robot.translation()).norm();
    travel_m += step_m;
    for (int id = submaps_before; id < submaps.size(); ++id) {
      SubmapRecord record;
      record.travel_first_m = travel_m;
      record.vertex = add_vertex(correction * submaps.submap(id).local_pose(), -1);
      submap_links.emplace_back();
      if (id > trajectory_first_submap) {
        link_submaps(id - 1, id,
                     travel_m - submap_records[static_cast<std::size_t>(id - 1)].travel_first_m);
      }
      submap_records.push_back(record);
    }
    Node node;
    node.scan = scan_index;
    node.vertex = add_vertex(correction * T_local, scan_index);
    node.T_local_robot = T_local;
    node.travel_m = travel_m;
    node.loop_points = adaptive_voxel_filter(points.returns_m, options.loop_points);
    if (wall) add_heading_prior(node.vertex, *wall);
    node.points = std::move(points);
    node.submaps = insertion.inserted_into;
    const Eigen::Matrix3d submap_information =
        information_of(grown(options.submap_sigmas, options.local_sigmas_per_m, step_m));
    for (const int id : insertion.inserted_into) {
      graph.edges.push_back({submap_records[static_cast<std::size_t>(id)].vertex, node.vertex,
                             between(submaps.submap(id).local_pose(), T_local), submap_information,
                             false});
    }
    if (starts_trajectory && !nodes.empty()) {
      tie_to_nearest_node(node);
    } else if (!nodes.empty()) {
      const Node& previous = nodes.back();
      graph.edges.push_back(
          {previous.vertex, node.vertex, between(previous.T_local_robot, T_local),
           information_of(grown(options.local_sigmas, options.local_sigmas_per_m, step_m)), false});
    }
    nodes.push_back(std::move(node));
    scans.push_back({scan.t_s, static_cast<int>(nodes.size()) - 1, T_local});
    ++nodes_since_optimization;
    stats.matching_s += seconds_since(t0);

    const auto t_loop = std::chrono::steady_clock::now();
    if (insertion.finished) on_submap_finished(*insertion.finished);
    if (options.loop_closure) {
      const int k = static_cast<int>(nodes.size()) - 1;
      const Node& newest = nodes.back();
      const int home = newest.submaps.back();
      compute_link_distances(home);
      const double to_home =
          newest.travel_m - submap_records[static_cast<std::size_t>(home)].travel_first_m;
      for (int id = 0; id < submaps.size(); ++id) {
        if (submap_records[static_cast<std::size_t>(id)].finished) {
          maybe_close_loop(k, id, to_home + link_distance_m[static_cast<std::size_t>(id)]);
        }
      }
    }
    stats.loop_search_s += seconds_since(t_loop);

    if (nodes_since_optimization >= options.optimize_every_n_nodes &&
        loop_constraints_since_optimization > 0) {
      if (Status s = optimize_graph(false); !s) return s;
    }
    report(scan_index + 1, scans_total);
    return Ok{};
  }

  /// Local SLAM's match (Hess et al. 2016 Sec. IV): the scan searched around its prediction
  /// T_local in the matching submap, then refined; the prediction itself when there is no submap
  /// yet or no point to match.
  Pose2 matched_in_submap(const Pose2& T_local, const std::vector<Vec2>& matching,
                          const std::optional<WallDirection>& wall) {
    const std::optional<int> id = submaps.matching_id();
    if (!id || matching.empty()) return T_local;
    const Submap& submap = submaps.submap(*id);
    const Pose2 predicted = between(submap.local_pose(), T_local);
    Pose2 start = predicted;
    if (options.real_time_search) {
      start = match_real_time(
                  submap.grid(), predicted, matching,
                  options.use_odometry ? options.real_time : options.real_time_without_odometry)
                  .T_grid_robot;
    }
    // Without odometry the refinement is tied to the predicted position but to the searched
    // heading (Cartographer's local matching does the same): the constant-velocity guess holds
    // along a corridor, where the walls do not say where the robot is, but a turn's rate
    // changes from scan to scan (decision 0034).
    const Pose2 prior =
        options.use_odometry ? predicted : Pose2{predicted.x, predicted.y, start.theta};
    const RefinedPose refined = refine_scan(submap.grid(), prior, start, matching, options.refiner,
                                            manhattan_heading(wall, submap, start));
    return submap.local_pose() * refined.T_grid_robot;
  }

  /// The scan's dominant wall direction when options.manhattan (wall_direction.hpp).
  [[nodiscard]] std::optional<WallDirection> manhattan_wall(const ScanPoints& points) const {
    if (!options.manhattan) return std::nullopt;
    return dominant_wall_direction(points.returns_m, points.return_beams, options.wall_direction);
  }

  /// The heading (submap frame) that puts the scan's walls along the local axis, the nearest such
  /// to the search's result, when it is within the gate (options.manhattan).
  std::optional<HeadingTarget> manhattan_heading(const std::optional<WallDirection>& wall,
                                                 const Submap& submap,
                                                 const Pose2& T_grid_robot_start) {
    if (!wall || !axis_local_rad || !(options.manhattan_rotation_weight > 0.0)) return std::nullopt;
    constexpr double kQuarter = 0.5 * std::numbers::pi;
    const double aligned = *axis_local_rad - wall->angle_rad - submap.local_pose().theta;
    const double off = aligned - T_grid_robot_start.theta;
    const double folded = off - kQuarter * std::round(off / kQuarter);
    if (std::abs(folded) > options.manhattan_gate_rad) return std::nullopt;
    ++stats.manhattan_pulls;
    return HeadingTarget{T_grid_robot_start.theta + folded, options.manhattan_rotation_weight};
  }

  /// The Manhattan prior of a node whose scan shows a dominant wall direction; the first one
  /// sets the building's axis where that node's walls point.
  void add_heading_prior(int vertex, const WallDirection& wall) {
    if (graph.heading_priors.empty()) {
      graph.axis_rad = normalize_angle(global_pose(vertex).theta + wall.angle_rad);
    }
    graph.heading_priors.push_back({vertex, wall.angle_rad, options.manhattan_sigma_rad});
    ++stats.manhattan_priors;
  }

  /// The first node of a new trajectory: a constraint to the nearest node of the earlier ones,
  /// where start_trajectory() placed it, and its submaps joined to that node's as if by a loop
  /// closure, so that the loop searches around it start from a small window.
  void tie_to_nearest_node(const Node& node) {
    const Vec2 at = global_pose(node.vertex).translation();
    const Node* nearest = &nodes.front();
    for (const Node& n : nodes) {
      if ((global_pose(n.vertex).translation() - at).norm() <
          (global_pose(nearest->vertex).translation() - at).norm()) {
        nearest = &n;
      }
    }
    graph.edges.push_back({nearest->vertex, node.vertex,
                           between(global_pose(nearest->vertex), global_pose(node.vertex)),
                           information_of(options.start_sigmas), false});
    for (const int a : nearest->submaps) {
      for (const int b : node.submaps) link_submaps(a, b, 0.0);
    }
  }

  /// Ends the trajectory so far, as finish() and start_trajectory() both do. The submaps still
  /// open have been matched only by the nodes inserted into them; finishing them searches them
  /// for every older node too, as every other submap was searched when it finished, so a loop
  /// that closes at the end of a log is found from both sides (decision 0013: ACES seed 3 at
  /// 0.3 deg/m, 0.263 -> 0.192 m). Then the final optimisation.
  Status end_trajectory() {
    if (nodes.empty()) return Ok{};
    for (const int id : submaps.finish_all()) on_submap_finished(id);
    if (stats.loop_closures > 0 || !graph.heading_priors.empty()) return optimize_graph(true);
    return Ok{};
  }

  /// One pass of options.final_map_passes: every node refined in the map of all nodes at their
  /// current poses (build_map()'s grid, the one the user gets), tied there (to a vertex of the
  /// map's frame, free to move), and the graph optimised with those ties; the first node stays
  /// where it is (a start pose given for it, start_trajectory, holds exactly).
  /// The ties live in a copy of the graph: held to a fixed frame, they would pin the nodes where
  /// this map puts them against the loop closures of a trajectory resumed later.
  Status match_against_whole_map() {
    const auto t0 = std::chrono::steady_clock::now();
    const ProbabilityGrid& map = probability_map();
    posegraph::PoseGraph tied = graph;
    const int map_vertex = static_cast<int>(tied.poses.size());
    tied.poses.push_back(Pose2{});
    tied.ids.push_back(map_vertex);
    for (const Node& node : nodes) {
      const std::vector<Vec2> matching =
          voxel_filter(node.points.returns_m, options.matching_voxel_m);
      if (matching.empty()) continue;
      const Pose2& T = global_pose(node.vertex);
      const RefinedPose refined = refine_scan(map, T, T, matching, options.final_map_refiner);
      const Eigen::Matrix3d information =
          options.final_map_hessian_scale * refined.hessian + Eigen::Matrix3d::Identity();
      tied.edges.push_back({map_vertex, node.vertex, refined.T_grid_robot, information, false});
    }
    posegraph::OptimizeOptions o = optimizer_options();
    o.fixed_nodes = {nodes.front().vertex};
    ++poses_version;
    const auto t_optimize = std::chrono::steady_clock::now();
    stats.whole_map_s += seconds_since(t0);
    Result<posegraph::OptimizeSummary> summary = posegraph::optimize(tied, o);
    stats.optimization_s += seconds_since(t_optimize);
    if (!summary) return summary.error();
    tied.poses.pop_back();
    graph.poses = std::move(tied.poses);
    graph.axis_rad = tied.axis_rad;
    return Ok{};
  }

  Status start_trajectory(const Pose2& T_map_robot) {
    if (Status s = end_trajectory(); !s) return s;
    has_pending_start = true;
    pending_start = T_map_robot;
    trajectory_first_submap = submaps.size();
    filter.reset();
    return Ok{};
  }

  void report(int done, int total) const {
    if (!options.progress) return;
    SlamProgress p;
    p.scans_done = done;
    p.scans_total = total;
    p.nodes = static_cast<int>(nodes.size());
    p.submaps = submaps.size();
    p.loop_closures = stats.loop_closures;
    options.progress(p);
  }

  // Every node's points inserted at its current global pose, in node order. A node's global pose
  // changes only in an optimisation, so between two the map only grows by the nodes added since
  // the last call: those are inserted into a kept grid, which gives the very map a full rebuild
  // gives (the same insertions in the same order) at the cost of the new nodes only. A live
  // robot asks for its map every half second; a rebuild each time cost it most of a core.
  OccupancyGrid build_map() const { return probability_map().to_occupancy_grid(2); }

  /// build_map()'s probabilities (the kept grid, brought up to date).
  const ProbabilityGrid& probability_map() const {
    if (map_cache_version != poses_version) {
      map_cache = ProbabilityGrid{};
      map_cache_nodes = 0;
      map_cache_version = poses_version;
    }
    RangeInserter inserter(options.map_insert);
    ProbabilityGrid& map = map_cache;
    for (; map_cache_nodes < nodes.size(); ++map_cache_nodes) {
      const Node& node = nodes[map_cache_nodes];
      const Pose2& T = global_pose(node.vertex);
      if (map.geometry().width() == 0) {
        const double res = options.map_resolution_m;
        // On the lattice of whole cells from the map frame's origin, so that a map at the
        // resolution of a ground-truth world built on that lattice compares cell by cell.
        map = ProbabilityGrid(GridGeometry({std::floor((T.x - 10.0) / res) * res,
                                            std::floor((T.y - 10.0) / res) * res},
                                           res,
                                           static_cast<int>(std::ceil(20.0 / res)),
                                           static_cast<int>(std::ceil(20.0 / res))));
      }
      inserter.insert(map, T, node.points);
    }
    return map;
  }

  // The pose of scan `i` under the current graph: its anchor node's global pose and the local
  // motion since that node.
  Pose2 scan_pose(std::size_t i) const {
    const ScanRecord& s = scans[i];
    const Node& anchor = nodes[static_cast<std::size_t>(s.anchor_node)];
    return global_pose(anchor.vertex) * between(anchor.T_local_robot, s.T_local_robot);
  }

  Result<LaserSlamResult> finish() {
    if (Status s = end_trajectory(); !s) return s.error();
    // Once, at the very end: a session resumed over many trajectories replays them all first.
    // Local SLAM alone (no loop closure) stays local: the pass corrects the graph as a closure
    // does.
    const int passes = options.loop_closure ? options.final_map_passes : 0;
    for (int pass = 0; pass < passes && !nodes.empty(); ++pass) {
      if (Status s = match_against_whole_map(); !s) return s.error();
    }
    LaserSlamResult out = result();
    out.graph = std::move(graph);
    out.vertex_scan = std::move(vertex_scan);
    return out;
  }

  /// Trajectory, map and statistics under the graph as it is; the graph itself is left to the
  /// caller (finish() moves it out, snapshot() copies it).
  LaserSlamResult result() const {
    LaserSlamResult out;
    out.trajectory.reserve(scans.size());
    out.local_trajectory.reserve(scans.size());
    for (std::size_t i = 0; i < scans.size(); ++i) {
      out.trajectory.push_back({scans[i].t_s, scan_pose(i)});
      out.local_trajectory.push_back({scans[i].t_s, scans[i].T_local_robot});
    }

    const auto t_map = std::chrono::steady_clock::now();
    out.map = build_map();

    out.stats = stats;
    out.stats.map_s = seconds_since(t_map);
    out.stats.scans = static_cast<int>(scans.size());
    out.stats.nodes = static_cast<int>(nodes.size());
    out.stats.submaps = submaps.size();
    out.stats.odometry_translation_scale = calibration.translation_scale();
    out.stats.odometry_rotation_scale = calibration.rotation_scale();
    out.stats.odometry_drift_rad_per_m = calibration.drift_rad_per_m();
    return out;
  }
};

LaserSlam::LaserSlam(const LaserSlamOptions& options) : impl_(std::make_unique<Impl>(options)) {
  TESSERA_ASSERT(!validate(options));
}

LaserSlam::~LaserSlam() = default;

Status LaserSlam::add_scan(const StampedScan& scan, int scans_total) {
  return impl_->add_scan(scan, scans_total);
}

Status LaserSlam::start_trajectory(const Pose2& T_map_robot) {
  return impl_->start_trajectory(T_map_robot);
}

Pose2 LaserSlam::latest_pose() const {
  TESSERA_ASSERT(!impl_->scans.empty());
  return impl_->scan_pose(impl_->scans.size() - 1);
}

OccupancyGrid LaserSlam::current_map() const { return impl_->build_map(); }

LaserSlamResult LaserSlam::snapshot() const {
  TESSERA_ASSERT(!impl_->scans.empty());
  LaserSlamResult out = impl_->result();
  out.graph = impl_->graph;
  out.vertex_scan = impl_->vertex_scan;
  return out;
}

Result<LaserSlamResult> LaserSlam::finish() {
  if (impl_->scans.empty()) return input_error("laser SLAM: no scans");
  return impl_->finish();
}

Result<LaserSlamResult> run_laser_slam(const LaserLog& log, const LaserSlamOptions& options,
                                       const std::vector<TrajectoryStart>& starts,
                                       const AfterScan& after_scan) {
  if (auto problem = validate(options)) return usage_error("laser SLAM options: " + *problem);
  if (log.scans.empty()) return input_error("laser SLAM: the log has no scans");
  const int total = static_cast<int>(log.scans.size());
  for (std::size_t k = 0; k < starts.size(); ++k) {
    const int first = starts[k].first_scan;
    if (first < 0 || first >= total || (k > 0 && first <= starts[k - 1].first_scan)) {
      return input_error("laser SLAM: trajectory start " + std::to_string(k + 1) + " is at scan " +
                         std::to_string(first) + "; expected scans 0-" + std::to_string(total - 1) +
                         " in increasing order");
    }
  }
  LaserSlam slam(options);
  auto next_start = starts.begin();
  for (int i = 0; i < total; ++i) {
    if (next_start != starts.end() && next_start->first_scan == i) {
      if (Status s = slam.start_trajectory(next_start->T_map_robot); !s) return s.error();
      ++next_start;
    }
    if (Status s = slam.add_scan(log.scans[static_cast<std::size_t>(i)], total); !s) {
      return s.error();
    }
    if (after_scan) {
      if (Status s = after_scan(slam, i + 1); !s) return s.error();
    }
  }
  return slam.finish();
}

}  // namespace tessera::slam
