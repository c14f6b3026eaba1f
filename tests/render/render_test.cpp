#include "tessera/render/render.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "io/io_test_util.hpp"
#include "tessera/io/image_file.hpp"

namespace tessera {
namespace {

using io_test::TempDir;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

// 4 x 3 cells at 1 m, origin (0, 0): row 2 occupied, rows 0-1 free except the unknown cell (3, 0).
OccupancyGrid small_map() {
  OccupancyGrid g(GridGeometry({0, 0}, 1.0, 4, 3));
  for (int x = 0; x < 4; ++x) {
    g.set_probability({x, 2}, 1.0);
    g.set_probability({x, 1}, 0.0);
    if (x < 3) g.set_probability({x, 0}, 0.0);
  }
  return g;
}

// Colour at the centre of cell c for `ppc` pixels per cell (north up).
Rgb cell_color(const RgbImage& image, Cell c, int ppc, int height_cells) {
  return image.at(c.x * ppc + ppc / 2, (height_cells - 1 - c.y) * ppc + ppc / 2);
}

TEST(RenderImage, NorthUpWithProbabilityShadedGreyAndUnknownMidGrey) {
  const OccupancyGrid map = small_map();
  RenderLayers layers;
  layers.map = &map;
  Result<RgbImage> image = render_image(layers, 10);
  ASSERT_TRUE(image) << image.error().message;
  EXPECT_EQ(image->width, 40);
  EXPECT_EQ(image->height, 30);
  EXPECT_EQ(image->at(0, 0), (Rgb{0, 0, 0}));  // top-left pixel: cell (0, 2), occupied
  EXPECT_EQ(cell_color(*image, {1, 1}, 10, 3), (Rgb{255, 255, 255}));
  EXPECT_EQ(cell_color(*image, {3, 0}, 10, 3), kUnknownColor);
  EXPECT_EQ(image->at(39, 29), kUnknownColor);  // bottom-right pixel: cell (3, 0)

  OccupancyGrid grey(GridGeometry({0, 0}, 1.0, 1, 1));
  grey.set_probability({0, 0}, 0.25);
  layers.map = &grey;
  Result<RgbImage> shaded = render_image(layers, 1);
  ASSERT_TRUE(shaded);
  EXPECT_EQ(shaded->at(0, 0), (Rgb{191, 191, 191}));  // 255 * (1 - p)
}

TEST(RenderImage, TruthErrorsAreColoured) {
  const OccupancyGrid map = small_map();
  // Truth: cell (0, 1) is solid (map says free), cell (1, 2) is free (map says occupied).
  std::vector<std::uint8_t> solid = {0, 0, 0, 1, /**/ 1, 0, 0, 0, /**/ 1, 0, 1, 1};
  const World truth(GridGeometry({0, 0}, 1.0, 4, 3), solid);
  RenderLayers layers;
  layers.map = &map;
  layers.truth = &truth;
  Result<RgbImage> image = render_image(layers, 4);
  ASSERT_TRUE(image) << image.error().message;
  EXPECT_EQ(cell_color(*image, {0, 1}, 4, 3), kOccupiedAsEmptyColor);
  EXPECT_EQ(cell_color(*image, {1, 2}, 4, 3), kEmptyAsOccupiedColor);
  EXPECT_EQ(cell_color(*image, {0, 2}, 4, 3), (Rgb{0, 0, 0}));  // correct: occupied and solid
  EXPECT_EQ(cell_color(*image, {3, 0}, 4, 3), kUnknownColor);   // unknown is never an error
}

TEST(RenderImage, FrontierPathsAndRobotsAreDrawnOnTop) {
  const OccupancyGrid map = small_map();
  RenderLayers layers;
  layers.map = &map;
  layers.frontier = {{2, 0}, {99, 99}};  // cells outside the map are ignored
  layers.paths_m = {{{0.5, 0.5}, {0.9, 1.2}}, {{3.5, 1.5}}};
  layers.robots_m = {{0.2, 1.9}, {3.5, 1.5}};
  Result<RgbImage> image = render_image(layers, 20);
  ASSERT_TRUE(image) << image.error().message;
  EXPECT_EQ(cell_color(*image, {2, 0}, 20, 3), kFrontierColor);
  // Path 0 runs from the centre of cell (0, 0) to the centre of (0, 1): halfway is path colour.
  EXPECT_EQ(image->at(10, 40), kPathPalette[0]);
  EXPECT_EQ(cell_color(*image, {0, 1}, 20, 3), kPathPalette[0]);  // robot 0's dot
  EXPECT_EQ(cell_color(*image, {3, 1}, 20, 3), kPathPalette[1]);  // robot 1's dot
  EXPECT_EQ(cell_color(*image, {1, 0}, 20, 3), (Rgb{255, 255, 255}));
}

TEST(RenderImage, AutomaticScaleMakesTheLongSideAboutAThousandPixels) {
  EXPECT_EQ(auto_pixels_per_cell(4, 3), 250);
  EXPECT_EQ(auto_pixels_per_cell(384, 384), 3);
  EXPECT_EQ(auto_pixels_per_cell(1000, 20), 1);
  EXPECT_EQ(auto_pixels_per_cell(5000, 20), 1);
  const OccupancyGrid map = small_map();
  RenderLayers layers;
  layers.map = &map;
  Result<RgbImage> image = render_image(layers);
  ASSERT_TRUE(image);
  EXPECT_EQ(image->width, 1000);
  EXPECT_EQ(image->height, 750);
}

TEST(RenderImage, MissingMapOrNegativeScaleIsAnInputError) {
  RenderLayers layers;
  Result<RgbImage> none = render_image(layers);
  ASSERT_FALSE(none);
  EXPECT_EQ(none.error().kind, ErrorKind::kInput);
  EXPECT_THAT(none.error().message, HasSubstr("no map"));
  const OccupancyGrid map = small_map();
  layers.map = &map;
  Result<RgbImage> negative = render_image(layers, -2);
  ASSERT_FALSE(negative);
  EXPECT_THAT(negative.error().message, HasSubstr("got -2"));
  Result<RgbImage> huge = render_image(layers, 100000);
  ASSERT_FALSE(huge);
  EXPECT_THAT(huge.error().message, HasSubstr("too large"));
}

TEST(WritePng, WritesADecodablePngAtomically) {
  TempDir dir;
  const OccupancyGrid map = small_map();
  RenderLayers layers;
  layers.map = &map;
  ASSERT_TRUE(write_png(dir / "map.png", layers, 2));
  EXPECT_THAT(io_test::files_in(dir.path()), ElementsAre("map.png"));
  Result<GrayImage> back = read_gray_image(dir / "map.png");
  ASSERT_TRUE(back) << back.error().message;
  EXPECT_EQ(back->width, 8);
  EXPECT_EQ(back->height, 6);
  EXPECT_EQ(back->at(0, 0), 0);
  EXPECT_EQ(back->at(2, 5), 255);
  EXPECT_EQ(back->at(7, 5), 128);
}

TEST(WritePng, ErrorsNameTheFileAndLeaveNothing) {
  TempDir dir;
  RenderLayers layers;
  const Status no_map = write_png(dir / "map.png", layers);
  ASSERT_FALSE(no_map);
  EXPECT_THAT(no_map.error().message, HasSubstr("map.png"));
  const OccupancyGrid map = small_map();
  layers.map = &map;
  const Status no_dir = write_png(dir / "missing" / "map.png", layers);
  ASSERT_FALSE(no_dir);
  EXPECT_EQ(no_dir.error().kind, ErrorKind::kRuntime);
  EXPECT_TRUE(io_test::files_in(dir.path()).empty());
}

}  // namespace
}  // namespace tessera
