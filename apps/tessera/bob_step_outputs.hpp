#pragma once
// What `tessera bob` does after every step of the run it shows: the monitor picture into
// --monitor-dir (BOBMapping Figure 5a's monitor, step by step) and the --record messages.
#include <filesystem>
#include <functional>
#include <optional>

#include "tessera/core/result.hpp"
#include "tessera/io/message_sink.hpp"
#include "tessera/mission/bob_mission.hpp"
#include "tessera/record/bob_recorder.hpp"

namespace tessera::cli {

class BobStepOutputs {
 public:
  /// `monitor_dir`: where the step pictures go (none: no pictures); `sink`: the recording (null:
  /// none); `robot_grid`: the robot's grid in the world.
  BobStepOutputs(std::optional<std::filesystem::path> monitor_dir, MessageSink* sink,
                 const GridGeometry& robot_grid);
  /// Creates the monitor folder. kRuntime error naming it.
  [[nodiscard]] Status prepare() const;
  /// BobMissionOptions::on_step for the run; empty when there is nothing to do.
  [[nodiscard]] std::function<void(const BobResult&)> on_step();
  /// The run's end (the recording's last path). The first failure, this one's or a step's.
  [[nodiscard]] Status finish(const BobResult& final_run);
  /// The first failure of a step (the callback cannot return one); later steps do nothing.
  [[nodiscard]] const Status& status() const { return status_; }

 private:
  void step(const BobResult& so_far);
  std::optional<std::filesystem::path> monitor_dir_;
  std::optional<BobRecorder> recorder_;
  int frame_ = 0;
  Status status_ = Ok{};
};

}  // namespace tessera::cli
