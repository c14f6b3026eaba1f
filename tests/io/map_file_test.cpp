#include "tessera/io/map_file.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "io_test_util.hpp"
#include "support/data.hpp"

namespace tessera {
namespace {

using io_test::TempDir;
using ::testing::HasSubstr;

TEST(LoadMap, DispatchesOnTheExtension) {
  TempDir dir;
  io_test::write_bytes(dir / "m.pgm", io_test::ascii_pgm({{0, 255}}));
  io_test::write_bytes(dir / "m.YAML", "image: m.pgm\nresolution: 0.5\norigin: [0, 0, 0]\n");
  io_test::write_bytes(dir / "h.json", R"({"verts": [[0, 0], [1, 0], [1, 1], [0, 1]]})");

  Result<LoadedMap> yaml = load_map(dir / "m.YAML");
  ASSERT_TRUE(yaml) << yaml.error().message;
  EXPECT_EQ(yaml->format, "ros_map_server");
  EXPECT_EQ(yaml->map.geometry().resolution_m(), 0.5);

  Result<LoadedMap> image = load_map(dir / "m.pgm", {0.2});
  ASSERT_TRUE(image) << image.error().message;
  EXPECT_EQ(image->format, "image");
  EXPECT_EQ(image->map.geometry(), GridGeometry({0, 0}, 0.2, 2, 1));

  Result<LoadedMap> movingai = load_map(io_test::fixture("movingai/tiny.map"));
  ASSERT_TRUE(movingai) << movingai.error().message;
  EXPECT_EQ(movingai->format, "movingai");
  EXPECT_EQ(movingai->map.geometry().resolution_m(), 1.0);
  Result<LoadedMap> scaled = load_map(io_test::fixture("movingai/tiny.map"), {0.25});
  ASSERT_TRUE(scaled) << scaled.error().message;
  EXPECT_EQ(scaled->map.geometry().resolution_m(), 0.25);

  Result<LoadedMap> stage = load_map(io_test::fixture("stage/lab.world"));
  ASSERT_TRUE(stage) << stage.error().message;
  EXPECT_EQ(stage->format, "stage");

  Result<LoadedMap> house = load_map(dir / "h.json");
  ASSERT_TRUE(house) << house.error().message;
  EXPECT_EQ(house->format, "houseexpo");
  EXPECT_EQ(house->map.geometry().resolution_m(), 0.05);
}

TEST(LoadMap, RefusesWhatItCannotLoadWithAClearMessage) {
  TempDir dir;
  io_test::write_bytes(dir / "plan.png", "whatever");
  io_test::write_bytes(dir / "map.bmp", "x");
  io_test::write_bytes(dir / "bad.map", "type octile\nheight 2\n");
  const struct {
    std::filesystem::path path;
    MapLoadOptions options;
    std::string expected;
  } cases[] = {
      {dir / "plan.png", {}, "plan.png: a plain image needs a resolution"},
      {dir / "gone.yaml", {}, (dir / "gone.yaml").string() + ": no such file"},
      {dir / "map.bmp", {}, "map.bmp: unknown map format '.bmp' (supported: .yaml/.yml"},
      {io_test::fixture("movingai/tiny.map"), {-1.0}, "tiny.map: resolution must be > 0, got -1"},
      {dir / "bad.map", {}, "bad.map: bad Moving AI header"},  // the reader's own error
  };
  for (const auto& c : cases) {
    Result<LoadedMap> m = load_map(c.path, c.options);
    ASSERT_FALSE(m) << c.path;
    EXPECT_EQ(m.error().kind, ErrorKind::kInput);
    EXPECT_THAT(m.error().message, HasSubstr(c.expected));
  }
  Result<LoadedMap> bmp = load_map(dir / "map.bmp");
  ASSERT_FALSE(bmp);
  for (const char* ext : {".yaml", ".png", ".pgm", ".map", ".world", ".json"}) {
    EXPECT_THAT(bmp.error().message, HasSubstr(ext));
  }
}

TEST(LoadMap, LoadsOneRealMapOfEachFormat) {
  const struct {
    const char* path;
    const char* format;
    int width, height;
  } maps[] = {
      {"maps/ros_map_server/turtlebot3_world_humble/map.yaml", "ros_map_server", 384, 384},
      {"maps/stage_bitmaps/simple.world", "stage", 500, 500},
      {"maps/movingai/arena.map", "movingai", 49, 49},
      {"maps/houseexpo/json/0a1b29dba355df2ab02630133187bfab.json", "houseexpo", 228, 217},
      {"maps/braincorp/three_rooms.png", "image", 438, 474},
  };
  for (const auto& m : maps) {
    const auto path = support::data_path(m.path);
    TESSERA_REQUIRE_DATA(path);
    Result<LoadedMap> loaded =
        load_map(path, m.format == std::string("image") ? MapLoadOptions{0.03} : MapLoadOptions{});
    ASSERT_TRUE(loaded) << loaded.error().message;
    EXPECT_EQ(loaded->format, m.format);
    EXPECT_EQ(loaded->map.geometry().width(), m.width) << m.path;
    EXPECT_EQ(loaded->map.geometry().height(), m.height) << m.path;
  }
}

}  // namespace
}  // namespace tessera
