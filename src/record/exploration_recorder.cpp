#include "tessera/record/exploration_recorder.hpp"

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "tessera/record/ros_conversions.hpp"

namespace tessera {
namespace {

constexpr std::int64_t kStepNs = 1'000'000'000;  // one step per second

std::string robot_frame(int robot) { return "robot" + std::to_string(robot) + "/base_link"; }

template <typename Message>
Status publish(MessageSink& sink, MessageSink::ChannelId channel, std::int64_t t_ns,
               const Message& m) {
  return sink.publish(channel, t_ns, encode_cdr(m));
}

MessageSink::ChannelId channel_of(MessageSink& sink, const std::string& topic,
                                  std::string_view type) {
  return sink.channel(topic, type, ros2msg_definition(type));
}

}  // namespace

ExplorationRecorder::ExplorationRecorder(MessageSink& sink, const ExplorationRecordOptions& options)
    : sink_(sink), options_(options) {
  tf_ = channel_of(sink_, "/tf", kRos2TfMessage);
  map_ = channel_of(sink_, "/map", kRos2OccupancyGrid);
  frontier_ = channel_of(sink_, "/frontier", kRos2MarkerArray);
}

Status ExplorationRecorder::step(const ExplorationMission& mission) {
  const std::int64_t step = mission.steps();
  const std::int64_t t_ns = step * kStepNs;
  // run_exploration calls once more when the mission finished, at the step it already saw.
  if (step != last_step_) {
    if (Status s = publish_transforms(mission, t_ns); !s) return s;
    last_step_ = step;
  }
  const bool due = mission.finished() || step % std::max(options_.map_every_steps, 1) == 0;
  if (!due || step == last_state_step_) return Ok{};
  last_state_step_ = step;
  return publish_state(mission, t_ns);
}

Status ExplorationRecorder::publish_transforms(const ExplorationMission& mission,
                                               std::int64_t t_ns) {
  TfMessage tf;
  for (int r = 0; r < mission.robots(); ++r) {
    tf.transforms.push_back(
        planar_transform_stamped(mission.paths()[r].back(), t_ns, "map", robot_frame(r)));
  }
  return publish(sink_, tf_, t_ns, tf);
}

Status ExplorationRecorder::publish_state(const ExplorationMission& mission, std::int64_t t_ns) {
  if (Status s = publish(sink_, map_, t_ns, occupancy_grid_message(mission.map(), t_ns, "map"));
      !s) {
    return s;
  }
  while (paths_.size() < static_cast<std::size_t>(mission.robots())) {
    paths_.push_back(
        channel_of(sink_, "/robot" + std::to_string(paths_.size()) + "/path", kRos2Path));
  }
  for (int r = 0; r < mission.robots(); ++r) {
    const std::vector<Pose2>& poses = mission.paths()[r];
    std::vector<std::int64_t> stamps(poses.size());
    // paths()[r] has the start and one pose per move; moves are one per step at most, so the
    // pose index is a step only for a robot that moved every step. Stamp them by index: the
    // path is a picture of where the robot went, not a timeline.
    for (std::size_t i = 0; i < poses.size(); ++i)
      stamps[i] = static_cast<std::int64_t>(i) * kStepNs;
    if (Status s = publish(sink_, paths_[r], t_ns, path_message(poses, stamps, t_ns, "map")); !s) {
      return s;
    }
  }
  const GridGeometry& g = mission.map().geometry();
  const std::vector<Cell> frontier = mission.frontier().cells();
  const std::vector<Cell> unreachable = mission.unreachable_frontier();
  MarkerArrayMessage markers;
  MarkerMessage clear;
  clear.header = {t_ns, "map"};
  clear.action = MarkerMessage::kDeleteAll;
  markers.markers.push_back(clear);
  markers.markers.push_back(
      cell_marker(frontier, g, t_ns, "map", "frontier", RosColor{1.0F, 0.8F, 0.0F, 0.9F}));
  markers.markers.push_back(
      cell_marker(unreachable, g, t_ns, "map", "unreachable", RosColor{0.9F, 0.1F, 0.1F, 0.9F}));
  markers.markers.push_back(cell_marker(mission.starts(), g, t_ns, "map", "starts",
                                        RosColor{0.1F, 0.4F, 1.0F, 1.0F}, 0.2));
  // Each robot's chosen frontier cell: a sphere, the way there, and its a, d and p = a / d.
  for (int r = 0; r < mission.robots(); ++r) {
    const std::optional<FrontierPlan>& plan = mission.plan(r);
    if (!plan) continue;
    const Vec2 target = g.center_of(plan->target);
    MarkerMessage goal = cell_marker(std::span<const Cell>(&plan->target, 1), g, t_ns, "map",
                                     "goals", RosColor{0.1F, 0.4F, 1.0F, 1.0F}, 0.2);
    goal.type = MarkerMessage::kSphereList;
    goal.id = 3 * r;
    markers.markers.push_back(goal);
    MarkerMessage way =
        cell_marker(plan->path, g, t_ns, "map", "goals", RosColor{0.1F, 0.4F, 1.0F, 0.6F});
    way.type = MarkerMessage::kLineStrip;
    way.id = 3 * r + 1;
    way.scale = {0.3 * g.resolution_m(), 0.0, 0.0};
    markers.markers.push_back(way);
    MarkerMessage text;
    text.header = {t_ns, "map"};
    text.ns = "goals";
    text.id = 3 * r + 2;
    text.type = MarkerMessage::kText;
    text.pose = planar_transform(target.x, target.y, 0.0);
    text.scale = {0.0, 0.0, 0.3};
    text.color = RosColor{0.0F, 0.0F, 0.0F, 1.0F};
    char label[96];
    std::snprintf(label, sizeof label, "robot%d -> (%d, %d) a=%d d=%d p=%.2f", r, plan->target.x,
                  plan->target.y, plan->unknown_neighbors, plan->distance_cells, plan->priority);
    text.text = label;
    markers.markers.push_back(text);
  }
  return publish(sink_, frontier_, t_ns, markers);
}

}  // namespace tessera
