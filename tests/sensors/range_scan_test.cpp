// mirrored(): the scan of an upside-down sensor as seen from above (io/tf_tree.hpp's PlanarLaser).
#include "tessera/sensors/range_scan.hpp"

#include <gtest/gtest.h>

namespace tessera {
namespace {

TEST(RangeScan, AMirroredScanHasItsBeamAnglesNegated) {
  const RangeScan scan{-0.5, 0.25, 0.1, 10.0, {1.0, 2.0, 3.0, 4.0, 5.0}};
  const RangeScan m = mirrored(scan);
  ASSERT_EQ(m.ranges_m.size(), 5u);
  for (std::size_t i = 0; i < 5; ++i) {
    const double angle = m.angle_min_rad + m.angle_increment_rad * static_cast<double>(i);
    const double original =
        scan.angle_min_rad + scan.angle_increment_rad * static_cast<double>(4 - i);
    EXPECT_NEAR(angle, -original, 1e-12);
    EXPECT_EQ(m.ranges_m[i], scan.ranges_m[4 - i]);
  }
  const RangeScan back = mirrored(m);
  EXPECT_NEAR(back.angle_min_rad, scan.angle_min_rad, 1e-12);
  EXPECT_EQ(back.ranges_m, scan.ranges_m);
  EXPECT_TRUE(mirrored(RangeScan{}).ranges_m.empty());
}

}  // namespace
}  // namespace tessera
