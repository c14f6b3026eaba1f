#include "tessera/record/bob_recorder.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include "tessera/record/ros_conversions.hpp"

namespace tessera {
namespace {

constexpr std::int64_t kStepNs = 1'000'000'000;  // one step per second

MessageSink::ChannelId channel_of(MessageSink& sink, std::string_view topic,
                                  std::string_view type) {
  return sink.channel(topic, type, ros2msg_definition(type));
}

}  // namespace

BobRecorder::BobRecorder(MessageSink& sink, const GridGeometry& robot_grid)
    : sink_(sink), grid_(robot_grid) {
  map_ = channel_of(sink_, "/map", kRos2OccupancyGrid);
  tf_ = channel_of(sink_, "/tf", kRos2TfMessage);
  path_ = channel_of(sink_, "/path", kRos2Path);
}

namespace {

// The robot's poses along its route: cell centres, facing the last move (North at the start).
std::vector<Pose2> route_poses(const BobResult& run, const GridGeometry& grid) {
  std::vector<Pose2> poses;
  poses.reserve(run.route.size());
  double heading_rad = std::numbers::pi / 2;
  for (std::size_t i = 0; i < run.route.size(); ++i) {
    const Cell c = run.route[i];
    if (i > 0) {
      const Cell p = run.route[i - 1];
      if (p.x != c.x || p.y != c.y) heading_rad = std::atan2(c.y - p.y, c.x - p.x);
    }
    const Vec2 centre = grid.center_of(c);
    poses.push_back({centre.x, centre.y, heading_rad});
  }
  return poses;
}

constexpr std::int64_t kPathEverySteps = 10;

}  // namespace

Status BobRecorder::step(const BobResult& so_far) {
  const std::int64_t step = step_++;
  const std::int64_t t_ns = step * kStepNs;
  OccupancyGridMessage map;
  map.header = {t_ns, "map"};
  map.map_load_time_ns = t_ns;
  map.resolution_m = static_cast<float>(grid_.resolution_m());
  map.width = static_cast<std::uint32_t>(so_far.width);
  map.height = static_cast<std::uint32_t>(so_far.height);
  map.origin = planar_transform(grid_.origin().x, grid_.origin().y, 0.0);
  map.data.resize(so_far.sensed.size());
  for (std::size_t i = 0; i < so_far.sensed.size(); ++i) {
    map.data[i] = so_far.sensed[i] == 0     ? std::int8_t{-1}
                  : so_far.occupied[i] != 0 ? std::int8_t{100}
                                            : std::int8_t{0};
  }
  if (Status s = sink_.publish(map_, t_ns, encode_cdr(map)); !s) return s;
  if (so_far.route.empty()) return Ok{};
  const Pose2 pose = route_poses(so_far, grid_).back();
  TfMessage tf;
  tf.transforms.push_back(planar_transform_stamped(pose, t_ns, "map", "robot0/base_link"));
  if (Status s = sink_.publish(tf_, t_ns, encode_cdr(tf)); !s) return s;
  if (step % kPathEverySteps != 0) return Ok{};
  return publish_path(so_far, t_ns);
}

Status BobRecorder::finish(const BobResult& final_run) {
  const std::int64_t last = step_ - 1;
  if (last < 0 || last == path_published_ || final_run.route.empty()) return Ok{};
  return publish_path(final_run, last * kStepNs);
}

Status BobRecorder::publish_path(const BobResult& run, std::int64_t t_ns) {
  const std::vector<Pose2> poses = route_poses(run, grid_);
  std::vector<std::int64_t> stamps(poses.size());
  for (std::size_t i = 0; i < stamps.size(); ++i)
    stamps[i] = static_cast<std::int64_t>(i) * kStepNs;
  path_published_ = t_ns / kStepNs;
  return sink_.publish(path_, t_ns, encode_cdr(path_message(poses, stamps, t_ns, "map")));
}

}  // namespace tessera
