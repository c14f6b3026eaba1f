#include "tessera/io/movingai_map.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "io_test_util.hpp"
#include "support/data.hpp"

namespace tessera {
namespace {

using io_test::row_text;
using io_test::TempDir;
using ::testing::HasSubstr;

Result<OccupancyGrid> read_text(const TempDir& dir, const std::string& text) {
  io_test::write_bytes(dir / "t.map", text);
  return read_movingai_map(dir / "t.map");
}

TEST(ReadMovingAiMap, ReadsTheFixtureTopRowFirst) {
  Result<OccupancyGrid> g = read_movingai_map(io_test::fixture("movingai/tiny.map"), 0.5);
  ASSERT_TRUE(g) << g.error().message;
  EXPECT_EQ(g->geometry(), GridGeometry({0, 0}, 0.5, 5, 3));
  EXPECT_EQ(g->known_count(), 15u);
  // File rows "@.GST", "..W.O", ".....": G and S passable; @, T, W, O blocked.
  EXPECT_EQ(row_text(*g, '@', 2), "@...@");
  EXPECT_EQ(row_text(*g, '@', 1), "..@.@");
  EXPECT_EQ(row_text(*g, '@', 0), ".....");
  EXPECT_NEAR(*g->probability_at({0, 2}), 1.0, 1e-3);
  EXPECT_NEAR(*g->probability_at({1, 2}), 0.0, 1e-3);
}

TEST(ReadMovingAiMap, AcceptsWindowsLineEndsAndTrailingBlankLines) {
  TempDir dir;
  Result<OccupancyGrid> g =
      read_text(dir, "type octile\r\nheight 1\r\nwidth 2\r\nmap\r\n.@\r\n\r\n");
  ASSERT_TRUE(g) << g.error().message;
  EXPECT_EQ(row_text(*g, '@', 0), ".@");
}

TEST(ReadMovingAiMap, WrongHeaderNamesTheLine) {
  TempDir dir;
  Result<OccupancyGrid> g = read_text(dir, "type octile\nheigth 2\nwidth 2\nmap\n..\n..\n");
  ASSERT_FALSE(g);
  EXPECT_EQ(g.error().kind, ErrorKind::kInput);
  EXPECT_THAT(g.error().message, HasSubstr("t.map:2: bad Moving AI header"));
  EXPECT_THAT(g.error().message, HasSubstr("'heigth 2'"));
}

TEST(ReadMovingAiMap, NonNumericSizeIsAnError) {
  TempDir dir;
  Result<OccupancyGrid> g = read_text(dir, "type octile\nheight two\nwidth 2\nmap\n");
  ASSERT_FALSE(g);
  EXPECT_THAT(
      g.error().message,
      HasSubstr("t.map:2: bad Moving AI header: height must be a positive integer, got 'two'"));
}

TEST(ReadMovingAiMap, MissingMapLineIsAnError) {
  TempDir dir;
  Result<OccupancyGrid> g = read_text(dir, "type octile\nheight 1\nwidth 1\n");
  ASSERT_FALSE(g);
  EXPECT_THAT(g.error().message, HasSubstr("t.map: bad Moving AI header: no 'map' line"));
}

TEST(ReadMovingAiMap, TooFewRowsSaysHowMany) {
  TempDir dir;
  Result<OccupancyGrid> g = read_text(dir, "type octile\nheight 3\nwidth 2\nmap\n..\n..\n");
  ASSERT_FALSE(g);
  EXPECT_EQ(g.error().message, (dir / "t.map").string() + ":6: height says 3 but 2 rows follow");
}

TEST(ReadMovingAiMap, TooManyRowsNamesTheFirstExtraLine) {
  TempDir dir;
  Result<OccupancyGrid> g = read_text(dir, "type octile\nheight 1\nwidth 2\nmap\n..\n..\n");
  ASSERT_FALSE(g);
  EXPECT_EQ(g.error().message, (dir / "t.map").string() + ":6: height says 1 but 2 rows follow");
}

TEST(ReadMovingAiMap, ShortRowNamesItsLine) {
  TempDir dir;
  Result<OccupancyGrid> g = read_text(dir, "type octile\nheight 2\nwidth 3\nmap\n...\n..\n");
  ASSERT_FALSE(g);
  EXPECT_EQ(g.error().message,
            (dir / "t.map").string() + ":6: row 2 has 2 cells, expected width 3");
}

TEST(ReadMovingAiMap, NonPositiveCellSizeIsAnError) {
  Result<OccupancyGrid> g = read_movingai_map(io_test::fixture("movingai/tiny.map"), 0.0);
  ASSERT_FALSE(g);
  EXPECT_THAT(g.error().message, HasSubstr("tiny.map: cell size must be > 0, got 0"));
}

TEST(ReadMovingAiMap, MissingFileSaysSo) {
  TempDir dir;
  Result<OccupancyGrid> g = read_movingai_map(dir / "none.map");
  ASSERT_FALSE(g);
  EXPECT_THAT(g.error().message, HasSubstr("none.map: no such file"));
}

struct MovingAiMap {
  const char* name;
  int width, height;
  std::size_t passable;
};

// Passable ('.', 'G', 'S') counts made independently with Python.
const MovingAiMap kMovingAiMaps[] = {
    {"8room_000.map", 512, 512, 206642}, {"arena.map", 49, 49, 2054},
    {"den312d.map", 65, 81, 2445},       {"maze-128-128-2.map", 128, 128, 10858},
    {"maze-32-32-2.map", 32, 32, 666},   {"room-32-32-4.map", 32, 32, 682},
    {"room-64-64-8.map", 64, 64, 3232},
};

TEST(ReadMovingAiMap, ReadsEveryRealBenchmarkMap) {
  for (const MovingAiMap& m : kMovingAiMaps) {
    const auto path = support::data_path(std::string("maps/movingai/") + m.name);
    TESSERA_REQUIRE_DATA(path);
    Result<OccupancyGrid> g = read_movingai_map(path);
    ASSERT_TRUE(g) << g.error().message;
    EXPECT_EQ(g->geometry(), GridGeometry({0, 0}, 1.0, m.width, m.height)) << m.name;
    EXPECT_EQ(g->known_count(), g->geometry().size()) << m.name;
    EXPECT_EQ(g->count_states().free, m.passable) << m.name;
  }
}

TEST(ReadMovingAiMap, FirstFileRowIsTheTopOfTheGrid) {
  const auto path = support::data_path("maps/movingai/room-32-32-4.map");
  TESSERA_REQUIRE_DATA(path);
  Result<OccupancyGrid> g = read_movingai_map(path);
  ASSERT_TRUE(g) << g.error().message;
  EXPECT_EQ(row_text(*g, '@', 31).substr(0, 5), "@@@.@");  // file row 0
  EXPECT_EQ(row_text(*g, '@', 0).substr(0, 5), "@...@");   // last file row
}

}  // namespace
}  // namespace tessera
