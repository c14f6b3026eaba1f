// ExplorationRecorder as run_exploration's on_step: transforms every step, the map, paths and
// frontier every map_every_steps steps and at the end, one path topic per robot.
#include "tessera/record/exploration_recorder.hpp"

#include <gtest/gtest.h>

#include "recording_sink.hpp"
#include "tessera/io/ros_messages.hpp"
#include "tessera/sim/builtin_world.hpp"

namespace tessera {
namespace {

TEST(ExplorationRecorder, RecordsEveryStepsPosesAndThePeriodicMap) {
  const World world = builtin_world("labyrinth", 0.25);
  ExplorationMissionOptions options;
  options.robots = 2;
  test::RecordingSink sink;
  ExplorationRecordOptions record;
  record.map_every_steps = 5;
  ExplorationRecorder recorder(sink, record);
  std::int64_t calls = 0, last_step = -1;
  Result<ExplorationResult> result =
      run_exploration(world, options, {}, [&](const ExplorationMission& mission) {
        ++calls;
        last_step = mission.steps();
        ASSERT_TRUE(recorder.step(mission));
      });
  ASSERT_TRUE(result.ok()) << result.error().message;
  const std::int64_t steps = result->metrics.steps;
  ASSERT_GT(steps, 10);
  EXPECT_EQ(last_step, steps);

  // One tf message per step (the call once finished repeats the last step), each with both
  // robots, stamped at its step (one per second).
  EXPECT_EQ(calls, steps + 2);
  const auto tf = sink.on("/tf");
  ASSERT_EQ(static_cast<std::int64_t>(tf.size()), steps + 1);
  Result<TfMessage> last_tf = decode_tf_message(tf.back()->cdr, RosEncoding::kCdr);
  ASSERT_TRUE(last_tf.ok());
  ASSERT_EQ(last_tf->transforms.size(), 2U);
  EXPECT_EQ(last_tf->transforms[1].child_frame_id, "robot1/base_link");
  EXPECT_EQ(tf.back()->t_ns, steps * 1'000'000'000);
  const Pose2 end = result->paths[1].back();
  EXPECT_DOUBLE_EQ(last_tf->transforms[1].transform.x_m, end.x);

  // The map at steps 0, 5, 10, ... and once more at the end (unless the end is a multiple).
  const auto maps = sink.on("/map");
  const std::size_t periodic = static_cast<std::size_t>(steps / 5) + 1;
  EXPECT_EQ(maps.size(), steps % 5 == 0 ? periodic : periodic + 1);
  EXPECT_EQ(maps.back()->t_ns, steps * 1'000'000'000);
  EXPECT_EQ(sink.on("/frontier").size(), maps.size());
  EXPECT_EQ(sink.on("/robot0/path").size(), maps.size());
  EXPECT_EQ(sink.on("/robot1/path").size(), maps.size());
  EXPECT_FALSE(sink.definitions.at("nav_msgs/msg/OccupancyGrid").empty());
}

}  // namespace
}  // namespace tessera
