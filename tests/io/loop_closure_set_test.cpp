#include "tessera/io/loop_closure_set.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "support/data.hpp"
#include "support/temp_dir.hpp"

namespace tessera {
namespace {

using ::testing::HasSubstr;

const std::filesystem::path kSet = "rgbd/rtabmap_loop_samples";

void put_u16(std::string& s, std::uint16_t v) {
  s.push_back(static_cast<char>(v & 0xff));
  s.push_back(static_cast<char>(v >> 8));
}
void put_u32(std::string& s, std::uint32_t v) {
  for (int k = 0; k < 4; ++k) s.push_back(static_cast<char>((v >> (8 * k)) & 0xff));
}

/// An 8-bit grey-palette BMP (as samples_GT.bmp is) of `rows` (top row first).
std::string bmp8(const std::vector<std::vector<std::uint8_t>>& rows) {
  const auto h = static_cast<std::uint32_t>(rows.size());
  const auto w = static_cast<std::uint32_t>(rows.front().size());
  const std::uint32_t stride = (w + 3) / 4 * 4;
  const std::uint32_t offset = 14 + 40 + 1024;
  std::string s = "BM";
  put_u32(s, offset + stride * h);
  put_u32(s, 0);
  put_u32(s, offset);
  put_u32(s, 40);
  put_u32(s, w);
  put_u32(s, h);  // positive: bottom row first
  put_u16(s, 1);
  put_u16(s, 8);
  put_u32(s, 0);
  put_u32(s, stride * h);
  put_u32(s, 2835);
  put_u32(s, 2835);
  put_u32(s, 256);
  put_u32(s, 256);
  for (int i = 0; i < 256; ++i) {
    for (int c = 0; c < 3; ++c) s.push_back(static_cast<char>(i));
    s.push_back('\0');
  }
  for (std::uint32_t r = h; r-- > 0;) {
    for (std::uint8_t v : rows[r]) s.push_back(static_cast<char>(v));
    s.append(stride - w, '\0');
  }
  return s;
}

std::vector<std::vector<std::uint8_t>> matrix(int rows, int cols, std::uint8_t fill = 0) {
  return std::vector<std::vector<std::uint8_t>>(static_cast<std::size_t>(rows),
                                                std::vector<std::uint8_t>(cols, fill));
}

TEST(LoopClosureSet, ReadsRtabmapsGroundTruth) {
  const auto path = support::data_path(kSet / "samples_GT.bmp");
  TESSERA_REQUIRE_DATA(path);
  const Result<LoopGroundTruth> gt = read_loop_ground_truth(path, 84);
  ASSERT_TRUE(gt.ok()) << gt.error().message;
  EXPECT_EQ(gt->size, 84);
  int loops = 0;
  for (int i = 0; i < 84; ++i) {
    for (int j = 0; j < 84; ++j) loops += gt->is_loop(i, j) ? 1 : 0;
  }
  EXPECT_EQ(loops, 228);                // SOURCES.md
  EXPECT_EQ(gt->queries_with_loop(), 44);
  EXPECT_FALSE(gt->has_loop(39));       // image 40: first pass
  EXPECT_TRUE(gt->has_loop(40));        // image 41 revisits images 1 to 3
  EXPECT_TRUE(gt->is_loop(40, 0));
  EXPECT_FALSE(gt->is_loop(40, 39));
  EXPECT_FALSE(gt->is_loop(0, 40));     // strictly lower-triangular: rows are queries
}

TEST(LoopClosureSet, ReadsAHandMadeMatrixRowsAsQueries) {
  support::TempDir dir;
  auto m = matrix(3, 3);
  m[2][0] = 255;  // image 3 revisits image 1
  support::write_bytes(dir / "gt.bmp", bmp8(m));
  const Result<LoopGroundTruth> gt = read_loop_ground_truth(dir / "gt.bmp", 3);
  ASSERT_TRUE(gt.ok()) << gt.error().message;
  EXPECT_TRUE(gt->is_loop(2, 0));
  EXPECT_FALSE(gt->is_loop(0, 2));
  EXPECT_EQ(gt->queries_with_loop(), 1);
}

TEST(LoopClosureSet, AMatrixOfTheWrongSizeIsAnInputErrorNamingTheFile) {
  support::TempDir dir;
  support::write_bytes(dir / "gt.bmp", bmp8(matrix(84, 80)));
  const Result<LoopGroundTruth> gt = read_loop_ground_truth(dir / "gt.bmp", 84);
  ASSERT_FALSE(gt.ok());
  EXPECT_EQ(gt.error().kind, ErrorKind::kInput);
  EXPECT_THAT(gt.error().message, HasSubstr("gt.bmp"));
  EXPECT_THAT(gt.error().message, HasSubstr("expected an 84 x 84 matrix"));
  EXPECT_THAT(gt.error().message, HasSubstr("got 80 x 84"));
}

TEST(LoopClosureSet, AValueOtherThanZeroOr255IsAnInputErrorWithItsPlace) {
  support::TempDir dir;
  auto m = matrix(4, 4);
  m[3][1] = 17;
  support::write_bytes(dir / "gt.bmp", bmp8(m));
  const Result<LoopGroundTruth> gt = read_loop_ground_truth(dir / "gt.bmp", 4);
  ASSERT_FALSE(gt.ok());
  EXPECT_THAT(gt.error().message, HasSubstr("row 3, column 1"));
  EXPECT_THAT(gt.error().message, HasSubstr("got 17"));
}

TEST(LoopClosureSet, AMissingOrUndecodableFileIsAnInputError) {
  support::TempDir dir;
  const Result<LoopGroundTruth> missing = read_loop_ground_truth(dir / "none.bmp", 84);
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.error().kind, ErrorKind::kInput);
  EXPECT_THAT(missing.error().message, HasSubstr("none.bmp: no such file"));
  support::write_bytes(dir / "junk.bmp", "not an image");
  const Result<LoopGroundTruth> junk = read_loop_ground_truth(dir / "junk.bmp", 84);
  ASSERT_FALSE(junk.ok());
  EXPECT_THAT(junk.error().message, HasSubstr("junk.bmp: cannot decode image"));
}

TEST(LoopClosureSet, ReadsTheImagesInNumericOrderAsGrey) {
  const auto folder = support::data_path(kSet / "images");
  TESSERA_REQUIRE_DATA(folder);
  const Result<std::vector<GrayImage>> images = read_loop_closure_images(folder, 84);
  ASSERT_TRUE(images.ok()) << images.error().message;
  ASSERT_EQ(images->size(), 84u);
  for (const GrayImage& g : *images) {
    EXPECT_EQ(g.width, 512);
    EXPECT_EQ(g.height, 384);
    EXPECT_EQ(g.pixels.size(), 512u * 384u);
  }
  EXPECT_NE((*images)[0].pixels, (*images)[1].pixels);
}

TEST(LoopClosureSet, AMissingImageOrFolderIsAnInputErrorNamingIt) {
  const auto folder = support::data_path(kSet / "images");
  TESSERA_REQUIRE_DATA(folder);
  const Result<std::vector<GrayImage>> too_many = read_loop_closure_images(folder, 85);
  ASSERT_FALSE(too_many.ok());
  EXPECT_EQ(too_many.error().kind, ErrorKind::kInput);
  EXPECT_THAT(too_many.error().message, HasSubstr("85.jpg: no such file"));
  support::TempDir dir;
  const Result<std::vector<GrayImage>> no_folder = read_loop_closure_images(dir / "nope", 3);
  ASSERT_FALSE(no_folder.ok());
  EXPECT_THAT(no_folder.error().message, HasSubstr("nope: not a folder"));
  support::write_bytes(dir / "1.jpg", "garbage");
  const Result<std::vector<GrayImage>> junk = read_loop_closure_images(dir.path(), 1);
  ASSERT_FALSE(junk.ok());
  EXPECT_THAT(junk.error().message, HasSubstr("1.jpg: cannot decode image"));
}

}  // namespace
}  // namespace tessera
