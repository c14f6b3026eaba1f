#include "tessera/io/map_yaml.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "io_test_util.hpp"
#include "support/data.hpp"
#include "tessera/io/pgm.hpp"

namespace tessera {
namespace {

using io_test::TempDir;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

constexpr double kTol = 1e-3;  // set_probability clamps 0 and 1 to 1e-4 and 1 - 1e-4

// Writes "<name>.yaml" (with `yaml_body` after the image line) and the image beside it.
std::filesystem::path write_map(const TempDir& dir, const std::string& yaml_body,
                                const std::vector<std::vector<int>>& rows,
                                const std::string& name = "m") {
  io_test::write_bytes(dir / (name + ".pgm"), io_test::ascii_pgm(rows));
  io_test::write_bytes(dir / (name + ".yaml"), "image: " + name + ".pgm\n" + yaml_body);
  return dir / (name + ".yaml");
}

const std::string kPlainYaml =
    "resolution: 0.5\norigin: [-1.0, 2.0, 0.0]\nnegate: 0\n"
    "occupied_thresh: 0.65\nfree_thresh: 0.196\n";

// States of row y, left to right: 'o' occupied (p > 0.5), 'f' free, '?' unknown.
std::string row_states(const OccupancyGrid& g, int y) {
  std::string s;
  for (int x = 0; x < g.geometry().width(); ++x) {
    const CellState st = g.state({x, y});
    s += st == CellState::kUnknown ? '?' : st == CellState::kOccupied ? 'o' : 'f';
  }
  return s;
}

// Asserts that `r` failed with a kInput error whose message contains every piece.
template <typename T>
void expect_input_error(const Result<T>& r, std::initializer_list<std::string> pieces) {
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().kind, ErrorKind::kInput);
  EXPECT_EQ(r.error().message.find('\n'), std::string::npos) << "one line";
  for (const std::string& p : pieces) EXPECT_THAT(r.error().message, HasSubstr(p));
}

TEST(ParseMapYaml, ReadsEveryKey) {
  TempDir dir;
  const auto yaml = write_map(dir,
                              "mode: scale\nresolution: 0.05\norigin: [-10.5, -3, 1.5707963]\n"
                              "negate: 1\noccupied_thresh: 0.7\nfree_thresh: 0.2\n",
                              {{0}});
  Result<MapYaml> m = parse_map_yaml(yaml);
  ASSERT_TRUE(m) << m.error().message;
  EXPECT_EQ(m->image, dir / "m.pgm");
  EXPECT_DOUBLE_EQ(m->resolution_m, 0.05);
  EXPECT_DOUBLE_EQ(m->origin.x, -10.5);
  EXPECT_DOUBLE_EQ(m->origin.y, -3.0);
  EXPECT_NEAR(m->origin.theta, std::numbers::pi / 2, 1e-7);
  EXPECT_TRUE(m->negate);
  EXPECT_DOUBLE_EQ(m->occupied_thresh, 0.7);
  EXPECT_DOUBLE_EQ(m->free_thresh, 0.2);
  EXPECT_EQ(m->mode, MapYaml::Mode::kScale);
}

TEST(ParseMapYaml, OptionalKeysTakeMapServerDefaultsAndNegateAcceptsBooleans) {
  TempDir dir;
  Result<MapYaml> m = parse_map_yaml(write_map(dir, "resolution: 1\norigin: [0, 0, 0]\n", {{0}}));
  ASSERT_TRUE(m) << m.error().message;
  EXPECT_FALSE(m->negate);
  EXPECT_DOUBLE_EQ(m->occupied_thresh, 0.65);
  EXPECT_DOUBLE_EQ(m->free_thresh, 0.196);
  EXPECT_EQ(m->mode, MapYaml::Mode::kTrinary);
  Result<MapYaml> b =
      parse_map_yaml(write_map(dir, "resolution: 1\norigin: [0, 0, 0]\nnegate: true\n", {{0}}));
  ASSERT_TRUE(b) << b.error().message;
  EXPECT_TRUE(b->negate);
}

struct BrokenYaml {
  const char* yaml;  // whole file; "m.pgm" (one black pixel) sits beside it
  const char* expected;
};

// Each case: the message names the file, the line where there is one, and the problem.
const BrokenYaml kBrokenYamls[] = {
    {"image: m.pgm\nresolution: 0.05\norigin: [0, 0, 0\n", "YAML syntax error"},
    {"resolution: 0.05\norigin: [0, 0, 0]\n", "b.yaml: missing 'image'"},
    {"image: m.pgm\norigin: [0, 0, 0]\nresolution: -0.05\n",
     "b.yaml:3: resolution must be > 0, got -0.05"},
    {"image: m.pgm\norigin: [0, 0, 0]\n", "b.yaml: missing 'resolution'"},
    {"image: m.pgm\nresolution: fine\norigin: [0, 0, 0]\n",
     "b.yaml:2: resolution must be a number, got 'fine'"},
    {"image: m.pgm\nresolution: 1\norigin: [1, 2]\n",
     "b.yaml:3: origin must be [x, y, yaw] (3 numbers), got 2 elements"},
    {"image: m.pgm\nresolution: 1\n", "b.yaml: missing 'origin'"},
    {"image: m.pgm\nresolution: 1\norigin: [0, 0, 0]\nmode: fancy\n",
     "b.yaml:4: mode must be trinary, scale or raw, got 'fancy'"},
    {"image: m.pgm\nresolution: 1\norigin: [0, 0, 0]\nnegate: maybe\n",
     "b.yaml:4: negate must be 0, 1, true or false, got 'maybe'"},
    {"image: m.pgm\nresolution: 1\norigin: [0, 0, 0]\noccupied_thresh: 1.5\n",
     "b.yaml:4: occupied_thresh must be in [0, 1], got 1.5"},
    {"image: m.pgm\nresolution: 1\norigin: [0, 0, 0]\nfree_thresh: -0.1\n",
     "b.yaml:4: free_thresh must be in [0, 1], got -0.1"},
    {"image: m.pgm\nresolution: 1\norigin: [0, 0, 0]\noccupied_thresh: 0.3\nfree_thresh: 0.6\n",
     "b.yaml:5: free_thresh (0.6) must not exceed occupied_thresh (0.3)"},
    {"resolution: 1\norigin: [0, 0, 0]\nimage: gone.pgm\n",
     "b.yaml:3: image file 'gone.pgm' not found (looked for "},
};

TEST(ReadMapYaml, EachBrokenFileIsReportedWithItsFileLineAndProblem) {
  TempDir dir;
  io_test::write_bytes(dir / "m.pgm", io_test::ascii_pgm({{0}}));
  io_test::write_bytes(dir / "not_an_image.pgm", "hello");
  expect_input_error(read_map_yaml(dir / "nope.yaml"), {"nope.yaml: no such file"});
  for (const BrokenYaml& c : kBrokenYamls) {
    SCOPED_TRACE(c.yaml);
    io_test::write_bytes(dir / "b.yaml", c.yaml);
    expect_input_error(read_map_yaml(dir / "b.yaml"), {(dir / "b.yaml").string(), c.expected});
  }
  // An image that does not decode is reported under the image's own name.
  io_test::write_bytes(dir / "b.yaml",
                       "image: not_an_image.pgm\nresolution: 1\norigin: [0, 0, 0]\n");
  expect_input_error(read_map_yaml(dir / "b.yaml"),
                     {(dir / "not_an_image.pgm").string() + ": cannot decode image"});
}

TEST(ReadMapYaml, TrinaryFollowsMapServerThresholdsExactly) {
  TempDir dir;
  // occ = 1 - v/255: occupied when occ > 0.65 (v <= 89), free when occ < 0.196 (v >= 206).
  const auto yaml = write_map(dir, kPlainYaml, {{0, 89, 90, 204, 205, 206, 254, 255}});
  Result<OccupancyGrid> g = read_map_yaml(yaml);
  ASSERT_TRUE(g) << g.error().message;
  EXPECT_EQ(row_states(*g, 0), "oo???fff");
  EXPECT_NEAR(*g->probability_at({0, 0}), 1.0, kTol);
  EXPECT_NEAR(*g->probability_at({7, 0}), 0.0, kTol);
}

TEST(ReadMapYaml, ImageTopRowIsTheHighestCellRowAndOriginIsTheLowerLeftCorner) {
  TempDir dir;
  const auto yaml = write_map(dir, kPlainYaml, {{0, 255, 255}, {255, 255, 255}});
  Result<OccupancyGrid> g = read_map_yaml(yaml);
  ASSERT_TRUE(g) << g.error().message;
  EXPECT_EQ(g->geometry(), GridGeometry({-1.0, 2.0}, 0.5, 3, 2));
  EXPECT_EQ(row_states(*g, 1), "off");
  EXPECT_EQ(row_states(*g, 0), "fff");
}

TEST(ReadMapYaml, NegateMakesWhiteOccupied) {
  TempDir dir;
  const auto yaml =
      write_map(dir, "resolution: 1\norigin: [0, 0, 0]\nnegate: 1\n", {{0, 49, 50, 165, 166, 255}});
  Result<OccupancyGrid> g = read_map_yaml(yaml);
  ASSERT_TRUE(g) << g.error().message;
  // occ = v/255: free when < 0.196 (v <= 49), occupied when > 0.65 (v >= 166).
  EXPECT_EQ(row_states(*g, 0), "ff??oo");
}

TEST(ReadMapYaml, ScaleModeMapsTheMiddleLinearly) {
  TempDir dir;
  const auto yaml =
      write_map(dir, "resolution: 1\norigin: [0, 0, 0]\nmode: scale\n", {{0, 150, 255, 205}});
  Result<OccupancyGrid> g = read_map_yaml(yaml);
  ASSERT_TRUE(g) << g.error().message;
  EXPECT_NEAR(*g->probability_at({0, 0}), 1.0, kTol);
  // occ = 1 - 150/255 = 0.41176: rint((0.41176 - 0.196) / (0.65 - 0.196) * 100) = 48.
  EXPECT_NEAR(*g->probability_at({1, 0}), 0.48, 1e-6);
  EXPECT_NEAR(*g->probability_at({2, 0}), 0.0, kTol);
  // occ = 0.19608 is just above free_thresh: rint(0.0173) = 0 -> p = 0 but via the scale branch.
  EXPECT_NEAR(*g->probability_at({3, 0}), 0.0, kTol);
}

TEST(ReadMapYaml, RawModeTakesPixelValuesAsPercent) {
  TempDir dir;
  const auto yaml =
      write_map(dir, "resolution: 1\norigin: [0, 0, 0]\nmode: raw\n", {{0, 50, 100, 101, 255}});
  Result<OccupancyGrid> g = read_map_yaml(yaml);
  ASSERT_TRUE(g) << g.error().message;
  EXPECT_NEAR(*g->probability_at({0, 0}), 0.0, kTol);
  EXPECT_NEAR(*g->probability_at({1, 0}), 0.5, 1e-6);
  EXPECT_NEAR(*g->probability_at({2, 0}), 1.0, kTol);
  EXPECT_FALSE(g->known({3, 0}));
  EXPECT_FALSE(g->known({4, 0}));
}

TEST(ReadMapYaml, TrinaryAveragesAlphaInAndScaleTreatsTransparencyAsUnknown) {
  TempDir dir;
  std::filesystem::copy_file(io_test::fixture("ros/rgba_4x1.png"), dir / "rgba.png");
  // Pixels: opaque white, opaque black, white at alpha 128, opaque (100, 150, 200).
  io_test::write_bytes(dir / "t.yaml", "image: rgba.png\nresolution: 1\norigin: [0, 0, 0]\n");
  io_test::write_bytes(dir / "s.yaml",
                       "image: rgba.png\nresolution: 1\norigin: [0, 0, 0]\nmode: scale\n");
  Result<OccupancyGrid> trinary = read_map_yaml(dir / "t.yaml");
  ASSERT_TRUE(trinary) << trinary.error().message;
  // shade = (R + G + B + A) / 4 / 255: 1, 0.25, 0.875, 0.691.
  EXPECT_EQ(row_states(*trinary, 0), "fof?");
  Result<OccupancyGrid> scale = read_map_yaml(dir / "s.yaml");
  ASSERT_TRUE(scale) << scale.error().message;
  EXPECT_EQ(row_states(*scale, 0), "fo?f");
  EXPECT_NEAR(*scale->probability_at({3, 0}), 0.48, 1e-6);  // occ = 1 - 450/765
}

OccupancyGrid sample_map() {
  // 4 x 2 at 0.25 m: row 1 = occupied, free, unknown, p 0.5; row 0 = p 0.25, p 0.26, p 0.65, p 0.64
  OccupancyGrid g(GridGeometry({-1.5, 0.25}, 0.25, 4, 2));
  g.set_probability({0, 1}, 1.0);
  g.set_probability({1, 1}, 0.0);
  g.set_probability({3, 1}, 0.5);
  g.set_probability({0, 0}, 0.25);
  g.set_probability({1, 0}, 0.26);
  g.set_probability({2, 0}, 0.65);
  g.set_probability({3, 0}, 0.64);
  return g;
}

TEST(WriteMapYaml, WritesMapSaverGoldenFilesThatReadBackAsTheSameStates) {
  TempDir dir;
  const OccupancyGrid original = sample_map();
  ASSERT_TRUE(write_map_yaml(original, dir / "lab.yaml"));
  EXPECT_THAT(io_test::files_in(dir.path()), ElementsAre("lab.pgm", "lab.yaml"));
  EXPECT_EQ(io_test::read_bytes(dir / "lab.yaml"),
            "image: lab.pgm\nmode: trinary\nresolution: 0.25\norigin: [-1.5, 0.25, 0]\n"
            "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n");
  std::string pgm = "P5\n4 2\n255\n";
  for (const int v : {0, 254, 205, 205, 254, 205, 0, 205}) pgm += static_cast<char>(v);
  EXPECT_EQ(io_test::read_bytes(dir / "lab.pgm"), pgm);

  Result<OccupancyGrid> back = read_map_yaml(dir / "lab.yaml");
  ASSERT_TRUE(back) << back.error().message;
  EXPECT_EQ(back->geometry(), original.geometry());
  EXPECT_EQ(row_states(*back, 1), "of??");
  EXPECT_EQ(row_states(*back, 0), "f?o?");
}

TEST(WriteMapYaml, FailuresNameTheFileAndLeaveNothingBehind) {
  TempDir dir;
  MapSaveOptions options;
  options.free_thresh = 0.8;
  const Status bad_options = write_map_yaml(sample_map(), dir / "lab.yaml", options);
  ASSERT_FALSE(bad_options);
  EXPECT_EQ(bad_options.error().kind, ErrorKind::kInput);
  EXPECT_THAT(bad_options.error().message, HasSubstr("lab.yaml"));
  EXPECT_THAT(bad_options.error().message,
              HasSubstr("free_thresh (0.8) must be below occupied_thresh"));

  const Status no_folder = write_map_yaml(sample_map(), dir / "missing" / "lab.yaml");
  ASSERT_FALSE(no_folder);
  EXPECT_EQ(no_folder.error().kind, ErrorKind::kRuntime);
  EXPECT_THAT(no_folder.error().message, HasSubstr("lab."));

  const Status empty =
      write_map_yaml(OccupancyGrid(GridGeometry({0, 0}, 1.0, 0, 0)), dir / "e.yaml");
  ASSERT_FALSE(empty);
  EXPECT_THAT(empty.error().message, HasSubstr("e.yaml: cannot save an empty map"));

  EXPECT_TRUE(io_test::files_in(dir.path()).empty());
}

struct RealMap {
  const char* path;
  int width, height;
  double resolution_m;
  Vec2 origin;
  std::size_t free, occupied, unknown;
};

// Counts made independently with a pure-Python PGM reader and map_server's trinary rule.
const RealMap kRealMaps[] = {
    {"maps/ros_map_server/nav2_tb3_sandbox/tb3_sandbox.yaml",
     384,
     384,
     0.05,
     {-10, -10},
     7903,
     870,
     138683},
    {"maps/ros_map_server/nav2_warehouse/warehouse.yaml",
     1006,
     1674,
     0.03,
     {-15.1, -25},
     1422292,
     30951,
     230801},
    {"maps/ros_map_server/turtlebot3_world_humble/map.yaml",
     384,
     384,
     0.05,
     {-10, -10},
     7939,
     795,
     138722},
    {"maps/explore_bench/corridor.yaml", 250, 250, 0.1, {-12.5, -12.5}, 27262, 1298, 33940},
    {"maps/explore_bench/loop.yaml", 250, 250, 0.1, {-12.5, -12.5}, 19041, 1360, 42099},
    {"maps/explore_bench/room.yaml", 250, 250, 0.1, {-12.5, -12.5}, 37830, 1980, 22690},
};

TEST(ReadMapYaml, ReadsEveryRealMapServerMap) {
  for (const RealMap& m : kRealMaps) {
    const auto path = support::data_path(m.path);
    TESSERA_REQUIRE_DATA(path);
    Result<OccupancyGrid> g = read_map_yaml(path);
    ASSERT_TRUE(g) << g.error().message;
    EXPECT_EQ(g->geometry(), GridGeometry(m.origin, m.resolution_m, m.width, m.height)) << m.path;
    const CellCounts counts = g->count_states();
    EXPECT_EQ(counts.free, m.free) << m.path;
    EXPECT_EQ(counts.occupied, m.occupied) << m.path;
    EXPECT_EQ(g->geometry().size() - g->known_count(), m.unknown) << m.path;
  }
}

TEST(WriteMapYaml, RealMapSurvivesARoundTrip) {
  const auto path = support::data_path("maps/ros_map_server/nav2_tb3_sandbox/tb3_sandbox.yaml");
  TESSERA_REQUIRE_DATA(path);
  Result<OccupancyGrid> original = read_map_yaml(path);
  ASSERT_TRUE(original) << original.error().message;
  TempDir dir;
  ASSERT_TRUE(write_map_yaml(*original, dir / "copy.yaml"));
  Result<OccupancyGrid> back = read_map_yaml(dir / "copy.yaml");
  ASSERT_TRUE(back) << back.error().message;
  ASSERT_EQ(back->geometry(), original->geometry());
  const GridGeometry& g = original->geometry();
  int differing = 0;
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) differing += back->state({x, y}) != original->state({x, y});
  }
  EXPECT_EQ(differing, 0);
  // The original image uses only 0, 205 and 254, so the written PGM reproduces it byte for byte.
  Result<GrayImage> a = read_pgm(path.parent_path() / "tb3_sandbox.pgm");
  Result<GrayImage> b = read_pgm(dir / "copy.pgm");
  ASSERT_TRUE(a && b);
  EXPECT_EQ(*a, *b);
}

}  // namespace
}  // namespace tessera
