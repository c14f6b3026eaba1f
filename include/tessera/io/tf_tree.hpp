#pragma once
// The transforms of a bag's /tf and /tf_static as tf2 keeps them (tf2::BufferCore): a tree of
// frames, each child with one parent. A static transform holds at all times and a later static
// transform of the same child replaces it (tf2's static cache keeps only the last one); dynamic
// transforms are a time series per child. Frame names are compared without a leading '/'
// (ROS 1 bags of the tf1 era write "/base_link").
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "tessera/core/pose2.hpp"
#include "tessera/core/result.hpp"
#include "tessera/io/ros_messages.hpp"

namespace tessera {

/// The planar part of a 3D transform: x, y and the yaw (rotation about z) of the quaternion.
[[nodiscard]] Pose2 planar_pose(const RosTransform& T);

/// A 2D laser's pose as the planar pipeline takes it (T_base_laser): its planar pose, and whether
/// it is mounted upside down (its z axis points down, as a laser hung under a plate: seen from
/// above, its beams turn clockwise, so its scans are taken mirrored, range_scan.hpp's mirrored()).
/// The yaw is the heading of the laser's x axis either way.
struct PlanarLaser {
  Pose2 T_base_laser;
  bool upside_down = false;
};
[[nodiscard]] PlanarLaser planar_laser(const RosTransform& T_base_laser);

/// "base_link" for "/base_link" and "base_link".
[[nodiscard]] std::string_view tf_frame_name(std::string_view frame);

class TfTree {
 public:
  /// Adds T_parent_child (parent = header.frame_id, child = child_frame_id) at header.stamp.
  void add(const TransformStampedMessage& t, bool is_static);

  /// T_target_source at time t_ns: composes the edges from source up to the nearest common
  /// ancestor and down to target. A dynamic edge is interpolated between its samples just before
  /// and after t_ns (linear in translation, normalised linear in the quaternion), and clamped to
  /// its first or last sample outside them. kInput error naming both frames when no chain of
  /// transforms connects them. Cost: O(depth * log samples).
  [[nodiscard]] Result<RosTransform> lookup(std::string_view target, std::string_view source,
                                            std::int64_t t_ns) const;

  /// The lowest moving (dynamic) edge at or above `frame`: going up from `frame`, the first edge
  /// that /tf moves, with its samples T_parent_child in time order. In a robot's tf tree that is
  /// odom -> base (the base driver's odometry; a localizer's map -> odom sits above it). Nullopt
  /// when every edge up from `frame` is static, or `frame` is not in the tree.
  struct MovingEdge {
    std::string parent, child;
    std::vector<std::pair<std::int64_t, RosTransform>> T_parent_child;  // (stamp ns, transform)
  };
  [[nodiscard]] std::optional<MovingEdge> lowest_moving_edge(std::string_view frame) const;

  /// Every frame that appears as a parent or a child, sorted (for error messages).
  [[nodiscard]] std::vector<std::string> frames() const;

 private:
  struct Sample {
    std::int64_t t_ns = 0;
    RosTransform T_parent_child;
  };
  struct Edge {
    std::string parent;
    bool is_static = false;
    std::vector<Sample> samples;  // static: one; dynamic: sorted by time, at least one
  };
  /// The edge's transform at t_ns.
  [[nodiscard]] static RosTransform at(const Edge& edge, std::int64_t t_ns);

  std::map<std::string, Edge, std::less<>> edges_;  // child -> edge to its parent
};

}  // namespace tessera
