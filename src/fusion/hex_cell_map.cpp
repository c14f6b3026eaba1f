#include "tessera/fusion/hex_cell_map.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "tessera/core/assert.hpp"

namespace tessera::fusion {
namespace {

// A walk longer than this in one update is cut short (a pose jump of ~30 km at d = 0.3 m); the
// next update continues from where it stopped.
constexpr int kMaxStepsPerUpdate = 100000;

void insert_sorted_unique(std::vector<std::size_t>& v, std::size_t x) {
  const auto it = std::lower_bound(v.begin(), v.end(), x);
  if (it == v.end() || *it != x) v.insert(it, x);
}

bool positive_finite(double v) { return std::isfinite(v) && v > 0.0; }

}  // namespace

std::optional<std::string> validate(const HexCellMapOptions& o) {
  if (!positive_finite(o.cell_radius_m)) {
    return "cell_radius_m must be > 0, got " + std::to_string(o.cell_radius_m);
  }
  if (!positive_finite(o.firing_field_radius_m) ||
      o.firing_field_radius_m > o.cell_radius_m / 2.0) {
    return "firing_field_radius_m must be in (0, cell_radius_m / 2], got " +
           std::to_string(o.firing_field_radius_m);
  }
  if (!positive_finite(o.pose_node_spacing_m)) {
    return "pose_node_spacing_m must be > 0, got " + std::to_string(o.pose_node_spacing_m);
  }
  if (!positive_finite(o.pose_node_overlap_m)) {
    return "pose_node_overlap_m must be > 0, got " + std::to_string(o.pose_node_overlap_m);
  }
  return std::nullopt;
}

HexCellMap::HexCellMap(HexCellMapOptions options)
    : options_(options),
      lattice_(positive_finite(options.cell_radius_m) ? options.cell_radius_m : 0.3) {
  TESSERA_ASSERT(!validate(options_));
}

const HexCell& HexCellMap::cell(std::size_t id) const {
  TESSERA_ASSERT(id < cells_.size());
  return cells_[id];
}

std::size_t HexCellMap::current_cell() const {
  TESSERA_ASSERT(!cells_.empty());
  return current_;
}

std::optional<std::size_t> HexCellMap::find(HexCoord c) const {
  const auto it = by_coord_.find(c);
  if (it == by_coord_.end()) return std::nullopt;
  return it->second;
}

bool HexCellMap::in_firing_field(Vec2 p_m) const {
  if (cells_.empty()) return false;
  return (p_m - cells_[current_].centre_m).norm() < options_.firing_field_radius_m;
}

HexMapUpdate HexCellMap::update(const Pose2& T_map_robot) {
  HexMapUpdate out;
  const Vec2 p = T_map_robot.translation();
  if (cells_.empty()) {
    // The first pose starts the map: pose node 0 and cell 0 centred on it (Algorithm 2, line 7).
    lattice_ = HexGrid(options_.cell_radius_m, p);
    nodes_.push_back({T_map_robot, 0});
    index_node(0);
    last_candidate_m_ = p;
    anchor_node_ = 0;
    HexCell first;
    first.coord = {0, 0};
    first.centre_m = p;
    first.anchor_node = 0;
    first.centre_in_anchor_m = {0.0, 0.0};
    first.rotation_in_anchor_rad = -T_map_robot.theta;
    cells_.push_back(std::move(first));
    by_coord_.emplace(HexCoord{0, 0}, 0);
    current_ = 0;
    out.cell = 0;
    out.entered_cells = {0};
    out.created_cells = {0};
    out.pose_node_added = true;
    out.in_firing_field = in_firing_field(p);
    return out;
  }

  // Section 4.3.2: compare the distance to the current centre with the distances to the six
  // neighbours (existing cells where they are, Table 4.3 offsets where they are not yet); enter
  // the closest while it is closer than the current centre. Every step strictly shortens the
  // distance to p, so the walk ends.
  for (int step = 0; step < kMaxStepsPerUpdate; ++step) {
    const HexCell& cur = cells_[current_];
    double best_d = (p - cur.centre_m).norm();
    int best_k = -1;
    for (int k = 0; k < 6; ++k) {
      const std::optional<std::size_t> id = find(HexGrid::neighbor(cur.coord, k));
      const Vec2 c = id ? cells_[*id].centre_m : neighbor_centre(cur, k);
      const double dist = (p - c).norm();
      if (dist < best_d) {  // strict: a point on a border stays where it is
        best_d = dist;
        best_k = k;
      }
    }
    if (best_k < 0) break;
    const std::size_t before = cells_.size();
    const std::size_t next = enter_neighbor(current_, best_k);
    if (cells_.size() != before) out.created_cells.push_back(next);
    link(current_, next);
    current_ = next;
    out.entered_cells.push_back(next);
  }
  update_pose_nodes(T_map_robot, out);
  out.cell = current_;
  out.in_firing_field = in_firing_field(p);
  return out;
}

Vec2 HexCellMap::neighbor_centre(const HexCell& from, int k) const {
  const Vec2 o = hex_neighbor_offset(k, options_.cell_radius_m);
  if (from.lattice_rotation_rad == 0.0) return from.centre_m + o;  // exactly Table 4.3
  const double c = std::cos(from.lattice_rotation_rad), s = std::sin(from.lattice_rotation_rad);
  return from.centre_m + Vec2{c * o.x - s * o.y, s * o.x + c * o.y};
}

std::size_t HexCellMap::enter_neighbor(std::size_t from, int k) {
  const HexCoord coord = HexGrid::neighbor(cells_[from].coord, k);
  if (const std::optional<std::size_t> id = find(coord)) return *id;
  HexCell c;
  c.coord = coord;
  c.centre_m = neighbor_centre(cells_[from], k);
  c.lattice_rotation_rad = cells_[from].lattice_rotation_rad;
  c.anchor_node = anchor_node_;
  const Pose2& T_map_anchor = nodes_[anchor_node_].T_map_robot;
  c.centre_in_anchor_m = T_map_anchor.inverse() * c.centre_m;
  c.rotation_in_anchor_rad = c.lattice_rotation_rad - T_map_anchor.theta;
  const std::size_t id = cells_.size();
  cells_.push_back(std::move(c));
  by_coord_.emplace(coord, id);
  return id;
}

void HexCellMap::link(std::size_t a, std::size_t b) {
  if (a == b) return;
  insert_sorted_unique(cells_[a].traversed, b);
  insert_sorted_unique(cells_[b].traversed, a);
}

// Algorithm 2, lines 12-34: a candidate every pose_node_spacing_m of travel; stored unless the
// path already passes within pose_node_overlap_m of an existing node.
void HexCellMap::update_pose_nodes(const Pose2& T_map_robot, HexMapUpdate& out) {
  const Vec2 p = T_map_robot.translation();
  if (!((p - last_candidate_m_).norm() > options_.pose_node_spacing_m)) return;
  last_candidate_m_ = p;
  const Cell b = bucket_of(p);
  std::size_t nearest = 0;
  double nearest_d = std::numeric_limits<double>::infinity();
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      const auto it = node_buckets_.find(Cell{b.x + dx, b.y + dy});
      if (it == node_buckets_.end()) continue;
      for (const std::size_t id : it->second) {
        const double dist = (p - nodes_[id].T_map_robot.translation()).norm();
        if (dist < nearest_d || (dist == nearest_d && id < nearest)) {
          nearest_d = dist;
          nearest = id;
        }
      }
    }
  }
  if (nearest_d < options_.pose_node_overlap_m) {
    anchor_node_ = nearest;  // the path overlaps an existing node: new cells hang on that one
    return;
  }
  nodes_.push_back({T_map_robot, current_});
  anchor_node_ = nodes_.size() - 1;
  index_node(anchor_node_);
  out.pose_node_added = true;
}

Cell HexCellMap::bucket_of(Vec2 p_m) const {
  const double s = options_.pose_node_overlap_m;
  return {static_cast<int>(std::floor(p_m.x / s)), static_cast<int>(std::floor(p_m.y / s))};
}

void HexCellMap::index_node(std::size_t id) {
  node_buckets_[bucket_of(nodes_[id].T_map_robot.translation())].push_back(id);
}

std::vector<std::size_t> HexCellMap::geometric_neighbors(std::size_t id) const {
  TESSERA_ASSERT(id < cells_.size());
  std::vector<std::size_t> out;
  for (int k = 0; k < 6; ++k) {
    if (const std::optional<std::size_t> n = find(HexGrid::neighbor(cells_[id].coord, k))) {
      out.push_back(*n);
    }
  }
  return out;
}

CellGraph HexCellMap::graph(CellAdjacency kind) const {
  CellGraph g;
  g.centres_m.reserve(cells_.size());
  g.adjacent.reserve(cells_.size());
  for (std::size_t i = 0; i < cells_.size(); ++i) {
    g.centres_m.push_back(cells_[i].centre_m);
    if (kind == CellAdjacency::kTraversed) {
      g.adjacent.push_back(cells_[i].traversed);
    } else {
      std::vector<std::size_t> n = geometric_neighbors(i);
      std::sort(n.begin(), n.end());
      g.adjacent.push_back(std::move(n));
    }
  }
  return g;
}

void HexCellMap::add_image_node(std::size_t cell, std::size_t image_node_id) {
  TESSERA_ASSERT(cell < cells_.size());
  cells_[cell].image_nodes.push_back(image_node_id);
}

void HexCellMap::move_pose_nodes(std::span<const Pose2> corrected) {
  TESSERA_ASSERT(corrected.size() == nodes_.size());
  if (nodes_.empty()) return;
  // The pending candidate moves rigidly with the node new cells are anchored to.
  const Pose2 correction = corrected[anchor_node_] * nodes_[anchor_node_].T_map_robot.inverse();
  last_candidate_m_ = correction * last_candidate_m_;
  for (std::size_t i = 0; i < nodes_.size(); ++i) nodes_[i].T_map_robot = corrected[i];
  for (HexCell& c : cells_) {
    const Pose2& T_map_anchor = nodes_[c.anchor_node].T_map_robot;
    c.centre_m = T_map_anchor * c.centre_in_anchor_m;
    c.lattice_rotation_rad = normalize_angle(T_map_anchor.theta + c.rotation_in_anchor_rad);
  }
  node_buckets_.clear();
  for (std::size_t i = 0; i < nodes_.size(); ++i) index_node(i);
}

}  // namespace tessera::fusion
