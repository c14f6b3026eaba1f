// BobRecorder as BobMissionOptions::on_step: the robot's grid every step in ROS's layout, its pose
// every step, its route every 10 steps and at the end.
#include "tessera/record/bob_recorder.hpp"

#include <gtest/gtest.h>

#include "recording_sink.hpp"
#include "tessera/io/ros_messages.hpp"
#include "tessera/sim/builtin_world.hpp"

namespace tessera {
namespace {

TEST(BobRecorder, RecordsTheGridAndPoseEveryStepAndTheRoute) {
  const World world = builtin_world("bob-arena", 0.01);
  BobMissionOptions options;
  options.noise = false;
  Result<World> truth = bob_grid_truth(world, options);
  ASSERT_TRUE(truth.ok()) << truth.error().message;
  test::RecordingSink sink;
  BobRecorder recorder(sink, truth->geometry());
  int steps = 0;
  options.on_step = [&](const BobResult& so_far) {
    ++steps;
    ASSERT_TRUE(recorder.step(so_far));
  };
  std::unique_ptr<BobExplorerPort> explorer = local_bob_explorer();
  Result<BobResult> run = run_bob(world, *truth, options, *explorer);
  ASSERT_TRUE(run.ok()) << run.error().message;
  ASSERT_TRUE(recorder.finish(*run));
  ASSERT_GT(steps, 20);

  const auto maps = sink.on("/map");
  ASSERT_EQ(maps.size(), static_cast<std::size_t>(steps));
  EXPECT_EQ(sink.on("/tf").size(), static_cast<std::size_t>(steps));
  const std::size_t periodic = static_cast<std::size_t>((steps - 1) / 10 + 1);
  EXPECT_EQ(sink.on("/path").size(), (steps - 1) % 10 == 0 ? periodic : periodic + 1);
  EXPECT_EQ(sink.on("/path").back()->t_ns, (steps - 1) * 1'000'000'000LL);

  // The last map: the run's sensed and occupied cells, row-major, after the CDR prefix (4 bytes
  // of encapsulation ... the uint32 count) in the message's last width x height bytes.
  const std::vector<std::uint8_t>& cdr = maps.back()->cdr;
  const std::size_t cells = run->sensed.size();
  ASSERT_EQ(cells, static_cast<std::size_t>(run->width * run->height));
  ASSERT_GE(cdr.size(), cells);
  for (std::size_t i = 0; i < cells; ++i) {
    const auto v = static_cast<std::int8_t>(cdr[cdr.size() - cells + i]);
    const std::int8_t expected = run->sensed[i] == 0 ? -1 : run->occupied[i] != 0 ? 100 : 0;
    ASSERT_EQ(v, expected) << "cell " << i;
  }
  // The last pose: the centre of the route's last cell.
  Result<TfMessage> tf = decode_tf_message(sink.on("/tf").back()->cdr, RosEncoding::kCdr);
  ASSERT_TRUE(tf.ok());
  const Vec2 end = truth->geometry().center_of(run->route.back());
  EXPECT_DOUBLE_EQ(tf->transforms[0].transform.x_m, end.x);
  EXPECT_DOUBLE_EQ(tf->transforms[0].transform.y_m, end.y);
}

}  // namespace
}  // namespace tessera
