#include "tessera/fusion/fusion_slam.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "tessera/core/assert.hpp"
#include "tessera/posegraph/pose_graph.hpp"

namespace tessera::fusion {
namespace {

bool positive(double v) { return std::isfinite(v) && v > 0.0; }

/// T_robot_optical: the camera's optical frame (x right, y down, z forward) on the pan neck at
/// pan angle neck_rad, height_m above the robot's base (sim/rgbd_camera.hpp's geometry).
Eigen::Isometry3d robot_from_optical(double neck_rad, double height_m) {
  Eigen::Matrix3d base_from_optical;
  base_from_optical << 0, 0, 1,  //
      -1, 0, 0,                  //
      0, -1, 0;
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(neck_rad, Eigen::Vector3d::UnitZ()).toRotationMatrix() *
               base_from_optical;
  T.translation() = Eigen::Vector3d(0.0, 0.0, height_m);
  return T;
}

}  // namespace

std::optional<std::string> validate(const FusionSlamOptions& o) {
  if (auto e = validate(o.map)) return "map: " + *e;
  if (auto e = validate(o.node)) return "node: " + *e;
  if (auto e = validate(o.matcher)) return "matcher: " + *e;
  if (!positive(o.graph_node_spacing_m)) return std::string("graph_node_spacing_m must be > 0");
  if (!positive(o.graph_node_turn_rad)) return std::string("graph_node_turn_rad must be > 0");
  if (!positive(o.recapture_turn_rad)) return std::string("recapture_turn_rad must be > 0");
  if (!positive(o.candidate_max_heading_difference_rad)) {
    return std::string("candidate_max_heading_difference_rad must be > 0");
  }
  if (o.max_candidates < 1) return std::string("max_candidates must be >= 1");
  if (o.recent_candidates < 0) return std::string("recent_candidates must be >= 0");
  if (!positive(o.max_match_innovation_m) || !positive(o.max_match_innovation_rad)) {
    return std::string("max_match_innovation_m and _rad must be > 0");
  }
  if (!positive(o.max_out_of_plane_m) || !positive(o.max_out_of_plane_rad)) {
    return std::string("max_out_of_plane_m and _rad must be > 0");
  }
  if (!positive(o.odometry_sigma_xy_m_per_sqrt_m) ||
      !positive(o.odometry_sigma_theta_rad_per_sqrt_m) ||
      !positive(o.odometry_sigma_theta_rad_per_sqrt_rad)) {
    return std::string("odometry sigmas must be > 0");
  }
  if (!positive(o.match_sigma_xy_m) || !positive(o.match_sigma_theta_rad)) {
    return std::string("match sigmas must be > 0");
  }
  if (!positive(o.huber_scale)) return std::string("huber_scale must be > 0");
  if (!std::isfinite(o.camera_height_m)) return std::string("camera_height_m must be finite");
  return std::nullopt;
}

FusionSlam::FusionSlam(FusionSlamOptions options)
    : options_(std::move(options)),
      map_(options_.map),
      rng_(options_.seed),
      sample_rng_(Rng(options_.seed).fork(1)) {
  TESSERA_ASSERT(!validate(options_));
}

Pose2 FusionSlam::estimate() const {
  if (poses_.empty()) return odometry_;
  const std::size_t last = poses_.size() - 1;
  return poses_[last] * between(graph_[last].odometry, odometry_);
}

std::size_t FusionSlam::add_graph_node() {
  const Pose2 pose = estimate();
  const std::size_t id = poses_.size();
  if (id > 0) {
    Edge e;
    e.from = id - 1;
    e.to = id;
    e.measurement = between(graph_[id - 1].odometry, odometry_);
    const double d_m = std::hypot(e.measurement.x, e.measurement.y);
    const double turn_rad = std::abs(e.measurement.theta);
    // Variances grow linearly with distance and turn (a random walk), plus a floor so that a
    // standing robot's edge stays well-conditioned.
    e.sigma_xy_m = std::sqrt(1e-6 + options_.odometry_sigma_xy_m_per_sqrt_m *
                                        options_.odometry_sigma_xy_m_per_sqrt_m * d_m);
    e.sigma_theta_rad = std::sqrt(
        1e-6 +
        options_.odometry_sigma_theta_rad_per_sqrt_m * options_.odometry_sigma_theta_rad_per_sqrt_m *
            d_m +
        options_.odometry_sigma_theta_rad_per_sqrt_rad *
            options_.odometry_sigma_theta_rad_per_sqrt_rad * turn_rad);
    edges_.push_back(e);
  }
  graph_.push_back({t_s_, odometry_});
  poses_.push_back(pose);
  graph_node_this_update_ = true;
  return id;
}

FusionUpdate FusionSlam::update(double t_s, const Pose2& T_odom_robot, double neck_rad) {
  t_s_ = t_s;
  odometry_ = T_odom_robot;
  neck_rad_ = neck_rad;
  graph_node_this_update_ = false;
  if (!started_) {
    started_ = true;
    add_graph_node();
  } else {
    const Pose2 since = between(graph_.back().odometry, odometry_);
    if (std::hypot(since.x, since.y) >= options_.graph_node_spacing_m ||
        std::abs(since.theta) >= options_.graph_node_turn_rad) {
      add_graph_node();
    }
  }
  FusionUpdate out;
  const Pose2 pose = estimate();
  const std::size_t hex_nodes_before = map_.pose_nodes().size();
  out.map = map_.update(pose);
  for (std::size_t i = hex_nodes_before; i < map_.pose_nodes().size(); ++i) {
    if (!graph_node_this_update_) add_graph_node();
    hex_node_graph_.push_back(poses_.size() - 1);
  }
  out.T_map_robot = estimate();

  // Firing field (thesis 4.3.2): one capture per visit of a cell's field, and another once the
  // camera has turned by recapture_turn_rad within it.
  wants_frame_ = false;
  if (out.map.in_firing_field) {
    const double heading = camera_heading(out.T_map_robot, neck_rad);
    if (field_cell_ != static_cast<std::ptrdiff_t>(out.map.cell) || !captured_in_field_) {
      if (field_cell_ != static_cast<std::ptrdiff_t>(out.map.cell)) captured_in_field_ = false;
      field_cell_ = static_cast<std::ptrdiff_t>(out.map.cell);
      wants_frame_ = true;
    } else if (std::abs(normalize_angle(heading - last_capture_heading_rad_)) >=
               options_.recapture_turn_rad) {
      wants_frame_ = true;
    }
  } else {
    field_cell_ = -1;
    captured_in_field_ = false;
  }
  out.wants_frame = wants_frame_;
  return out;
}

std::optional<Pose2> FusionSlam::planar_relative(const ImageNode& prev, const ImageNode& curr,
                                                 const MatchResult& m,
                                                 std::string& reason) const {
  const Eigen::Isometry3d T_rp_rc =
      robot_from_optical(prev.placement.neck_rad, options_.camera_height_m) * m.T_prev_curr *
      robot_from_optical(curr.placement.neck_rad, options_.camera_height_m).inverse();
  const Eigen::Vector3d t = T_rp_rc.translation();
  const Eigen::Matrix3d R = T_rp_rc.linear();
  // Tilt: the angle between the two robots' up axes.
  const double tilt_rad = std::acos(std::clamp(R(2, 2), -1.0, 1.0));
  if (std::abs(t.z()) > options_.max_out_of_plane_m || tilt_rad > options_.max_out_of_plane_rad) {
    reason = "not planar";
    return std::nullopt;
  }
  return Pose2{t.x(), t.y(), normalize_angle(std::atan2(R(1, 0), R(0, 0)))};
}

void FusionSlam::add_match_edge(std::size_t from, std::size_t to, const Pose2& T_from_to) {
  Edge e;
  e.from = from;
  e.to = to;
  e.measurement = T_from_to;
  e.match = true;
  e.sigma_xy_m = options_.match_sigma_xy_m;
  e.sigma_theta_rad = options_.match_sigma_theta_rad;
  edges_.push_back(e);
  ++match_edges_;
}

bool FusionSlam::optimise() {
  posegraph::PoseGraph graph;
  graph.poses = poses_;
  graph.ids.resize(poses_.size());
  for (std::size_t i = 0; i < poses_.size(); ++i) graph.ids[i] = static_cast<int>(i);
  for (const Edge& e : edges_) {
    posegraph::PoseGraphEdge g;
    g.from = static_cast<int>(e.from);
    g.to = static_cast<int>(e.to);
    g.measurement = e.measurement;
    g.information = Eigen::Matrix3d::Zero();
    g.information(0, 0) = g.information(1, 1) = 1.0 / (e.sigma_xy_m * e.sigma_xy_m);
    g.information(2, 2) = 1.0 / (e.sigma_theta_rad * e.sigma_theta_rad);
    g.robust = e.match;
    graph.edges.push_back(g);
  }
  posegraph::OptimizeOptions oo;
  oo.huber_scale = options_.huber_scale;
  oo.fixed_nodes = {0};
  const Result<posegraph::OptimizeSummary> summary = posegraph::optimize(graph, oo);
  if (!summary) return false;
  poses_ = graph.poses;
  ++stats_.optimisations;
  // The cells and nodes move with the optimised poses (thesis 6.2 item 2).
  std::vector<Pose2> hex_poses(hex_node_graph_.size());
  for (std::size_t i = 0; i < hex_node_graph_.size(); ++i) hex_poses[i] = poses_[hex_node_graph_[i]];
  map_.move_pose_nodes(hex_poses);
  for (StoredImageNode& n : nodes_) n.node.placement.T_map_robot = poses_[n.graph_node];
  return true;
}

std::vector<std::size_t> FusionSlam::match_candidates(std::size_t cell, std::size_t graph_node,
                                                      const Pose2& pose, double neck_rad) {
  const double heading = camera_heading(pose, neck_rad);
  // Views taken at this very pose (a neck scan) constrain nothing between poses; opposite views
  // share no features.
  const auto usable = [&](std::size_t id) {
    const NodePlacement& p = nodes_[id].node.placement;
    return nodes_[id].graph_node != graph_node &&
           std::abs(normalize_angle(camera_heading(p.T_map_robot, p.neck_rad) - heading)) <=
               options_.candidate_max_heading_difference_rad;
  };
  const auto distance = [&](std::size_t id) {
    const Pose2& p = nodes_[id].node.placement.T_map_robot;
    return std::hypot(p.x - pose.x, p.y - pose.y);
  };
  // The recent nodes, and for kCells the nodes of the current and neighbouring cells (thesis
  // 4.3.1: search by cell), nearest first.
  std::vector<std::size_t> pool;
  if (options_.candidate_search == CandidateSearch::kCells) {
    std::vector<std::size_t> cells = map_.geometric_neighbors(cell);
    cells.push_back(cell);
    for (std::size_t c : cells) {
      for (std::size_t id : map_.cell(c).image_nodes) pool.push_back(id);
    }
  }
  for (std::size_t k = 0;
       k < static_cast<std::size_t>(options_.recent_candidates) && k < nodes_.size(); ++k) {
    pool.push_back(nodes_.size() - 1 - k);
  }
  std::sort(pool.begin(), pool.end());
  pool.erase(std::unique(pool.begin(), pool.end()), pool.end());
  std::vector<std::pair<double, std::size_t>> ranked;
  for (std::size_t id : pool) {
    if (usable(id)) ranked.emplace_back(distance(id), id);
  }
  std::sort(ranked.begin(), ranked.end());
  const auto max_candidates = static_cast<std::size_t>(options_.max_candidates);
  if (ranked.size() > max_candidates) ranked.resize(max_candidates);
  std::vector<std::size_t> chosen;
  for (const auto& r : ranked) chosen.push_back(r.second);
  if (options_.candidate_search == CandidateSearch::kWholeMap) {
    // Endres et al. 2014: keyframes drawn at random from the whole graph, without replacement.
    std::vector<std::size_t> rest;
    for (std::size_t id = 0; id < nodes_.size(); ++id) {
      if (usable(id) && std::find(chosen.begin(), chosen.end(), id) == chosen.end()) {
        rest.push_back(id);
      }
    }
    for (std::size_t k = 0; k < max_candidates && !rest.empty(); ++k) {
      const auto pick =
          static_cast<std::size_t>(sample_rng_.uniform_int(0, static_cast<int>(rest.size()) - 1));
      chosen.push_back(rest[pick]);
      rest[pick] = rest.back();
      rest.pop_back();
    }
  }
  return chosen;
}

std::vector<Relation> FusionSlam::match_relations() const {
  std::vector<Relation> out;
  for (const Edge& e : edges_) {
    if (e.match) out.push_back({graph_[e.from].t_s, graph_[e.to].t_s, e.measurement});
  }
  return out;
}

FusionCapture FusionSlam::add_frame(const RgbdFrame& frame, double neck_rad) {
  TESSERA_ASSERT(started_);
  FusionCapture out;
  ++stats_.frames;
  const std::size_t cell = map_.current_cell();
  const Pose2 pose = estimate();
  NodePlacement placement{pose, neck_rad, static_cast<std::int64_t>(cell)};
  NodeCreation created = create_image_node(frame, placement, options_.node);
  // A capture in a field counts as done even when the checks fail (the thesis waits for the next
  // field; a robot turning in place tries again after recapture_turn_rad).
  captured_in_field_ = true;
  last_capture_heading_rad_ = camera_heading(pose, neck_rad_);
  wants_frame_ = false;
  out.check = created.check;
  if (!created.ok()) {
    ++stats_.frames_rejected;
    ++stats_.node_check_failures[std::string(to_string(created.check))];
    return out;
  }
  created.node.t_s = t_s_;
  const std::size_t graph_node = current_graph_node();

  const std::vector<std::size_t> chosen = match_candidates(cell, graph_node, pose, neck_rad);
  for (std::size_t id : chosen) {
    const StoredImageNode& stored = nodes_[id];
    ++stats_.matches_tried;
    const MatchResult m = match_nodes(stored.node, created.node, options_.matcher, rng_);
    NodeMatchRecord record{id, false, std::string(to_string(m.reason))};
    if (m.accepted) {
      std::string why;
      const std::optional<Pose2> rel = planar_relative(stored.node, created.node, m, why);
      if (rel) {
        const Pose2 predicted = between(poses_[stored.graph_node], poses_[graph_node]);
        const Pose2 innovation = between(predicted, *rel);
        if (options_.match_gate &&
            (std::hypot(innovation.x, innovation.y) > options_.max_match_innovation_m ||
             std::abs(innovation.theta) > options_.max_match_innovation_rad)) {
          record.reason = "inconsistent with the graph";
        } else {
          record.accepted = true;
          add_match_edge(stored.graph_node, graph_node, *rel);
        }
      } else {
        record.reason = why;
      }
    }
    if (record.accepted) {
      ++out.accepted;
      ++stats_.matches_accepted;
    } else {
      ++stats_.match_rejections[record.reason];
    }
    out.matches.push_back(record);
  }

  const std::size_t id = nodes_.size();
  nodes_.push_back({std::move(created.node), graph_node, cell});
  map_.add_image_node(cell, id);
  out.stored = true;
  out.node_id = id;
  if (out.accepted > 0) out.optimised = optimise();
  return out;
}

NodeConfirmation FusionSlam::confirm_node(std::size_t node_id, const RgbdFrame& frame) {
  TESSERA_ASSERT(started_ && node_id < nodes_.size());
  NodeConfirmation out;
  const Pose2 pose = estimate();
  NodePlacement placement{pose, neck_rad_, static_cast<std::int64_t>(map_.current_cell())};
  const NodeCreation created = create_image_node(frame, placement, options_.node);
  out.check = created.check;
  if (!created.ok()) {
    out.reason = std::string(to_string(created.check));
    return out;
  }
  const StoredImageNode& stored = nodes_[node_id];
  ++stats_.matches_tried;
  const MatchResult m = match_nodes(stored.node, created.node, options_.matcher, rng_);
  out.reason = std::string(to_string(m.reason));
  if (!m.accepted) {
    ++stats_.match_rejections[out.reason];
    return out;
  }
  std::string why;
  const std::optional<Pose2> rel = planar_relative(stored.node, created.node, m, why);
  if (!rel) {
    out.reason = why;
    ++stats_.match_rejections[out.reason];
    return out;
  }
  ++stats_.matches_accepted;
  out.confirmed = true;
  out.T_node_robot = *rel;
  const std::size_t graph_node = current_graph_node();
  if (stored.graph_node != graph_node) {
    add_match_edge(stored.graph_node, graph_node, *rel);
    optimise();
  }
  return out;
}

std::vector<std::size_t> FusionSlam::nodes_in_cell(std::size_t cell) const {
  return map_.cell(cell).image_nodes;
}

std::vector<StampedPose2> FusionSlam::corrected_trajectory() const {
  std::vector<StampedPose2> out(poses_.size());
  for (std::size_t i = 0; i < poses_.size(); ++i) out[i] = {graph_[i].t_s, poses_[i]};
  return out;
}

std::vector<StampedPose2> FusionSlam::odometry_trajectory() const {
  std::vector<StampedPose2> out(graph_.size());
  for (std::size_t i = 0; i < graph_.size(); ++i) out[i] = {graph_[i].t_s, graph_[i].odometry};
  return out;
}

}  // namespace tessera::fusion
