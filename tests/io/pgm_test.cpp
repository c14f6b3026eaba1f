#include "tessera/io/pgm.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "io_test_util.hpp"
#include "support/data.hpp"

namespace tessera {
namespace {

using io_test::TempDir;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

TEST(Pgm, BinaryRoundTripIsExact) {
  GrayImage image(3, 2);
  image.pixels = {0, 1, 2, 128, 254, 255};
  const std::string bytes = encode_pgm(image);
  EXPECT_EQ(bytes.substr(0, 11), "P5\n3 2\n255\n");
  Result<GrayImage> back = decode_pgm(bytes, "mem.pgm");
  ASSERT_TRUE(back) << back.error().message;
  EXPECT_EQ(*back, image);
}

TEST(Pgm, ReadsAsciiWithCommentsAnywhereInTheHeader) {
  const std::string text =
      "P2 # magic\n# a comment line\n3 # width\n2\n# maxval next\n255\n"
      "0 10 20\n# comment between pixels\n30 40 255\n";
  Result<GrayImage> image = decode_pgm(text, "a.pgm");
  ASSERT_TRUE(image) << image.error().message;
  EXPECT_EQ(image->width, 3);
  EXPECT_EQ(image->height, 2);
  EXPECT_THAT(image->pixels, ElementsAre(0, 10, 20, 30, 40, 255));
  EXPECT_EQ(image->at(2, 1), 255);  // x 2, image row 1 (the bottom row)
}

TEST(Pgm, BinaryWithCommentInHeaderReads) {
  std::string bytes = "P5\n# CREATOR: GIMP PNM Filter Version 1.1\n2 1\n255\n";
  bytes += '\x07';
  bytes += '\xfe';
  Result<GrayImage> image = decode_pgm(bytes, "gimp.pgm");
  ASSERT_TRUE(image) << image.error().message;
  EXPECT_THAT(image->pixels, ElementsAre(7, 254));
}

TEST(Pgm, SixteenBitSamplesAreScaledToEightBits) {
  std::string bytes = "P5 3 1 65535\n";
  for (const unsigned v : {0u, 32896u, 65535u}) {  // 32896 = 128 * 257
    bytes += static_cast<char>(v >> 8);
    bytes += static_cast<char>(v & 0xFF);
  }
  Result<GrayImage> image = decode_pgm(bytes, "deep.pgm");
  ASSERT_TRUE(image) << image.error().message;
  EXPECT_THAT(image->pixels, ElementsAre(0, 128, 255));
}

TEST(Pgm, SmallMaxvalIsScaledToFullRange) {
  Result<GrayImage> image = decode_pgm("P2 3 1 15\n0 8 15\n", "four_bit.pgm");
  ASSERT_TRUE(image) << image.error().message;
  EXPECT_THAT(image->pixels, ElementsAre(0, 136, 255));
}

TEST(Pgm, WrongMagicIsNotAPgm) {
  Result<GrayImage> image = decode_pgm("P6\n1 1\n255\nabc", "colour.ppm");
  ASSERT_FALSE(image);
  EXPECT_EQ(image.error().kind, ErrorKind::kInput);
  EXPECT_THAT(image.error().message, HasSubstr("colour.ppm"));
  EXPECT_THAT(image.error().message, HasSubstr("not a PGM file"));
  EXPECT_THAT(image.error().message, HasSubstr("'P6'"));
}

TEST(Pgm, BadHeaderNamesTheLineAndTheField) {
  Result<GrayImage> image = decode_pgm("P2\n# comment\n4 x\n255\n", "bad.pgm");
  ASSERT_FALSE(image);
  EXPECT_EQ(image.error().message, "bad.pgm:3: bad PGM header: expected height, got 'x'");
}

TEST(Pgm, ZeroWidthOrHugeMaxvalIsABadHeader) {
  Result<GrayImage> zero = decode_pgm("P5 0 3 255\n", "zero.pgm");
  ASSERT_FALSE(zero);
  EXPECT_THAT(zero.error().message, HasSubstr("zero.pgm:1: bad PGM header: width and height"));
  Result<GrayImage> deep = decode_pgm("P5 1 1 70000\n", "deep.pgm");
  ASSERT_FALSE(deep);
  EXPECT_THAT(deep.error().message, HasSubstr("maxval must be in 1..65535, got 70000"));
}

TEST(Pgm, TruncatedBinaryDataSaysHowManyBytesWereExpected) {
  Result<GrayImage> image = decode_pgm("P5\n3 2\n255\nabcd", "short.pgm");
  ASSERT_FALSE(image);
  EXPECT_EQ(image.error().message,
            "short.pgm: truncated pixel data: expected 3*2 = 6 bytes, got 4");
}

TEST(Pgm, TruncatedAsciiDataSaysHowManyValuesWereExpected) {
  Result<GrayImage> image = decode_pgm("P2\n2 2\n255\n1 2\n3\n", "short.pgm");
  ASSERT_FALSE(image);
  EXPECT_THAT(image.error().message,
              HasSubstr("truncated pixel data: expected 2*2 = 4 values, got 3"));
}

TEST(Pgm, AsciiValueAboveMaxvalIsAnErrorWithItsLine) {
  Result<GrayImage> image = decode_pgm("P2\n2 1\n15\n3\n16\n", "over.pgm");
  ASSERT_FALSE(image);
  EXPECT_EQ(image.error().message, "over.pgm:5: bad PGM pixel data: value 16 exceeds maxval 15");
}

TEST(Pgm, MissingFileSaysSo) {
  TempDir dir;
  Result<GrayImage> image = read_pgm(dir / "absent.pgm");
  ASSERT_FALSE(image);
  EXPECT_EQ(image.error().kind, ErrorKind::kInput);
  EXPECT_THAT(image.error().message, HasSubstr("absent.pgm: no such file"));
}

TEST(Pgm, ReadsAFileFromDisk) {
  TempDir dir;
  io_test::write_bytes(dir / "a.pgm", io_test::ascii_pgm({{0, 255}, {100, 200}}));
  Result<GrayImage> image = read_pgm(dir / "a.pgm");
  ASSERT_TRUE(image) << image.error().message;
  EXPECT_THAT(image->pixels, ElementsAre(0, 255, 100, 200));
}

TEST(Pgm, ReadsTheWillowGarageMap) {
  const auto path =
      support::data_path("maps/ros_map_server/willow_navigation_tutorials/willow-full.pgm");
  TESSERA_REQUIRE_DATA(path);
  Result<GrayImage> image = read_pgm(path);
  ASSERT_TRUE(image) << image.error().message;
  EXPECT_EQ(image->width, 584);
  EXPECT_EQ(image->height, 526);
}

}  // namespace
}  // namespace tessera
