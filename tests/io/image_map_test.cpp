#include "tessera/io/image_map.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "io_test_util.hpp"
#include "support/data.hpp"
#include "tessera/io/image_file.hpp"

namespace tessera {
namespace {

using io_test::TempDir;
using ::testing::HasSubstr;

TEST(ReadImageMap, PlacesThePictureAtTheOriginWithTheTopRowHighest) {
  TempDir dir;
  GrayImage image(3, 2, 255);
  image.set(0, 0, 0);    // top-left: occupied, cell (0, 1)
  image.set(2, 1, 205);  // bottom-right: unknown, cell (2, 0)
  Result<std::string> png = encode_png(image);
  ASSERT_TRUE(png);
  io_test::write_bytes(dir / "plan.png", *png);
  Result<OccupancyGrid> g = read_image_map(dir / "plan.png", 0.1, {2.0, -1.0});
  ASSERT_TRUE(g) << g.error().message;
  EXPECT_EQ(g->geometry(), GridGeometry({2.0, -1.0}, 0.1, 3, 2));
  EXPECT_EQ(g->state({0, 1}), CellState::kOccupied);
  EXPECT_EQ(g->state({0, 0}), CellState::kFree);
  EXPECT_EQ(g->state({2, 0}), CellState::kUnknown);
}

TEST(ReadImageMap, ThresholdsAndNegateApply) {
  TempDir dir;
  io_test::write_bytes(dir / "p.pgm", io_test::ascii_pgm({{0, 128, 255}}));
  ImageMapThresholds t;
  t.negate = true;
  Result<OccupancyGrid> negated = read_image_map(dir / "p.pgm", 1.0, {}, t);
  ASSERT_TRUE(negated) << negated.error().message;
  EXPECT_EQ(negated->state({0, 0}), CellState::kFree);
  EXPECT_EQ(negated->state({1, 0}), CellState::kUnknown);
  EXPECT_EQ(negated->state({2, 0}), CellState::kOccupied);
  t = {0.4, 0.3, false};  // occ(128) = 0.498 > 0.4
  Result<OccupancyGrid> strict = read_image_map(dir / "p.pgm", 1.0, {}, t);
  ASSERT_TRUE(strict) << strict.error().message;
  EXPECT_EQ(strict->state({1, 0}), CellState::kOccupied);
}

TEST(ReadImageMap, BadArgumentsAndMissingFilesAreInputErrors) {
  TempDir dir;
  io_test::write_bytes(dir / "p.pgm", io_test::ascii_pgm({{0}}));
  Result<OccupancyGrid> negative = read_image_map(dir / "p.pgm", -0.05);
  ASSERT_FALSE(negative);
  EXPECT_EQ(negative.error().kind, ErrorKind::kInput);
  EXPECT_EQ(negative.error().message,
            (dir / "p.pgm").string() + ": resolution must be > 0, got -0.05");
  Result<OccupancyGrid> thresholds = read_image_map(dir / "p.pgm", 1.0, {}, {0.2, 0.5, false});
  ASSERT_FALSE(thresholds);
  EXPECT_THAT(thresholds.error().message, HasSubstr("p.pgm: free_thresh (0.5) must not exceed"));
  Result<OccupancyGrid> missing = read_image_map(dir / "none.png", 1.0);
  ASSERT_FALSE(missing);
  EXPECT_THAT(missing.error().message, HasSubstr("none.png: no such file"));
}

struct RealImage {
  const char* path;
  double resolution_m;
  int width, height;
  std::size_t free, occupied, unknown;
};

// Counts made independently with pure-Python PNG/PGM readers and map_server's trinary rule.
const RealImage kRealImages[] = {
    {"maps/ros_map_server/willow_navigation_tutorials/willow-full.pgm", 0.1, 584, 526, 134715, 6961,
     165508},
    {"maps/braincorp/three_rooms.png", 0.03, 438, 474, 172130, 35482, 0},
    {"maps/houseexpo/png/00922f91aa09dbdda3a74489ea0e21eb.png", 0.01, 1139, 897, 799472, 222211, 0},
    {"maps/stage_bitmaps/cave.png", 0.032, 500, 500, 244730, 5270, 0},
    {"maps/radish_carmen/intel-corrected.png", 0.1, 199, 200, 34612, 395, 4793},
};

TEST(ReadImageMap, ReadsRealFloorPlans) {
  for (const RealImage& m : kRealImages) {
    const auto path = support::data_path(m.path);
    TESSERA_REQUIRE_DATA(path);
    Result<OccupancyGrid> g = read_image_map(path, m.resolution_m);
    ASSERT_TRUE(g) << g.error().message;
    EXPECT_EQ(g->geometry(), GridGeometry({0, 0}, m.resolution_m, m.width, m.height)) << m.path;
    const CellCounts c = g->count_states();
    EXPECT_EQ(c.free, m.free) << m.path;
    EXPECT_EQ(c.occupied, m.occupied) << m.path;
    EXPECT_EQ(c.unknown, m.unknown) << m.path;
  }
}

}  // namespace
}  // namespace tessera
