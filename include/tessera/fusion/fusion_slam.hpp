#pragma once
// The online Fusion SLAM of the thesis (../shared/seeds/002, section 4.3, Algorithms 1 and 2) with
// the drift correction the thesis lacked (section 6.2 item 2):
//  - the hex-cell map grows with the robot (fusion/hex_cell_map.hpp: cells of radius 0.3 m, the
//    Table 4.3 neighbours, traversed adjacency, firing fields, pose nodes every 0.15 m);
//  - an image node (image_node.hpp) is captured when the robot is in a firing field (once per
//    visit of a field, and again when the camera has turned by recapture_turn_rad within it);
//  - each new image node is matched (node_matcher.hpp) against the stored nodes of the current
//    and the neighbouring cells ("search by cell", section 4.3.1) and the last few stored nodes,
//    those whose camera faces the same way, nearest first (CandidateSearch::kWholeMap takes the
//    cells away, for the ablation in docs/fusion-claims.md);
//  - every accepted match becomes a constraint with a Huber loss in a 2D pose graph
//    (posegraph/pose_graph.hpp) whose other edges are the odometry between consecutive graph nodes;
//    the graph is optimised on every accepted match, and the hex cells, pose nodes and image
//    nodes move with the optimised poses (HexCellMap::move_pose_nodes);
//  - the corrected pose estimate is the last graph node's optimised pose composed with the
//    odometry since that node.
// Frames are only needed where the system uses them: the caller feeds odometry with update() and
// renders or loads a frame only when wants_frame() says so (or to capture on purpose, e.g. at the
// taught goal), then passes it to add_frame(). No I/O, no printing; randomness (the RANSAC
// samples) comes from options.seed.
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "tessera/core/pose2.hpp"
#include "tessera/core/relation.hpp"
#include "tessera/core/rng.hpp"
#include "tessera/core/stamped_pose2.hpp"
#include "tessera/fusion/hex_cell_map.hpp"
#include "tessera/fusion/image_node.hpp"
#include "tessera/fusion/node_matcher.hpp"
#include "tessera/sensors/rgbd_frame.hpp"

namespace tessera::fusion {

/// Where a new image node's match candidates come from.
enum class CandidateSearch {
  /// The thesis' search by cell (4.3.1): the stored nodes of the current and neighbouring cells,
  /// nearest first, and the recent nodes.
  kCells,
  /// As an RGB-D SLAM without cells looks for loop closures (Endres et al. 2014, "3-D mapping
  /// with an RGB-D camera", IEEE T-RO 30(1): the immediate predecessors plus
  /// keyframes sampled at random from the whole graph): the recent nodes plus max_candidates
  /// nodes drawn at random from every stored node. For the ablation of the thesis' claim that
  /// the cells keep ambiguous images out (chapter 6, issue 18 item 11).
  kWholeMap,
};

struct FusionSlamOptions {
  /// The thesis' cells (d = 0.3 m, pose nodes every 0.15 m) with a firing field of d/2 = 0.15 m,
  /// the hexagon's apothem (the thesis gives no value): a robot crossing a cell anywhere near its
  /// middle captures a node, so that consecutive nodes overlap enough to be matched.
  HexCellMapOptions map{.cell_radius_m = 0.3,
                        .firing_field_radius_m = 0.15,
                        .pose_node_spacing_m = 0.15,
                        .pose_node_overlap_m = 0.15};
  ImageNodeOptions node;
  NodeMatcherOptions matcher;
  /// A new pose-graph node after this much travel or turn since the last one (thesis 4.3.2: pose
  /// nodes every 0.15 m). Graph nodes are also made at every capture and every hex pose node.
  double graph_node_spacing_m = 0.15;
  double graph_node_turn_rad = 0.3;
  /// Within one firing-field visit, capture again once the camera has turned this much (so that
  /// a robot turning in place in a cell stores its views all round). Ours.
  double recapture_turn_rad = 0.5;
  /// Match candidates: stored nodes of the current and neighbouring cells whose camera heading
  /// differs from the new node's by at most this (opposite views share no features) ...
  double candidate_max_heading_difference_rad = 0.9;
  /// ... nearest first, at most this many (each match costs two descriptor searches). The last
  /// recent_candidates stored nodes join the pool too (the previous views, wherever their cell).
  int max_candidates = 5;
  int recent_candidates = 6;
  /// kCells: the thesis' firing fields. kWholeMap: the ablation without them (the heading
  /// filter above applies to both, so that only the cells differ).
  CandidateSearch candidate_search = CandidateSearch::kCells;
  /// An accepted match must agree with the current graph within these bounds; the matcher's own
  /// checks come first, this guards against a poster photo that hangs twice nearby. Ours; with
  /// match_gate false every match the matcher accepts is kept, as in the thesis.
  bool match_gate = true;
  double max_match_innovation_m = 1.0;
  double max_match_innovation_rad = 0.5;
  /// Motion out of the plane that a match may show (the camera is level on a flat floor).
  double max_out_of_plane_m = 0.05;
  double max_out_of_plane_rad = 0.05;
  /// Odometry edge standard deviations, growing with the square root of the distance driven and
  /// the angle turned (a random walk; the thesis' drift of about 0.03 rad per metre fits inside).
  double odometry_sigma_xy_m_per_sqrt_m = 0.1;
  double odometry_sigma_theta_rad_per_sqrt_m = 0.05;
  double odometry_sigma_theta_rad_per_sqrt_rad = 0.05;
  /// Match edge standard deviations (the matcher is accurate to about 1 cm and 0.5 degrees on the
  /// real TUM pairs, docs/fusion-results.md).
  double match_sigma_xy_m = 0.01;
  double match_sigma_theta_rad = 0.005;
  /// Huber scale on match edges, in whitened units: quadratic within 3 sigma, linear beyond, so
  /// a wrong match that slipped past the checks bends the graph only a little.
  double huber_scale = 3.0;
  /// Pan neck geometry: the camera sits on the robot's centre, this far above the floor
  /// (thesis 3.1.3).
  double camera_height_m = 1.03;
  std::uint64_t seed = 1;
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const FusionSlamOptions& o);

/// An image node as the SLAM stores it.
struct StoredImageNode {
  ImageNode node;                // node.placement moves with the optimised graph
  std::size_t graph_node = 0;    // the pose-graph node taken at capture
  std::size_t cell = 0;          // hex cell it is stored in
};

/// What update() did.
struct FusionUpdate {
  HexMapUpdate map;
  Pose2 T_map_robot;   // corrected estimate after the update
  bool wants_frame = false;
};

/// Outcome of matching one new node against one stored node.
struct NodeMatchRecord {
  std::size_t stored_node = 0;
  bool accepted = false;
  std::string reason;  // MatchReason text, or "not planar", "inconsistent with the graph"
};

/// What add_frame() did.
struct FusionCapture {
  bool stored = false;            // the frame passed the node checks and was stored
  NodeCheck check = NodeCheck::kOk;
  std::size_t node_id = 0;        // valid when stored
  std::vector<NodeMatchRecord> matches;
  int accepted = 0;
  bool optimised = false;
};

/// Outcome of the image-node search's confirmation step (thesis 4.3.4, 6.2 item 4).
struct NodeConfirmation {
  bool confirmed = false;
  NodeCheck check = NodeCheck::kOk;
  std::string reason;
  /// The robot's pose in the frame of the robot pose the node was taken at (valid if confirmed).
  Pose2 T_node_robot;
};

struct FusionStatistics {
  int frames = 0;
  int frames_rejected = 0;        // failed the node checks
  std::map<std::string, int> node_check_failures;
  int matches_tried = 0;
  int matches_accepted = 0;
  std::map<std::string, int> match_rejections;  // reason -> count
  int optimisations = 0;
};

class FusionSlam {
 public:
  /// Precondition: validate(options) is empty.
  explicit FusionSlam(FusionSlamOptions options = {});

  [[nodiscard]] const FusionSlamOptions& options() const { return options_; }

  /// One odometry reading: T_odom_robot as wheel odometry reports it, the neck's pan angle.
  /// The first call starts the map (cell 0 and graph node 0 at the odometry pose, which defines
  /// the map frame). Precondition: t_s does not decrease. Cost: O(cells entered).
  FusionUpdate update(double t_s, const Pose2& T_odom_robot, double neck_rad);

  /// True when the last update() put the robot in a firing field that wants a capture.
  [[nodiscard]] bool wants_frame() const { return wants_frame_; }

  /// Captures `frame`, taken at the last update()'s pose and neck angle: node checks, matching
  /// against the stored nodes of the current and neighbouring cells and the recent nodes,
  /// pose-graph edges and optimisation. Precondition: update() was called.
  /// Cost: one feature extraction plus up to max_candidates + 1 matches and one optimisation.
  FusionCapture add_frame(const RgbdFrame& frame) { return add_frame(frame, neck_rad_); }
  /// As add_frame(frame), for a frame taken with the neck at neck_rad (a pan scan at a firing
  /// field: the robot's pose is the last update()'s).
  FusionCapture add_frame(const RgbdFrame& frame, double neck_rad);

  /// The confirmation step of the image-node search: matches `frame` (at the last update()'s pose
  /// and neck) against stored node `node_id` only. A confirmed match also becomes a graph
  /// constraint, and the graph is optimised. Precondition: node_id < image_nodes().size().
  NodeConfirmation confirm_node(std::size_t node_id, const RgbdFrame& frame);

  /// Corrected pose estimate (map frame) at the last update().
  [[nodiscard]] Pose2 estimate() const;
  [[nodiscard]] const HexCellMap& map() const { return map_; }
  [[nodiscard]] const std::vector<StoredImageNode>& image_nodes() const { return nodes_; }
  /// Stored image nodes in cell `cell` (ids into image_nodes()).
  [[nodiscard]] std::vector<std::size_t> nodes_in_cell(std::size_t cell) const;
  /// The pose-graph nodes: stamp and optimised pose (the drift-corrected trajectory), and the
  /// odometry pose at each (the same stamps).
  [[nodiscard]] std::vector<StampedPose2> corrected_trajectory() const;
  [[nodiscard]] std::vector<StampedPose2> odometry_trajectory() const;
  [[nodiscard]] const FusionStatistics& statistics() const { return stats_; }
  /// Pose-graph sizes.
  [[nodiscard]] std::size_t graph_nodes() const { return poses_.size(); }
  [[nodiscard]] std::size_t match_edges() const { return match_edges_; }
  /// Every accepted match as the relation it claims (Kummerle et al. 2009): the robot's pose at
  /// the new node's stamp in the frame of its pose at the stored node's stamp, in the order
  /// accepted. Scored against a true trajectory with eval/relation_metric.hpp, it says which
  /// loop closures were wrong.
  [[nodiscard]] std::vector<Relation> match_relations() const;

 private:
  struct GraphNode {
    double t_s = 0.0;
    Pose2 odometry;
  };
  std::size_t add_graph_node();
  /// The graph node of the last update(): the one it made, or a new one at its pose.
  std::size_t current_graph_node() {
    return graph_node_this_update_ ? poses_.size() - 1 : add_graph_node();
  }
  [[nodiscard]] std::optional<Pose2> planar_relative(const ImageNode& prev, const ImageNode& curr,
                                                     const MatchResult& m,
                                                     std::string& reason) const;
  /// The stored nodes a new node at `pose` in `cell` is matched against (options.candidate_search),
  /// at most max_candidates of the cells or recent nodes and, for kWholeMap, as many drawn from
  /// the whole map.
  [[nodiscard]] std::vector<std::size_t> match_candidates(std::size_t cell, std::size_t graph_node,
                                                          const Pose2& pose, double neck_rad);
  void add_match_edge(std::size_t from, std::size_t to, const Pose2& T_from_to);
  bool optimise();
  [[nodiscard]] double camera_heading(const Pose2& T_map_robot, double neck_rad) const {
    return normalize_angle(T_map_robot.theta + neck_rad);
  }

  FusionSlamOptions options_;
  HexCellMap map_;
  Rng rng_;         // RANSAC samples
  Rng sample_rng_;  // kWholeMap's random candidates (its own stream: kCells draws none)

  // Pose graph (posegraph::PoseGraph is built on each optimisation from these).
  std::vector<GraphNode> graph_;
  std::vector<Pose2> poses_;
  struct Edge {
    std::size_t from = 0, to = 0;
    Pose2 measurement;
    bool match = false;
    double sigma_xy_m = 0.0, sigma_theta_rad = 0.0;
  };
  std::vector<Edge> edges_;
  std::size_t match_edges_ = 0;
  std::vector<std::size_t> hex_node_graph_;  // hex pose node i -> graph node

  std::vector<StoredImageNode> nodes_;

  bool started_ = false;
  double t_s_ = 0.0;
  Pose2 odometry_;
  double neck_rad_ = 0.0;
  bool graph_node_this_update_ = false;
  bool wants_frame_ = false;
  std::ptrdiff_t field_cell_ = -1;       // the cell whose firing field the robot is in
  double last_capture_heading_rad_ = 0.0;
  bool captured_in_field_ = false;

  FusionStatistics stats_;
};

}  // namespace tessera::fusion
