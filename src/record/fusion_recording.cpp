#include "tessera/record/fusion_recording.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "tessera/grid/hex_grid.hpp"
#include "tessera/record/ros_conversions.hpp"

namespace tessera {
namespace {

const std::string kBase = "robot0/base_link";

template <typename Message>
Status publish(MessageSink& sink, std::string_view topic, std::string_view type, std::int64_t t_ns,
               const Message& m) {
  const MessageSink::ChannelId channel = sink.channel(topic, type, ros2msg_definition(type));
  return sink.publish(channel, t_ns, encode_cdr(m));
}

// The cells: one LINE_LIST of every hexagon's six edges (rotated with the cell's lattice) and one
// SPHERE_LIST of the centres.
MarkerArrayMessage hex_cell_markers(const fusion::HexCellMap& map, std::int64_t t_ns) {
  MarkerMessage outlines;
  outlines.header = {t_ns, "map"};
  outlines.ns = "hex_cells";
  outlines.type = MarkerMessage::kLineList;
  outlines.scale = {0.01, 0.0, 0.0};  // line width
  outlines.color = {0.2F, 0.5F, 0.9F, 1.0F};
  MarkerMessage centres = outlines;
  centres.id = 1;
  centres.type = MarkerMessage::kSphereList;
  centres.scale = {0.04, 0.04, 0.04};
  const double radius_m = map.options().cell_radius_m;
  for (const fusion::HexCell& cell : map.cells()) {
    const auto corners = HexGrid::corners({0.0, 0.0}, radius_m);
    const double c = std::cos(cell.lattice_rotation_rad), s = std::sin(cell.lattice_rotation_rad);
    const auto at = [&](const Vec2& v) {
      return RosPoint{cell.centre_m.x + c * v.x - s * v.y, cell.centre_m.y + s * v.x + c * v.y,
                      0.0};
    };
    for (std::size_t k = 0; k < corners.size(); ++k) {
      outlines.points.push_back(at(corners[k]));
      outlines.points.push_back(at(corners[(k + 1) % corners.size()]));
    }
    centres.points.push_back({cell.centre_m.x, cell.centre_m.y, 0.0});
  }
  MarkerArrayMessage out;
  out.markers = {outlines, centres};
  return out;
}

}  // namespace

Status record_fusion_run(MessageSink& sink, const fusion::FusionSlam& slam,
                         std::span<const StampedPose2> truth, std::int64_t time_offset_ns) {
  const std::vector<StampedPose2> corrected = slam.corrected_trajectory();
  if (corrected.empty()) return Ok{};
  std::int64_t last_ns = to_ns(corrected.front().t_s) + time_offset_ns;
  for (const StampedPose2& p : corrected) {
    const std::int64_t t_ns = to_ns(p.t_s) + time_offset_ns;
    last_ns = std::max(last_ns, t_ns);
    TfMessage tf;
    tf.transforms.push_back(planar_transform_stamped(p.pose, t_ns, "map", kBase));
    if (Status s = publish(sink, "/tf", kRos2TfMessage, t_ns, tf); !s) return s;
  }
  if (Status s = publish(sink, "/path", kRos2Path, last_ns,
                         path_message(corrected, last_ns, "map", time_offset_ns));
      !s) {
    return s;
  }
  const std::vector<StampedPose2> odometry = slam.odometry_trajectory();
  if (Status s = publish(sink, "/odometry_path", kRos2Path, last_ns,
                         path_message(odometry, last_ns, "map", time_offset_ns));
      !s) {
    return s;
  }
  if (!truth.empty()) {
    if (Status s = publish(sink, "/truth_path", kRos2Path, last_ns,
                           path_message(truth, last_ns, "map", time_offset_ns));
        !s) {
      return s;
    }
  }
  if (Status s = publish(sink, "/hex_cells", kRos2MarkerArray, last_ns,
                         hex_cell_markers(slam.map(), last_ns));
      !s) {
    return s;
  }
  MarkerMessage nodes;
  nodes.header = {last_ns, "map"};
  nodes.ns = "image_nodes";
  nodes.type = MarkerMessage::kSphereList;
  nodes.scale = {0.06, 0.06, 0.06};
  nodes.color = {0.9F, 0.3F, 0.1F, 1.0F};
  for (const fusion::StoredImageNode& n : slam.image_nodes()) {
    if (n.graph_node >= corrected.size()) continue;
    const Pose2& at = corrected[n.graph_node].pose;
    nodes.points.push_back({at.x, at.y, 0.3});
  }
  MarkerArrayMessage node_markers;
  node_markers.markers.push_back(nodes);
  return publish(sink, "/image_nodes", kRos2MarkerArray, last_ns, node_markers);
}

Status record_teach_and_repeat(MessageSink& sink, const TeachAndRepeatResult& result,
                               std::int64_t time_offset_ns) {
  const TeachAndRepeatRun& run = result.run;
  if (Status s = record_fusion_run(sink, result.slam, {}, time_offset_ns); !s) return s;
  const std::int64_t end_ns = time_offset_ns + to_ns(run.duration_s);
  // The estimated paths of both stages and the true one, as they were driven.
  const auto path_through = [end_ns](const std::vector<Vec2>& points) {
    std::vector<Pose2> poses;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Vec2 to = i + 1 < points.size() ? points[i + 1] : points[i];
      const Vec2 from = i + 1 < points.size() ? points[i] : (i > 0 ? points[i - 1] : points[i]);
      poses.push_back({points[i].x, points[i].y, std::atan2(to.y - from.y, to.x - from.x)});
    }
    const std::vector<std::int64_t> stamps(poses.size(), end_ns);
    return path_message(poses, stamps, end_ns, "map");
  };
  for (const auto& [topic, points] :
       {std::pair<std::string_view, const std::vector<Vec2>*>{"/taught_path", &run.taught_path_m},
        {"/repeated_path", &run.repeated_path_m},
        {"/truth_path", &run.true_path_m}}) {
    if (points->empty()) continue;
    if (Status s = publish(sink, topic, kRos2Path, end_ns, path_through(*points)); !s) return s;
  }
  TfMessage tf;
  tf.transforms.push_back(planar_transform_stamped(run.final_pose, end_ns, "map", kBase));
  return publish(sink, "/tf", kRos2TfMessage, end_ns, tf);
}

}  // namespace tessera
