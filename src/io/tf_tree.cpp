// TfTree: tf2's lookupTransform over a bag (tf2/src/buffer_core.cpp walks from both frames up to
// a common ancestor the same way), with 3D rigid transforms as translation + unit quaternion.
#include "tessera/io/tf_tree.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "tessera/core/time_ns.hpp"

namespace tessera {
namespace {

struct Quat {
  double x, y, z, w;
};

Quat rotation(const RosTransform& T) { return {T.qx, T.qy, T.qz, T.qw}; }

Quat multiply(const Quat& a, const Quat& b) {
  return {
      a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y, a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
      a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w, a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z};
}

Quat normalized(const Quat& q) {
  const double n = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
  if (!(n > 0.0)) return {0.0, 0.0, 0.0, 1.0};
  return {q.x / n, q.y / n, q.z / n, q.w / n};
}

/// q * v * q^-1 for a unit quaternion.
void rotate(const Quat& q, double& x, double& y, double& z) {
  const Quat v{x, y, z, 0.0};
  const Quat r = multiply(multiply(q, v), Quat{-q.x, -q.y, -q.z, q.w});
  x = r.x;
  y = r.y;
  z = r.z;
}

RosTransform make(double x, double y, double z, const Quat& q) {
  return {x, y, z, q.x, q.y, q.z, q.w};
}

/// T_a_c = T_a_b * T_b_c.
RosTransform compose(const RosTransform& T_a_b, const RosTransform& T_b_c) {
  const Quat q = normalized(rotation(T_a_b));
  double x = T_b_c.x_m, y = T_b_c.y_m, z = T_b_c.z_m;
  rotate(q, x, y, z);
  return make(T_a_b.x_m + x, T_a_b.y_m + y, T_a_b.z_m + z,
              normalized(multiply(q, normalized(rotation(T_b_c)))));
}

RosTransform inverse(const RosTransform& T) {
  const Quat q = normalized(rotation(T));
  const Quat qi{-q.x, -q.y, -q.z, q.w};
  double x = -T.x_m, y = -T.y_m, z = -T.z_m;
  rotate(qi, x, y, z);
  return make(x, y, z, qi);
}

RosTransform interpolate(const RosTransform& a, const RosTransform& b, double f) {
  Quat qb = rotation(b);
  const Quat qa = rotation(a);
  if (qa.x * qb.x + qa.y * qb.y + qa.z * qb.z + qa.w * qb.w < 0.0) {  // the shorter arc
    qb = {-qb.x, -qb.y, -qb.z, -qb.w};
  }
  const Quat q = normalized({qa.x + f * (qb.x - qa.x), qa.y + f * (qb.y - qa.y),
                             qa.z + f * (qb.z - qa.z), qa.w + f * (qb.w - qa.w)});
  return make(a.x_m + f * (b.x_m - a.x_m), a.y_m + f * (b.y_m - a.y_m), a.z_m + f * (b.z_m - a.z_m),
              q);
}

}  // namespace

Pose2 planar_pose(const RosTransform& T) {
  const Quat q = normalized(rotation(T));
  const double yaw = std::atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z));
  return {T.x_m, T.y_m, normalize_angle(yaw)};
}

PlanarLaser planar_laser(const RosTransform& T_base_laser) {
  const Quat q = normalized(rotation(T_base_laser));
  // The z component of the laser's z axis in the base frame: R(2, 2) of the quaternion.
  const double z_up = 1.0 - 2.0 * (q.x * q.x + q.y * q.y);
  return {planar_pose(T_base_laser), z_up < 0.0};
}

std::string_view tf_frame_name(std::string_view frame) {
  while (!frame.empty() && frame.front() == '/') frame.remove_prefix(1);
  return frame;
}

void TfTree::add(const TransformStampedMessage& t, bool is_static) {
  const std::string child(tf_frame_name(t.child_frame_id));
  Edge& edge = edges_[child];
  const Sample sample{t.header.stamp_ns, t.transform};
  if (is_static || edge.is_static) {
    if (!is_static && edge.is_static) return;  // a static transform outranks dynamic ones
    edge.parent = std::string(tf_frame_name(t.header.frame_id));
    edge.is_static = true;
    edge.samples.assign(1, sample);
    return;
  }
  edge.parent = std::string(tf_frame_name(t.header.frame_id));
  const auto pos = std::upper_bound(edge.samples.begin(), edge.samples.end(), sample.t_ns,
                                    [](std::int64_t v, const Sample& s) { return v < s.t_ns; });
  edge.samples.insert(pos, sample);
}

RosTransform TfTree::at(const Edge& edge, std::int64_t t_ns) {
  const std::vector<Sample>& s = edge.samples;
  if (edge.is_static || s.size() == 1 || t_ns <= s.front().t_ns) return s.front().T_parent_child;
  if (t_ns >= s.back().t_ns) return s.back().T_parent_child;
  const auto after = std::lower_bound(s.begin(), s.end(), t_ns,
                                      [](const Sample& a, std::int64_t v) { return a.t_ns < v; });
  const auto before = after - 1;
  const double f = ns_difference(t_ns, before->t_ns) / ns_difference(after->t_ns, before->t_ns);
  return interpolate(before->T_parent_child, after->T_parent_child, f);
}

Result<RosTransform> TfTree::lookup(std::string_view target_frame, std::string_view source_frame,
                                    std::int64_t t_ns) const {
  const std::string_view target = tf_frame_name(target_frame);
  const std::string_view source = tf_frame_name(source_frame);
  // T_ancestor_frame for every ancestor of `frame` (itself included, with the identity).
  auto chain = [&](std::string_view frame) {
    std::vector<std::pair<std::string, RosTransform>> out{{std::string(frame), RosTransform{}}};
    std::set<std::string, std::less<>> seen{std::string(frame)};
    for (auto it = edges_.find(frame); it != edges_.end(); it = edges_.find(out.back().first)) {
      if (seen.count(it->second.parent) != 0) break;  // a loop: tf2 refuses it too
      seen.insert(it->second.parent);
      out.emplace_back(it->second.parent, compose(at(it->second, t_ns), out.back().second));
    }
    return out;
  };
  const auto up_from_source = chain(source);
  const auto up_from_target = chain(target);
  for (const auto& [frame, T_ancestor_source] : up_from_source) {
    for (const auto& [other, T_ancestor_target] : up_from_target) {
      if (frame == other) return compose(inverse(T_ancestor_target), T_ancestor_source);
    }
  }
  return input_error("no tf chain connects frame '" + std::string(target) + "' and frame '" +
                     std::string(source) + "'");
}

std::optional<TfTree::MovingEdge> TfTree::lowest_moving_edge(std::string_view frame) const {
  std::string child(tf_frame_name(frame));
  for (std::size_t depth = 0; depth <= edges_.size(); ++depth) {  // a cycle cannot loop forever
    const auto it = edges_.find(child);
    if (it == edges_.end()) return std::nullopt;
    const Edge& e = it->second;
    if (!e.is_static) {
      MovingEdge out{e.parent, child, {}};
      out.T_parent_child.reserve(e.samples.size());
      for (const Sample& s : e.samples) out.T_parent_child.emplace_back(s.t_ns, s.T_parent_child);
      return out;
    }
    child = e.parent;
  }
  return std::nullopt;
}

std::vector<std::string> TfTree::frames() const {
  std::set<std::string> all;
  for (const auto& [child, edge] : edges_) {
    all.insert(child);
    all.insert(edge.parent);
  }
  return {all.begin(), all.end()};
}

}  // namespace tessera
