#include "tessera/io/image_file.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>

#include "io_test_util.hpp"
#include "support/data.hpp"
#include "tessera/io/pgm.hpp"

namespace tessera {
namespace {

using io_test::TempDir;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

TEST(ImageFile, GreyPngRoundTripIsExact) {
  TempDir dir;
  GrayImage image(4, 3);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    image.pixels[i] = static_cast<std::uint8_t>(i * 20);
  }
  Result<std::string> png = encode_png(image);
  ASSERT_TRUE(png) << png.error().message;
  EXPECT_EQ(png->substr(1, 3), "PNG");
  io_test::write_bytes(dir / "g.png", *png);
  Result<GrayImage> back = read_gray_image(dir / "g.png");
  ASSERT_TRUE(back) << back.error().message;
  EXPECT_EQ(*back, image);
}

TEST(ImageFile, ColourPixelsBecomeTheMeanOfRedGreenAndBlueAndAlphaIsDropped) {
  TempDir dir;
  RgbImage image(3, 1);
  image.set(0, 0, {255, 0, 0});      // mean 85
  image.set(1, 0, {100, 150, 200});  // mean 150
  image.set(2, 0, {10, 10, 11});     // mean 10.33 -> 10
  Result<std::string> png = encode_png(image);
  ASSERT_TRUE(png) << png.error().message;
  io_test::write_bytes(dir / "c.png", *png);
  Result<GrayImage> grey = read_gray_image(dir / "c.png");
  ASSERT_TRUE(grey) << grey.error().message;
  EXPECT_THAT(grey->pixels, ElementsAre(85, 150, 10));
  // Opaque white, opaque black, half-transparent white, opaque (100, 150, 200).
  Result<GrayImage> rgba = read_gray_image(io_test::fixture("ros/rgba_4x1.png"));
  ASSERT_TRUE(rgba) << rgba.error().message;
  EXPECT_THAT(rgba->pixels, ElementsAre(255, 0, 255, 150));
}

TEST(ImageFile, ReadsPgmByItsContent) {
  TempDir dir;
  io_test::write_bytes(dir / "map.pgm", io_test::ascii_pgm({{1, 2, 3}}));
  Result<GrayImage> grey = read_gray_image(dir / "map.pgm");
  ASSERT_TRUE(grey) << grey.error().message;
  EXPECT_THAT(grey->pixels, ElementsAre(1, 2, 3));
}

TEST(ImageFile, BrokenFilesAreInputErrorsAndNothingIsPrinted) {
  TempDir dir;
  const std::string png = io_test::read_bytes(io_test::fixture("ros/rgba_4x1.png"));
  std::string damaged = png;
  damaged[45] = static_cast<char>(damaged[45] ^ 0x55);  // inside the IDAT data
  io_test::write_bytes(dir / "cut.png", png.substr(0, 60));
  io_test::write_bytes(dir / "bad.png", damaged);
  io_test::write_bytes(dir / "junk.png", "\x89PNG but then nothing useful");
  const struct {
    const char* file;
    const char* expected;
  } cases[] = {
      {"cut.png", "cut.png: cannot decode image: truncated PNG: chunk 'IDAT'"},
      {"bad.png", "bad.png: cannot decode image: damaged PNG: CRC mismatch in chunk 'IDAT'"},
      {"junk.png", "junk.png: cannot decode image"},
      {"nothing.png", "nothing.png: no such file"},
  };
  for (const auto& c : cases) {
    ::testing::internal::CaptureStderr();
    Result<GrayImage> grey = read_gray_image(dir / c.file);
    EXPECT_EQ(::testing::internal::GetCapturedStderr(), "") << c.file;  // libpng stays quiet
    ASSERT_FALSE(grey) << c.file;
    EXPECT_EQ(grey.error().kind, ErrorKind::kInput);
    EXPECT_THAT(grey.error().message, HasSubstr(c.expected));
  }
}

TEST(ImageFile, ReadsTheOneBitAutolabBitmap) {
  const auto path = support::data_path("maps/stage_bitmaps/autolab.png");
  TESSERA_REQUIRE_DATA(path);
  Result<GrayImage> grey = read_gray_image(path);
  ASSERT_TRUE(grey) << grey.error().message;
  EXPECT_EQ(grey->width, 809);
  EXPECT_EQ(grey->height, 689);
  EXPECT_TRUE(std::all_of(grey->pixels.begin(), grey->pixels.end(),
                          [](std::uint8_t v) { return v == 0 || v == 255; }));
  // 24185 dark pixels (counted independently with a pure-Python PNG decoder).
  EXPECT_EQ(std::count(grey->pixels.begin(), grey->pixels.end(), 0), 24185);
}

}  // namespace
}  // namespace tessera
