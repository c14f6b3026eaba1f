#include "tessera/report/bob_monitor.hpp"

#include <gtest/gtest.h>

namespace tessera {
namespace {

// A 2 x 2 run: (0,0) sensed free (start), (1,0) sensed occupied, (0,1) sensed free, (1,1) never
// sensed; one move North.
BobResult tiny_run() {
  BobResult r;
  r.width = 2;
  r.height = 2;
  r.final_map = {0x02, 0x02};  // row 0: x=1 occupied; row 1: x=1 unsensed (1)
  r.sensed = {1, 1, 1, 0};
  r.route = {{0, 0}, {0, 1}};
  return r;
}

TEST(BobMonitor, ColoursCellsAsFigure5a) {
  const RgbImage img = render_bob_monitor(tiny_run(), 10);
  ASSERT_EQ(img.width, 21);
  ASSERT_EQ(img.height, 21);
  // Top image row is the highest cell row. Sample near a corner, away from the route's arrows.
  EXPECT_EQ(img.at(12, 12), kBobOccupied);  // cell (1, 0)
  EXPECT_EQ(img.at(12, 2), kBobUnsensed);   // cell (1, 1)
  EXPECT_EQ(img.at(2, 18), kBobEmpty);      // cell (0, 0)
  EXPECT_EQ(img.at(0, 0), kBobGridLine);
}

TEST(BobMonitor, DrawsTheRoute) {
  const RgbImage img = render_bob_monitor(tiny_run(), 10);
  int route_pixels = 0;
  for (int row = 0; row < img.height; ++row) {
    for (int x = 0; x < img.width; ++x) route_pixels += img.at(x, row) == kBobRoute ? 1 : 0;
  }
  EXPECT_GT(route_pixels, 20);
  // The move crosses the border between the two cells near column 5 (shifted right of travel).
  bool crosses = false;
  for (int x = 3; x <= 9; ++x) crosses = crosses || img.at(x, 10) == kBobRoute;
  EXPECT_TRUE(crosses);
}

}  // namespace
}  // namespace tessera
