#include "tessera/slam/submap_trimmer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "tessera/core/assert.hpp"
#include "tessera/grid/cell_region.hpp"
#include "tessera/grid/grid_geometry.hpp"
#include "tessera/grid/ray_cast.hpp"

namespace tessera::slam {
namespace {

/// A node's rays in the map frame: the sensor's origin and the end of every return and miss.
struct NodeRays {
  int scan = 0;
  int trajectory = 0;
  Vec2 origin_m;
  std::vector<Vec2> ends_m;
};

/// Per scan: its trajectory, counted by the starts at or before it (0 before the first start).
std::vector<int> trajectory_of_scans(std::size_t scans,
                                     const std::vector<TrajectoryStart>& starts) {
  std::vector<int> out(scans, 0);
  std::size_t t = 0;
  for (std::size_t i = 0; i < scans; ++i) {
    while (t < starts.size() && static_cast<std::size_t>(starts[t].first_scan) <= i) ++t;
    out[i] = static_cast<int>(t);
  }
  return out;
}

/// The coverage grid: every ray end and origin inside it.
GridGeometry coverage_geometry(const std::vector<NodeRays>& nodes, double cell_m) {
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0;
  double x1 = -x0, y1 = -x0;
  const auto extend = [&](Vec2 p) {
    x0 = std::min(x0, p.x);
    y0 = std::min(y0, p.y);
    x1 = std::max(x1, p.x);
    y1 = std::max(y1, p.y);
  };
  for (const NodeRays& n : nodes) {
    extend(n.origin_m);
    for (const Vec2 e : n.ends_m) extend(e);
  }
  if (!(x0 <= x1)) return GridGeometry({0.0, 0.0}, cell_m, 0, 0);
  return GridGeometry({x0 - cell_m, y0 - cell_m}, cell_m,
                      static_cast<int>(std::ceil((x1 - x0) / cell_m)) + 3,
                      static_cast<int>(std::ceil((y1 - y0) / cell_m)) + 3);
}

/// Calls visit(index) for every cell a node's rays pass through or end in (a cell once per ray).
template <typename Visit>
void for_each_observed_cell(const GridGeometry& g, const NodeRays& n, Visit&& visit) {
  for (const Vec2 end : n.ends_m) {
    traverse_ray(g, n.origin_m, end, [&](Cell c, double, double) { visit(g.index_of(c)); });
  }
}

}  // namespace

SubmapTrim trim_covered_submaps(const std::vector<StampedScan>& scans,
                                const std::vector<StampedPose2>& trajectory,
                                const std::vector<TrajectoryStart>& starts,
                                const posegraph::PoseGraph& graph,
                                const std::vector<int>& vertex_scan,
                                const SubmapTrimOptions& options) {
  TESSERA_ASSERT(trajectory.size() == scans.size() && vertex_scan.size() == graph.poses.size() &&
                 options.cell_m > 0.0);
  const int newest = static_cast<int>(starts.size());
  const std::vector<int> trajectory_of = trajectory_of_scans(scans.size(), starts);
  SubmapTrim out;

  // Nodes and their rays; submaps and the nodes inserted into them.
  std::vector<int> node_of_vertex(vertex_scan.size(), -1);
  std::vector<NodeRays> nodes;
  for (std::size_t v = 0; v < vertex_scan.size(); ++v) {
    if (vertex_scan[v] < 0) continue;
    const StampedScan& s = scans[static_cast<std::size_t>(vertex_scan[v])];
    const Pose2& T = graph.poses[v];
    const ScanPoints points = scan_to_points(s, options.points);
    NodeRays n{vertex_scan[v],
               trajectory_of[static_cast<std::size_t>(vertex_scan[v])],
               T * points.origin_m,
               {}};
    n.ends_m.reserve(points.returns_m.size() + points.misses_m.size());
    for (const Vec2 p : points.returns_m) n.ends_m.push_back(T * p);
    for (const Vec2 p : points.misses_m) n.ends_m.push_back(T * p);
    node_of_vertex[v] = static_cast<int>(nodes.size());
    nodes.push_back(std::move(n));
  }
  std::vector<int> submap_of_vertex(vertex_scan.size(), -1);
  std::vector<std::vector<int>> members;  // per submap: its nodes
  for (std::size_t v = 0; v < vertex_scan.size(); ++v) {
    if (vertex_scan[v] >= 0) continue;
    submap_of_vertex[v] = static_cast<int>(members.size());
    members.emplace_back();
  }
  std::vector<std::vector<int>> submaps_of_node(nodes.size());
  for (const posegraph::PoseGraphEdge& e : graph.edges) {
    const int submap = submap_of_vertex[static_cast<std::size_t>(e.from)];
    const int node = node_of_vertex[static_cast<std::size_t>(e.to)];
    if (e.robust || submap < 0 || node < 0) continue;
    members[static_cast<std::size_t>(submap)].push_back(node);
    submaps_of_node[static_cast<std::size_t>(node)].push_back(submap);
  }
  out.submaps = static_cast<int>(members.size());
  out.nodes = static_cast<int>(nodes.size());

  // Each cell belongs to the newest trajectory that observed it.
  const GridGeometry g = coverage_geometry(nodes, options.cell_m);
  std::vector<std::int32_t> newest_seen(g.size(), -1);
  for (const NodeRays& n : nodes) {
    for_each_observed_cell(g, n, [&](std::size_t i) {
      newest_seen[i] = std::max(newest_seen[i], static_cast<std::int32_t>(n.trajectory));
    });
  }

  // A submap of an earlier trajectory is kept while enough of what it saw is its own, or a
  // patch of it.
  std::vector<char> submap_kept(members.size(), 1);
  std::vector<std::int32_t> counted_by(g.size(), -1);
  std::vector<std::int32_t> fresh_of(g.size(), -1);
  std::vector<std::size_t> fresh_cells;
  const double cell_area_m2 = options.cell_m * options.cell_m;
  for (std::size_t m = 0; m < members.size(); ++m) {
    if (members[m].empty()) continue;
    const int t = nodes[static_cast<std::size_t>(members[m].front())].trajectory;
    if (t == newest) continue;
    const auto id = static_cast<std::int32_t>(m);
    std::size_t observed = 0;
    fresh_cells.clear();
    for (const int node : members[m]) {
      for_each_observed_cell(g, nodes[static_cast<std::size_t>(node)], [&](std::size_t i) {
        if (counted_by[i] == id) return;
        counted_by[i] = id;
        ++observed;
        if (newest_seen[i] == t) {
          fresh_of[i] = id;
          fresh_cells.push_back(i);
        }
      });
    }
    // Fresh cells inside patches: all 8 neighbours fresh in this submap too.
    const auto fresh_here = [&](Cell c) { return g.contains(c) && fresh_of[g.index_of(c)] == id; };
    std::size_t inside = 0;
    for (const std::size_t i : fresh_cells)
      inside += inside_region_8(g.cell_of(i), fresh_here) ? 1 : 0;
    const double share =
        observed == 0 ? 0.0
                      : static_cast<double>(fresh_cells.size()) / static_cast<double>(observed);
    const double area_m2 = static_cast<double>(inside) * cell_area_m2;
    out.fresh_shares.push_back(share);
    out.fresh_areas_m2.push_back(area_m2);
    if (share < options.min_fresh_share && area_m2 < options.min_fresh_area_m2) {
      submap_kept[m] = 0;
      ++out.submaps_trimmed;
    }
  }

  // A node is kept with any of its submaps (always in the newest trajectory), and a scan with
  // the node it was placed from: the last node at or before it in its trajectory.
  std::vector<int> node_of_scan(scans.size(), -1);
  std::vector<char> node_kept(nodes.size(), 1);
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    node_of_scan[static_cast<std::size_t>(nodes[k].scan)] = static_cast<int>(k);
    if (nodes[k].trajectory == newest || submaps_of_node[k].empty()) continue;
    node_kept[k] = std::any_of(submaps_of_node[k].begin(), submaps_of_node[k].end(), [&](int m) {
      return submap_kept[static_cast<std::size_t>(m)] != 0;
    });
    if (node_kept[k] == 0) ++out.nodes_trimmed;
  }
  // The session's own first scan needs a start only when the session placed it (a trimmed
  // session's): otherwise it starts where its odometry puts it, as it did.
  const bool placed_first = !starts.empty() && starts.front().first_scan == 0;
  int previous_trajectory = -1;
  bool anchor_kept = true;
  for (int i = 0; i < static_cast<int>(scans.size()); ++i) {
    const int t = trajectory_of[static_cast<std::size_t>(i)];
    if (t != previous_trajectory) anchor_kept = true;  // before its first node: kept
    if (const int node = node_of_scan[static_cast<std::size_t>(i)]; node >= 0) {
      anchor_kept = node_kept[static_cast<std::size_t>(node)] != 0;
    }
    if (anchor_kept || t == newest) {
      // A new trajectory begins at a trajectory's start and after a gap.
      const bool continues =
          !out.kept_scans.empty() && out.kept_scans.back() == i - 1 && t == previous_trajectory;
      const int index = static_cast<int>(out.kept_scans.size());
      if (!continues && (i > 0 || placed_first)) {
        out.starts.push_back({index, trajectory[static_cast<std::size_t>(i)].pose});
      }
      out.kept_scans.push_back(i);
    }
    previous_trajectory = t;
  }
  return out;
}

Result<TrimmedRun> trim_and_replay(const LaserLog& log, const std::vector<TrajectoryStart>& starts,
                                   const LaserSlamResult& result, const LaserSlamOptions& options,
                                   const SubmapTrimOptions& trim_options) {
  TrimmedRun out;
  out.trim = trim_covered_submaps(log.scans, result.trajectory, starts, result.graph,
                                  result.vertex_scan, trim_options);
  if (out.trim.kept_scans.size() == log.scans.size()) return out;  // nothing to replay
  out.log.backward_stamps = log.backward_stamps;
  out.log.scans.reserve(out.trim.kept_scans.size());
  for (const int i : out.trim.kept_scans) {
    out.log.scans.push_back(log.scans[static_cast<std::size_t>(i)]);
  }
  Result<LaserSlamResult> replayed = run_laser_slam(out.log, options, out.trim.starts);
  if (!replayed) return replayed.error();
  out.result = std::move(replayed).value();
  return out;
}

}  // namespace tessera::slam
