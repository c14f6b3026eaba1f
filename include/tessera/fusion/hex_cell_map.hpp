#pragma once
// The growing hex-cell map of the Fusion SLAM thesis, section 4.3.2 (odometry call-back loop,
// Algorithm 2): grid cells with firing fields, the adjacency the robot traversed, image nodes per
// cell, and the topological path of pose nodes.
//
// - The first pose creates cell 0 centred on it (the thesis starts the map once the first view is
//   good; the caller decides when to call update() the first time).
// - As the robot moves, the distances to the six neighbours of the current cell (Table 4.3,
//   grid/hex_grid.hpp) are compared with the distance to the current centre; when a neighbour is
//   closer the robot "exceeds the boundary of the current segment" and enters it. A neighbour that
//   does not exist yet is created at the current centre plus its Table 4.3 offset. The two cells
//   are stored as adjacent: this TRAVERSED adjacency is what the thesis' wavefront uses
//   (Figure 4.7: a cell knows nothing of mapped cells it was never driven to or from). Geometric
//   adjacency (existing cells that are lattice neighbours) is also available.
// - Firing field: the robot is in the current cell's firing field when it is closer to the centre
//   than firing_field_radius_m; that is when the thesis captures an image node.
// - Pose nodes (Algorithm 2, lines 12-34): when the robot is more than pose_node_spacing_m from the
//   previous candidate it makes a new candidate, which becomes a pose node unless an existing pose
//   node lies within pose_node_overlap_m (the path overlaps one already stored). Thesis: 0.15 m.
// - Drift correction (thesis 6.2 item 2): every cell is anchored to a pose node (the one current
//   when the cell was made) by its centre in that node's frame. After pose-graph optimisation the
//   caller passes the corrected node poses to move_pose_nodes() and every centre moves with its
//   anchor (and turns with it: a neighbour made later is placed along the cell's rotated Table 4.3
//   axes, so a rotated stretch of map keeps growing consistently). Cells keep their lattice
//   coordinate (identity), not their lattice position.
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "tessera/core/cell.hpp"
#include "tessera/core/pose2.hpp"
#include "tessera/core/vec2.hpp"
#include "tessera/grid/cell_graph.hpp"
#include "tessera/grid/hex_grid.hpp"

namespace tessera::fusion {

struct HexCellMapOptions {
  /// The thesis' grid cell radius d: the distance between neighbouring centres (section 4.3.2,
  /// "a radius of 0.3 m produces finer navigational control").
  double cell_radius_m = 0.3;
  /// Firing field: distance to the cell centre below which an image node is captured. The thesis
  /// names a threshold but gives no value; one third of d (0.1 m) is ours.
  double firing_field_radius_m = 0.1;
  /// A new pose-node candidate every pose_node_spacing_m of travel (thesis: 0.15 m).
  double pose_node_spacing_m = 0.15;
  /// A candidate within this distance of an existing pose node is not stored (thesis: 0.15 m).
  double pose_node_overlap_m = 0.15;
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const HexCellMapOptions& o);

/// Which cell pairs count as adjacent in graph().
enum class CellAdjacency {
  kTraversed,  // the robot moved directly between them (the thesis' adjacency, Figure 4.7)
  kGeometric,  // lattice neighbours that both exist, traversed or not
};

struct HexCell {
  HexCoord coord;               // lattice identity, never changes
  Vec2 centre_m;                // map frame; moves with the anchor pose node
  std::size_t anchor_node = 0;  // the pose node the centre is attached to
  Vec2 centre_in_anchor_m;      // centre in the anchor node's frame
  /// Direction of the cell's Table 4.3 axes in the map frame: 0 until a correction rotates the
  /// anchor; new neighbours of this cell are placed along the rotated axes.
  double lattice_rotation_rad = 0.0;
  double rotation_in_anchor_rad = 0.0;   // lattice_rotation_rad minus the anchor node's heading
  std::vector<std::size_t> traversed;    // cells the robot moved to or from, ascending
  std::vector<std::size_t> image_nodes;  // ids of image nodes stored in this cell (caller's ids)
};

struct PoseNode {
  Pose2 T_map_robot;     // map frame
  std::size_t cell = 0;  // the current cell when the node was stored
};

/// What one update() did.
struct HexMapUpdate {
  std::size_t cell = 0;                    // current cell after the update
  std::vector<std::size_t> entered_cells;  // cells entered during this update, in order
  std::vector<std::size_t> created_cells;  // of those, the cells that were new
  bool pose_node_added = false;
  bool in_firing_field = false;
};

class HexCellMap {
 public:
  /// Precondition: !validate(options).
  explicit HexCellMap(HexCellMapOptions options = {});

  [[nodiscard]] const HexCellMapOptions& options() const { return options_; }
  /// The lattice the cells were made on (cell 0's centre at the first pose).
  [[nodiscard]] const HexGrid& lattice() const { return lattice_; }

  /// Feeds one pose of the robot in the map frame (odometry or corrected). Cost: O(cells entered
  /// + pose nodes within pose_node_overlap_m). A jump of several cells is walked cell by cell, so
  /// every step is a traversed adjacency.
  HexMapUpdate update(const Pose2& T_map_robot);

  [[nodiscard]] bool empty() const { return cells_.empty(); }
  [[nodiscard]] std::size_t cell_count() const { return cells_.size(); }
  /// Precondition: id < cell_count().
  [[nodiscard]] const HexCell& cell(std::size_t id) const;
  [[nodiscard]] std::span<const HexCell> cells() const { return cells_; }
  /// Precondition: !empty().
  [[nodiscard]] std::size_t current_cell() const;
  /// The cell with lattice coordinate c, if it exists.
  [[nodiscard]] std::optional<std::size_t> find(HexCoord c) const;

  /// True when p_m is within the firing field of the current cell (false before the first update).
  [[nodiscard]] bool in_firing_field(Vec2 p_m) const;

  /// Existing cells that are lattice neighbours of `id`, in the thesis' neighbour order 0..5.
  [[nodiscard]] std::vector<std::size_t> geometric_neighbors(std::size_t id) const;
  /// Centres and adjacency for navigation. Cost: O(cells).
  [[nodiscard]] CellGraph graph(CellAdjacency kind = CellAdjacency::kTraversed) const;

  /// Stores an image node id in a cell (thesis Algorithm 1, "add image node to grid cell").
  /// Precondition: cell < cell_count().
  void add_image_node(std::size_t cell, std::size_t image_node_id);

  [[nodiscard]] std::span<const PoseNode> pose_nodes() const { return nodes_; }

  /// Drift correction: replaces every pose node's pose (corrected[i] for node i, e.g. after
  /// pose-graph optimisation) and moves each cell centre with its anchor node. The next candidate
  /// spacing is measured from where the last candidate moved to.
  /// Precondition: corrected.size() == pose_nodes().size(). Cost: O(cells + pose nodes).
  void move_pose_nodes(std::span<const Pose2> corrected);

 private:
  std::size_t enter_neighbor(std::size_t from, int k);
  [[nodiscard]] Vec2 neighbor_centre(const HexCell& from, int k) const;
  void link(std::size_t a, std::size_t b);
  void update_pose_nodes(const Pose2& T_map_robot, HexMapUpdate& out);
  [[nodiscard]] Cell bucket_of(Vec2 p_m) const;
  void index_node(std::size_t id);

  HexCellMapOptions options_;
  HexGrid lattice_;
  std::vector<HexCell> cells_;
  std::unordered_map<HexCoord, std::size_t, HexCoordHash> by_coord_;
  std::size_t current_ = 0;

  std::vector<PoseNode> nodes_;
  std::unordered_map<Cell, std::vector<std::size_t>, CellHash> node_buckets_;
  Vec2 last_candidate_m_;
  std::size_t anchor_node_ = 0;  // node new cells are anchored to: the last stored or overlapped
};

}  // namespace tessera::fusion
