#pragma once
// Records a BOBMapping run (mission/bob_mission.hpp) as ROS 2 messages, one call per step
// (BobMissionOptions::on_step), into a MessageSink. Steps are stamped one per second from t = 0.
// Every step: /map (nav_msgs/OccupancyGrid of the robot's grid: -1 unsensed, 0 free, 100
// occupied, as the monitor of BOBMapping Figure 5a colours it) and /tf (map -> robot0/base_link
// at the centre of the robot's cell, facing its last move); every 10 steps and at the end, /path
// (nav_msgs/Path of the route's cell centres, which grows with the run).
#include <cstdint>

#include "tessera/core/result.hpp"
#include "tessera/grid/grid_geometry.hpp"
#include "tessera/io/message_sink.hpp"
#include "tessera/mission/bob_mission.hpp"

namespace tessera {

class BobRecorder {
 public:
  /// `robot_grid`: where the robot's grid lies in the world (bob_grid_truth(...).geometry()).
  BobRecorder(MessageSink& sink, const GridGeometry& robot_grid);
  /// The run so far (BobMission::snapshot()).
  [[nodiscard]] Status step(const BobResult& so_far);
  /// The run's end: the path, unless the last step published it.
  [[nodiscard]] Status finish(const BobResult& final_run);

 private:
  Status publish_path(const BobResult& run, std::int64_t t_ns);
  MessageSink& sink_;
  GridGeometry grid_;
  MessageSink::ChannelId map_ = 0, tf_ = 0, path_ = 0;
  std::int64_t step_ = 0;             // steps seen
  std::int64_t path_published_ = -1;  // the step whose path was published last
};

}  // namespace tessera
