#pragma once
// Records a frontier exploration (mission/exploration_mission.hpp) as ROS 2 messages, one call per
// step, into a MessageSink (an MCAP file, the live view). Steps are stamped one per second from
// t = 0 (the simulator has no clock; `tessera explore` stamps its trajectory the same way).
// Topics: /tf (map -> robotN/base_link, every step), /map (nav_msgs/OccupancyGrid), /robotN/path
// (nav_msgs/Path) and /frontier (visualization_msgs/MarkerArray: the frontier cells, the
// frontier cells no robot can reach, and each robot's start), the last three every
// map_every_steps steps and once the mission finished.
#include <cstdint>

#include "tessera/core/result.hpp"
#include "tessera/io/message_sink.hpp"
#include "tessera/mission/exploration_mission.hpp"

namespace tessera {

struct ExplorationRecordOptions {
  /// Map, paths and frontier every this many steps (>= 1); the transforms every step.
  int map_every_steps = 10;
};

class ExplorationRecorder {
 public:
  explicit ExplorationRecorder(MessageSink& sink, const ExplorationRecordOptions& options = {});
  /// The mission's state after its latest step (at the start, before the first; once finished,
  /// the final map, paths and frontier). run_exploration's on_step.
  [[nodiscard]] Status step(const ExplorationMission& mission);

 private:
  Status publish_transforms(const ExplorationMission& mission, std::int64_t t_ns);
  Status publish_state(const ExplorationMission& mission, std::int64_t t_ns);

  MessageSink& sink_;
  ExplorationRecordOptions options_;
  MessageSink::ChannelId tf_ = 0, map_ = 0, frontier_ = 0;
  std::vector<MessageSink::ChannelId> paths_;
  std::int64_t last_step_ = -1;        // the step whose transforms were published last
  std::int64_t last_state_step_ = -1;  // the step whose map, paths and frontier were
};

}  // namespace tessera
