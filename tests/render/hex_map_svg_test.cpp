#include "tessera/render/hex_map_svg.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "io/io_test_util.hpp"
#include "tessera/io/image_file.hpp"

namespace tessera {
namespace {

using io_test::TempDir;
using ::testing::HasSubstr;

// A map taught along an L: east 1.5 m, north 1 m.
fusion::HexCellMap l_map() {
  fusion::HexCellMap map;
  for (int i = 0; i <= 150; ++i) (void)map.update({0.01 * i, 0.0, 0.0});
  for (int i = 0; i <= 100; ++i) (void)map.update({1.5, 0.01 * i, 1.57});
  return map;
}

std::size_t count(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + 1)) ++n;
  return n;
}

// Well-formed enough for any XML reader: one root, every element closed in order, quotes balanced.
::testing::AssertionResult well_formed_xml(const std::string& doc) {
  std::vector<std::string> open;
  std::size_t i = doc.find("?>");
  if (doc.rfind("<?xml", 0) != 0 || i == std::string::npos) {
    return ::testing::AssertionFailure() << "no XML declaration";
  }
  int roots = 0;
  for (i = doc.find('<', i); i != std::string::npos; i = doc.find('<', i + 1)) {
    const std::size_t end = doc.find('>', i);
    if (end == std::string::npos) return ::testing::AssertionFailure() << "unclosed tag at " << i;
    const std::string tag = doc.substr(i + 1, end - i - 1);
    if (count(tag, "\"") % 2 != 0) return ::testing::AssertionFailure() << "quotes in <" << tag;
    if (tag.find('<') != std::string::npos) return ::testing::AssertionFailure() << "< in tag";
    if (tag[0] == '/') {
      if (open.empty() || open.back() != tag.substr(1)) {
        return ::testing::AssertionFailure() << "mismatched </" << tag.substr(1) << ">";
      }
      open.pop_back();
    } else {
      const std::string name = tag.substr(0, tag.find_first_of(" /"));
      if (open.empty()) ++roots;
      if (tag.back() != '/') open.push_back(name);
    }
  }
  if (!open.empty()) return ::testing::AssertionFailure() << "<" << open.back() << "> not closed";
  if (roots != 1) return ::testing::AssertionFailure() << roots << " root elements";
  return ::testing::AssertionSuccess();
}

TEST(HexMapSvg, WritesAWellFormedSvgWithOneHexagonPerCellAndEveryLayer) {
  const fusion::HexCellMap map = l_map();
  ASSERT_GE(map.cell_count(), 8u);
  HexMapPicture pic;
  pic.map = &map;
  pic.image_nodes_m = {{0.0, 0.0}, {1.5, 1.0}};
  pic.taught_path_m = {{0, 0}, {1.5, 0}, {1.5, 1.0}};
  pic.repeated_path_m = {{0, 0.02}, {1.5, 1.0}};
  pic.true_path_m = {{0, -0.02}, {1.5, 1.0}};
  pic.start_cell = 0;
  pic.goal_cell = static_cast<std::ptrdiff_t>(map.current_cell());
  TempDir dir;
  const auto path = dir / "cells.svg";
  const Status s = write_hex_map_svg(path, pic);
  ASSERT_TRUE(s) << s.error().message;
  const std::string svg = io_test::read_bytes(path);
  EXPECT_TRUE(well_formed_xml(svg));
  EXPECT_EQ(count(svg, "<polygon class=\"cell\""), map.cell_count());
  EXPECT_EQ(count(svg, "<circle"), 2u);
  EXPECT_EQ(count(svg, "<polyline class=\"taught\""), 1u);
  EXPECT_EQ(count(svg, "<polyline class=\"repeated\""), 1u);
  EXPECT_EQ(count(svg, "<polyline class=\"true\""), 1u);
  EXPECT_EQ(count(svg, "class=\"start\""), 1u);
  EXPECT_EQ(count(svg, "class=\"goal\""), 1u);
  // One line per traversed adjacency pair: the robot walked a chain, so cells - 1 pairs.
  std::size_t pairs = 0;
  for (const fusion::HexCell& c : map.cells()) pairs += c.traversed.size();
  EXPECT_EQ(count(svg, "<line "), pairs / 2);
  EXPECT_EQ(pairs / 2, map.cell_count() - 1);
  // The cell hexagons are flat-topped, 0.3 m between flat edges at 100 px/m: the first cell's
  // polygon has two vertices on the same y, 30 px above two others.
  // Parsed by hand: <regex> trips GCC 12's -Wmaybe-uninitialized under ASan (an error with -Werror).
  const std::string key = "id=\"cell0\" points=\"";
  const std::size_t at = svg.find(key);
  ASSERT_NE(at, std::string::npos);
  const std::size_t begin = at + key.size();
  const std::size_t end = svg.find('"', begin);
  ASSERT_NE(end, std::string::npos);
  std::istringstream pts(svg.substr(begin, end - begin));
  std::vector<double> ys;
  double x = 0.0, y = 0.0;
  char comma = 0;
  while (pts >> x >> comma >> y) {
    ASSERT_EQ(comma, ',');
    ys.push_back(y);
  }
  ASSERT_EQ(ys.size(), 6u);
  EXPECT_NEAR(ys[1], ys[2], 0.011);         // top edge (corners at 60 and 120 degrees)
  EXPECT_NEAR(ys[4] - ys[1], 30.0, 0.011);  // bottom edge 0.3 m below
}

TEST(HexMapSvg, DrawsTheFloorPlanSolidCellsAsRowRunsUnderTheCells) {
  const fusion::HexCellMap map = l_map();
  // 4 x 3 cells of 1 m: the top row solid (one run), one solid cell in the bottom row.
  const World world(GridGeometry({-1.0, -1.0}, 1.0, 4, 3),
                    {0, 1, 0, 0, /**/ 0, 0, 0, 0, /**/ 1, 1, 1, 1});
  HexMapPicture pic;
  pic.map = &map;
  pic.floor_plan = &world;
  const Result<std::string> svg = render_hex_map_svg(pic);
  ASSERT_TRUE(svg) << svg.error().message;
  EXPECT_TRUE(well_formed_xml(*svg));
  const std::size_t floor = svg->find("<g id=\"floor_plan\"");
  const std::size_t cells = svg->find("<g id=\"cells\"");
  ASSERT_NE(floor, std::string::npos);
  EXPECT_LT(floor, cells);
  EXPECT_EQ(count(svg->substr(floor, cells - floor), "<rect "), 2u);
  // The picture covers the whole floor plan (4 m + 2 margins of 0.3 m at 100 px/m).
  EXPECT_THAT(*svg, HasSubstr("width=\"460\""));
}

TEST(HexMapPng, RastersTheSameDrawingAndWritesAPng) {
  const fusion::HexCellMap map = l_map();
  HexMapPicture pic;
  pic.map = &map;
  pic.goal_cell = 0;
  pic.pixels_per_m = 50.0;
  const Result<RgbImage> image = render_hex_map_image(pic);
  ASSERT_TRUE(image) << image.error().message;
  const Result<std::string> svg = render_hex_map_svg(pic);
  ASSERT_TRUE(svg);
  EXPECT_THAT(*svg, HasSubstr("width=\"" + std::to_string(image->width) + "\""));
  // Cell 0 is the goal: its centre pixel is the goal colour.
  const int cx = static_cast<int>(std::lround(0.3 * 50.0 + 0.3 / std::sqrt(3.0) * 50.0));
  bool found_goal = false;
  for (int row = 0; row < image->height && !found_goal; ++row) {
    found_goal = image->at(cx, row) == kHexGoalColor;
  }
  EXPECT_TRUE(found_goal);
  TempDir dir;
  ASSERT_TRUE(write_hex_map_png(dir / "cells.png", pic));
  const Result<GrayImage> back = read_gray_image(dir / "cells.png");
  ASSERT_TRUE(back) << back.error().message;
  EXPECT_EQ(back->width, image->width);
}

TEST(HexMapSvg, BadPicturesAreInputErrorsAndWriteNothing) {
  const fusion::HexCellMap map = l_map();
  const fusion::HexCellMap empty;
  TempDir dir;
  const auto path = dir / "cells.svg";
  HexMapPicture pic;
  Status s = write_hex_map_svg(path, pic);
  ASSERT_FALSE(s);
  EXPECT_EQ(s.error().kind, ErrorKind::kInput);
  EXPECT_THAT(s.error().message, HasSubstr("cells.svg: hex map picture: no map"));
  pic.map = &empty;
  EXPECT_THAT(write_hex_map_svg(path, pic).error().message, HasSubstr("no cells"));
  pic.map = &map;
  pic.goal_cell = 1000;
  EXPECT_THAT(write_hex_map_svg(path, pic).error().message, HasSubstr("goal cell 1000"));
  pic.goal_cell = -1;
  pic.pixels_per_m = 0.0;
  EXPECT_THAT(write_hex_map_png(dir / "cells.png", pic).error().message,
              HasSubstr("pixels per metre"));
  pic.pixels_per_m = 100.0;
  pic.true_path_m = {{0, 0}, {std::nan(""), 0}};
  EXPECT_THAT(write_hex_map_svg(path, pic).error().message, HasSubstr("true path point 1"));
  pic.true_path_m.clear();
  pic.pixels_per_m = 1e6;  // 2 m x 1 m at 1 px/um
  EXPECT_THAT(write_hex_map_png(dir / "cells.png", pic).error().message, HasSubstr("too large"));
  EXPECT_TRUE(io_test::files_in(dir.path()).empty());
  // A folder that does not exist: a runtime error, nothing left behind.
  pic.pixels_per_m = 100.0;
  s = write_hex_map_svg(dir / "missing" / "cells.svg", pic);
  ASSERT_FALSE(s);
  EXPECT_EQ(s.error().kind, ErrorKind::kRuntime);
  EXPECT_TRUE(io_test::files_in(dir.path()).empty());
}

}  // namespace
}  // namespace tessera
