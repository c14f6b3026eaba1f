#include "tessera/io/stage_world.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "io_test_util.hpp"
#include "support/data.hpp"

namespace tessera {
namespace {

using io_test::row_text;
using io_test::TempDir;
using ::testing::HasSubstr;

// A world in a temp folder with the fixture bitmap beside it.
std::filesystem::path world_with(const TempDir& dir, const std::string& text) {
  std::filesystem::copy_file(io_test::fixture("stage/lab.pgm"), dir / "lab.pgm",
                             std::filesystem::copy_options::overwrite_existing);
  io_test::write_bytes(dir / "w.world", text);
  return dir / "w.world";
}

TEST(ParseStageWorld, FindsTheFloorplanBlockAndSkipsCommentsAndOtherModels) {
  Result<StageFloorplan> plan = parse_stage_world(io_test::fixture("stage/lab.world"));
  ASSERT_TRUE(plan) << plan.error().message;
  EXPECT_EQ(plan->bitmap, io_test::fixture("stage/lab.pgm"));
  EXPECT_EQ(plan->size_m, (Vec2{8.0, 3.0}));
  EXPECT_EQ(plan->center_m, (Vec2{1.0, 2.0}));
  EXPECT_EQ(plan->yaw_rad, 0.0);
  EXPECT_EQ(plan->line, 23);
}

TEST(ReadStageWorld, ResamplesAnAnisotropicBitmapWithoutOpeningWalls) {
  Result<OccupancyGrid> g = read_stage_world(io_test::fixture("stage/lab.world"));
  ASSERT_TRUE(g) << g.error().message;
  // 8 x 2 px over 8 x 3 m: 1 m x 1.5 m pixels, 1 m cells; origin = pose - size / 2.
  EXPECT_EQ(g->geometry(), GridGeometry({-3.0, 0.5}, 1.0, 8, 3));
  EXPECT_EQ(g->known_count(), 24u);
  EXPECT_EQ(row_text(*g, '#', 2), "..#.....");  // top pixel row only
  EXPECT_EQ(row_text(*g, '#', 1), "..#....#");  // the middle cell row overlaps both pixel rows
  EXPECT_EQ(row_text(*g, '#', 0), ".......#");  // bottom pixel row only
}

TEST(ReadStageWorld, QuarterTurnYawRotatesTheGridCounterClockwise) {
  TempDir dir;
  const auto world =
      world_with(dir, "floorplan ( bitmap \"lab.pgm\" size [8 3 1] pose [10 20 0 90] )\n");
  Result<OccupancyGrid> g = read_stage_world(world);
  ASSERT_TRUE(g) << g.error().message;
  EXPECT_EQ(g->geometry(), GridGeometry({8.5, 16.0}, 1.0, 3, 8));
  // The model's right edge (x = 7, rows 0 and 1 blocked) becomes the top edge.
  EXPECT_EQ(row_text(*g, '#', 7), ".##");
  EXPECT_EQ(row_text(*g, '#', 2), "##.");  // the model's column 2 (rows 1 and 2 blocked)
  EXPECT_EQ(row_text(*g, '#', 0), "...");
}

TEST(ReadStageWorld, AcceptsMacrosStageThreePosesAndBitmapsCopiedBesideTheWorld) {
  TempDir dir;
  // The bitmap and size come from a define; the instance only names itself.
  Result<OccupancyGrid> macro =
      read_stage_world(world_with(dir,
                                  "define plan floorplan\n(\n  bitmap \"lab.pgm\"  # the map\n"
                                  "  size [8 3 0.5]\n)\nplan ( name \"x\" pose [0 0 0 0] )\n"));
  ASSERT_TRUE(macro) << macro.error().message;
  EXPECT_EQ(macro->geometry(), GridGeometry({-4.0, -1.5}, 1.0, 8, 3));
  EXPECT_EQ(macro->count_states().free, 20u);

  // Stage 3 poses have three values, [x y a].
  Result<OccupancyGrid> stage3 = read_stage_world(
      world_with(dir, "floorplan ( bitmap \"lab.pgm\" size [8 3] pose [4 1.5 0] )\n"));
  ASSERT_TRUE(stage3) << stage3.error().message;
  EXPECT_EQ(stage3->geometry().origin(), (Vec2{0.0, 0.0}));

  // "bitmaps/lab.pgm" is not there, but lab.pgm beside the world is.
  Result<StageFloorplan> beside =
      parse_stage_world(world_with(dir, "floorplan ( bitmap \"bitmaps/lab.pgm\" size [8 3 1] )\n"));
  ASSERT_TRUE(beside) << beside.error().message;
  EXPECT_EQ(beside->bitmap, dir / "lab.pgm");
}

struct BrokenWorld {
  const char* world;  // whole file; lab.pgm sits beside it
  const char* expected;
};

const BrokenWorld kBrokenWorlds[] = {
    {"# no map here\nfloorplan ( size [8 3 1] )\n", "w.world: no model with a bitmap"},
    {"\nfloorplan\n(\n  bitmap \"lab.pgm\"\n)\n",
     "w.world:2: the floorplan block with the bitmap has no size"},
    {"floorplan ( bitmap \"lab.pgm\"\n size [8 -3 1] )\n",
     "w.world:2: size must be [w h z] with w, h > 0 metres, got [8 -3 1]"},
    {"floorplan (\n bitmap \"maps/gone.png\"\n size [1 1 1] )\n",
     "w.world:2: bitmap 'maps/gone.png' not found (looked for "},
    {"resolution 0.02\nfloorplan\n(\n  bitmap \"lab.pgm\"\n",
     "w.world:2: syntax error: '(' is never closed"},
    {"floorplan ( bitmap \"lab.pgm\" size [8 3 1] pose [0 0 0 30] )\n",
     "w.world:1: floorplan pose yaw 30 degrees is not supported"},
    {"floorplan ( bitmap \"lab.pgm\" size [8 3 1] ) ]\n",
     "w.world:1: syntax error: unexpected ']'"},
    {"floorplan ( bitmap \"lab.pgm\" size [8 3 1] pose [0 0] )\n",
     "w.world:1: pose must be [x y z a] (metres, degrees)"},
};

TEST(ReadStageWorld, EachBrokenWorldIsReportedWithItsFileLineAndProblem) {
  TempDir dir;
  Result<OccupancyGrid> missing = read_stage_world(dir / "none.world");
  ASSERT_FALSE(missing);
  EXPECT_THAT(missing.error().message, HasSubstr("none.world: no such file"));
  for (const BrokenWorld& c : kBrokenWorlds) {
    SCOPED_TRACE(c.world);
    Result<OccupancyGrid> g = read_stage_world(world_with(dir, c.world));
    ASSERT_FALSE(g);
    EXPECT_EQ(g.error().kind, ErrorKind::kInput);
    EXPECT_THAT(g.error().message, HasSubstr(c.expected));
    EXPECT_EQ(g.error().message.find('\n'), std::string::npos);
  }
  // A missing bitmap names both places it was looked for.
  Result<OccupancyGrid> gone =
      read_stage_world(world_with(dir, "floorplan ( bitmap \"maps/gone.png\" size [1 1 1] )\n"));
  ASSERT_FALSE(gone);
  EXPECT_THAT(gone.error().message, HasSubstr((dir / "maps" / "gone.png").string()));
  EXPECT_THAT(gone.error().message, HasSubstr((dir / "gone.png").string()));
}

struct RealWorld {
  const char* path;
  double resolution_m;
  int width, height;
  Vec2 origin;
  std::size_t free;
};

// Resolution, size and free cells computed independently (pure-Python PNG/PGM decoder, interval
// overlap resampling).
const RealWorld kRealWorlds[] = {
    {"maps/stage_bitmaps/autolab.world", 20.0 / 809, 809, 809, {-10, -10}, 623340},
    {"maps/stage_bitmaps/simple.world", 0.032, 500, 500, {-8, -8}, 244730},
    {"maps/stage_bitmaps/uoa_robotics_lab.world", 6.27 / 566, 566, 1418, {-3.135, -7.85}, 728029},
    {"maps/stage_bitmaps/everything.world", 40.0 / 1086, 1086, 489, {-20, -9}, 503705},
    // pose [-29.35 27 0 90]: the 540 x 587 px (54 x 58.7 m) map turned a quarter.
    {"maps/ros_map_server/willow_stage_ros/willow-erratic.world",
     0.1,
     587,
     540,
     {-58.7, 0},
     300466},
    // "../maps/willow-full-0.05.pgm" sits beside the world; 1165 x 945 px at 5 cm, turned a
    // quarter.
    {"maps/ros_map_server/willow_navigation_tutorials/willow-pr2-5cm.world",
     0.05,
     945,
     1165,
     {-47.25, 0},
     549308},
};

TEST(ReadStageWorld, ReadsTheRealStageWorlds) {
  for (const RealWorld& w : kRealWorlds) {
    const auto path = support::data_path(w.path);
    TESSERA_REQUIRE_DATA(path);
    Result<OccupancyGrid> g = read_stage_world(path);
    ASSERT_TRUE(g) << g.error().message;
    const GridGeometry& geo = g->geometry();
    EXPECT_NEAR(geo.resolution_m(), w.resolution_m, 1e-12) << w.path;
    EXPECT_EQ(geo.width(), w.width) << w.path;
    EXPECT_EQ(geo.height(), w.height) << w.path;
    EXPECT_NEAR(geo.origin().x, w.origin.x, 1e-9) << w.path;
    EXPECT_NEAR(geo.origin().y, w.origin.y, 1e-9) << w.path;
    EXPECT_EQ(g->known_count(), geo.size()) << w.path;
    EXPECT_EQ(g->count_states().free, w.free) << w.path;
  }
}

}  // namespace
}  // namespace tessera
