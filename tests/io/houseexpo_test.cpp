#include "tessera/io/houseexpo.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "io_test_util.hpp"
#include "support/data.hpp"

namespace tessera {
namespace {

using io_test::TempDir;
using ::testing::HasSubstr;

// A 2 m x 1 m rectangle with its corner at (1, 1).
const char* kRoom = R"({
  "id": "test",
  "room_num": 1,
  "bbox": {"min": [1.0, 1.0], "max": [3.0, 2.0]},
  "verts": [[1.0, 1.0], [3.0, 1.0], [3.0, 2.0], [1.0, 2.0]],
  "room_category": {"bedroom": [[1.0, 1.0, 3.0, 2.0]]}
})";

TEST(ReadHouseExpoJson, ContourBecomesOneFreeSpacePolygon) {
  TempDir dir;
  io_test::write_bytes(dir / "room.json", kRoom);
  Result<PolygonMap> plan = read_houseexpo_json(dir / "room.json");
  ASSERT_TRUE(plan) << plan.error().message;
  EXPECT_EQ(plan->meaning(), PolygonMap::Meaning::kFreeSpace);
  ASSERT_EQ(plan->polygons().size(), 1u);
  EXPECT_EQ(plan->polygons()[0].vertices.size(), 4u);
  EXPECT_EQ(plan->polygons()[0].vertices[1], (Vec2{3.0, 1.0}));
}

TEST(ReadHouseExpoMap, RasterisesWithOneCellOfMargin) {
  TempDir dir;
  io_test::write_bytes(dir / "room.json", kRoom);
  Result<OccupancyGrid> g = read_houseexpo_map(dir / "room.json", 0.25);
  ASSERT_TRUE(g) << g.error().message;
  EXPECT_EQ(g->geometry(), GridGeometry({0.75, 0.75}, 0.25, 10, 6));
  EXPECT_EQ(g->known_count(), 60u);
  // The contour follows cell borders, so exactly the 8 x 4 cells inside are free.
  EXPECT_EQ(g->count_states().free, 32u);
  EXPECT_EQ(g->state({0, 0}), CellState::kOccupied);
  EXPECT_EQ(g->state({1, 1}), CellState::kFree);
}

TEST(ReadHouseExpoJson, SyntaxErrorNamesTheLine) {
  TempDir dir;
  io_test::write_bytes(dir / "bad.json", "{\n  \"verts\": [[0, 0],\n   [1, 0]\n  \"id\": 3\n}\n");
  Result<PolygonMap> plan = read_houseexpo_json(dir / "bad.json");
  ASSERT_FALSE(plan);
  EXPECT_EQ(plan.error().kind, ErrorKind::kInput);
  EXPECT_THAT(plan.error().message, HasSubstr("bad.json:4: JSON syntax error"));
  EXPECT_EQ(plan.error().message.find('\n'), std::string::npos);
}

// nlohmann::json reports a number that overflows a double with an out_of_range exception, which
// once escaped the reader and aborted `tessera info` (exit 134).
TEST(ReadHouseExpoJson, NumberThatOverflowsADoubleIsAnInputErrorWithTheLine) {
  TempDir dir;
  io_test::write_bytes(dir / "big.json", "{\"id\": \"x\",\n \"verts\": [[0, 0], [-1e3085, 1]]}\n");
  Result<PolygonMap> plan = read_houseexpo_json(dir / "big.json");
  ASSERT_FALSE(plan);
  EXPECT_EQ(plan.error().kind, ErrorKind::kInput);
  EXPECT_THAT(plan.error().message,
              HasSubstr("big.json:2: JSON number out of range: '-1e3085' does not fit a double"));
}

TEST(ReadHouseExpoJson, NestingDeeperThanTheLimitIsAnInputError) {
  TempDir dir;
  io_test::write_bytes(dir / "deep.json", std::string(300, '[') + std::string(300, ']'));
  Result<PolygonMap> plan = read_houseexpo_json(dir / "deep.json");
  ASSERT_FALSE(plan);
  EXPECT_THAT(plan.error().message, HasSubstr("deep.json: JSON nested deeper than 256 levels"));
}

TEST(ReadHouseExpoMap, VerticesTooFarApartForAGridAreAnInputError) {
  TempDir dir;
  io_test::write_bytes(dir / "far.json", R"({"verts": [[-1e300, 0], [1e300, 0], [0, 1e300]]})");
  Result<OccupancyGrid> g = read_houseexpo_map(dir / "far.json", 0.05);
  ASSERT_FALSE(g);
  EXPECT_THAT(g.error().message, HasSubstr("far.json: a "));
  EXPECT_THAT(g.error().message, HasSubstr("is too large"));
}

TEST(ReadHouseExpoJson, MissingVertsIsAnError) {
  TempDir dir;
  io_test::write_bytes(dir / "nv.json", R"({"id": "x", "bbox": {}})");
  Result<PolygonMap> plan = read_houseexpo_json(dir / "nv.json");
  ASSERT_FALSE(plan);
  EXPECT_THAT(plan.error().message, HasSubstr("nv.json: missing 'verts'"));
}

TEST(ReadHouseExpoJson, FewerThanThreeVerticesIsAnError) {
  TempDir dir;
  io_test::write_bytes(dir / "two.json", R"({"verts": [[0, 0], [1, 1]]})");
  Result<PolygonMap> plan = read_houseexpo_json(dir / "two.json");
  ASSERT_FALSE(plan);
  EXPECT_THAT(plan.error().message,
              HasSubstr("two.json: 'verts' has 2 vertices, a contour needs at least 3"));
}

TEST(ReadHouseExpoJson, MalformedVertexNamesItsIndex) {
  TempDir dir;
  io_test::write_bytes(dir / "v.json", R"({"verts": [[0, 0], [1, "a"], [1, 1]]})");
  Result<PolygonMap> plan = read_houseexpo_json(dir / "v.json");
  ASSERT_FALSE(plan);
  EXPECT_THAT(plan.error().message, HasSubstr("v.json: verts[1] must be [x, y] (two numbers)"));
}

TEST(ReadHouseExpoMap, NonPositiveResolutionIsAnError) {
  TempDir dir;
  io_test::write_bytes(dir / "room.json", kRoom);
  Result<OccupancyGrid> g = read_houseexpo_map(dir / "room.json", 0.0);
  ASSERT_FALSE(g);
  EXPECT_THAT(g.error().message, HasSubstr("room.json: resolution must be > 0, got 0"));
}

TEST(ReadHouseExpoMap, ReadsTheRealHouse) {
  const auto path = support::data_path("maps/houseexpo/json/0a1b29dba355df2ab02630133187bfab.json");
  TESSERA_REQUIRE_DATA(path);
  Result<PolygonMap> plan = read_houseexpo_json(path);
  ASSERT_TRUE(plan) << plan.error().message;
  EXPECT_EQ(plan->corner_count(), 434u);
  Result<OccupancyGrid> g = read_houseexpo_map(path, 0.05);
  ASSERT_TRUE(g) << g.error().message;
  // bbox [0.1, 0.1]-[11.38, 10.85]: ceil(11.28 / 0.05) + 2 = 228, 10.75 / 0.05 + 2 = 217.
  const GridGeometry& geo = g->geometry();
  EXPECT_EQ(geo.width(), 228);
  EXPECT_EQ(geo.height(), 217);
  EXPECT_NEAR(geo.origin().x, 0.05, 1e-12);
  EXPECT_NEAR(geo.origin().y, 0.05, 1e-12);
  // Shoelace area 116.605 m^2 = 46642 cells; the cells the 116.9 m contour crosses (about 2339)
  // are occupied, so the free count lies between the two.
  const std::size_t free = g->count_states().free;
  EXPECT_LT(free, 46642u);
  EXPECT_GT(free, 46642u - 2 * 2339u);
}

}  // namespace
}  // namespace tessera
