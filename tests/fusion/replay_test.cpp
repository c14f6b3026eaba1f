// Feeding a recorded run to the online system: frames are loaded only when a firing field wants
// one, and a loader's error ends the replay with that error.
#include "tessera/fusion/replay.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace tessera::fusion {
namespace {

/// 2 m along x in 2 cm steps.
std::vector<ReplayStep> straight_run() {
  std::vector<ReplayStep> steps;
  for (int i = 0; i <= 100; ++i) steps.push_back({0.1 * i, {0.02 * i, 0.0, 0.0}, 0.0});
  return steps;
}

/// A frame the node checks refuse (no depth): the system stores nothing and asks again later.
RgbdFrame blank_frame(double t_s) {
  RgbdFrame f;
  f.t_s = t_s;
  f.width = 64;
  f.height = 48;
  f.rgb.assign(3 * 64 * 48, 128);
  f.depth_m.assign(64 * 48, 0.0F);
  f.intrinsics = {
      .fx_px = 60.0, .fy_px = 60.0, .cx_px = 32.0, .cy_px = 24.0, .width_px = 64, .height_px = 48};
  return f;
}

TEST(Replay, LoadsAFrameOnlyWhenTheSystemWantsOne) {
  const std::vector<ReplayStep> steps = straight_run();
  // The same run fed by hand: which steps want a frame.
  FusionSlam by_hand;
  std::vector<std::size_t> wanted;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    if (by_hand.update(steps[i].t_s, steps[i].odometry, steps[i].neck_pan_rad).wants_frame) {
      wanted.push_back(i);
      (void)by_hand.add_frame(blank_frame(steps[i].t_s));
    }
  }
  ASSERT_FALSE(wanted.empty());
  ASSERT_LT(wanted.size(), steps.size());

  FusionSlam slam;
  std::vector<std::size_t> loaded;
  std::size_t progress_calls = 0;
  const Result<ReplayResult> r = replay(
      slam, steps,
      [&](std::size_t i) -> Result<RgbdFrame> {
        loaded.push_back(i);
        return blank_frame(steps[i].t_s);
      },
      [&](std::size_t done, std::size_t total) {
        ++progress_calls;
        EXPECT_EQ(total, steps.size());
        EXPECT_EQ(done, progress_calls);
      });
  ASSERT_TRUE(r) << r.error().message;
  EXPECT_EQ(loaded, wanted);
  EXPECT_EQ(r->frames_loaded, static_cast<int>(wanted.size()));
  EXPECT_EQ(progress_calls, steps.size());
  ASSERT_EQ(r->path_m.size(), steps.size());
  EXPECT_NEAR(r->path_m.back().x, 2.0, 1e-9);  // no match, so the estimate is the odometry
  EXPECT_EQ(slam.statistics().frames_rejected, static_cast<int>(wanted.size()));
}

TEST(Replay, ALoaderErrorEndsTheReplayWithThatError) {
  const std::vector<ReplayStep> steps = straight_run();
  FusionSlam slam;
  int calls = 0;
  const Result<ReplayResult> r = replay(slam, steps, [&](std::size_t) -> Result<RgbdFrame> {
    ++calls;
    return input_error("seq/rgb/1.0.png: cannot be read as an image");
  });
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().message, "seq/rgb/1.0.png: cannot be read as an image");
  EXPECT_EQ(calls, 1);
}

}  // namespace
}  // namespace tessera::fusion
