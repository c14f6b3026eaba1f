#include "tessera/io/rgbd_pair_folder.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <numbers>

#include "support/data.hpp"
#include "support/temp_dir.hpp"
#include "tessera/io/image_file.hpp"

namespace tessera {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

const std::filesystem::path kPairs = "rgbd/tum_fr1_xyz_pairs";

/// A writable copy of a real pair folder.
std::filesystem::path copy_case(const support::TempDir& dir, const char* name) {
  const auto to = dir.path() / name;
  std::filesystem::copy(support::data_path(kPairs / name), to);
  return to;
}

TEST(RgbdPairFolder, ReadsTheRealCase1) {
  TESSERA_REQUIRE_DATA(support::data_path(kPairs / "case_1"));
  const Result<RgbdPair> pair = read_rgbd_pair_folder(support::data_path(kPairs / "case_1"));
  ASSERT_TRUE(pair.ok()) << pair.error().message;
  for (const RgbdFrame* f : {&pair->prev, &pair->curr}) {
    EXPECT_TRUE(f->consistent());
    EXPECT_EQ(f->width, 640);
    EXPECT_EQ(f->height, 480);
    EXPECT_DOUBLE_EQ(f->intrinsics.fx_px, 517.3);  // TUM fr1 by default
    // SOURCES.md: about 75% of the pixels hold a depth, spanning 0.85 to 3.7 m.
    std::size_t valid = 0;
    float lo = 100.0f, hi = 0.0f;
    for (const float z : f->depth_m) {
      if (z <= 0.0f) continue;
      ++valid;
      lo = std::min(lo, z);
      hi = std::max(hi, z);
    }
    EXPECT_NEAR(static_cast<double>(valid) / static_cast<double>(f->pixel_count()), 0.75, 0.1);
    EXPECT_GT(lo, 0.4f);
    EXPECT_LT(hi, 5.0f);
  }
  EXPECT_FALSE(pair->has_intrinsics_file);
  ASSERT_TRUE(pair->has_ground_truth);
  EXPECT_NEAR(pair->T_world_prev.position_m.x(), 1.3303, 1e-12);  // pose_prev.txt
  // pairs_gt.txt: case_1 moves 0.0216 m and 1.379 degrees, T_prev_curr row 0 = 0.999964 -0.002156
  // -0.008249 -0.001302.
  const Eigen::Isometry3d T = pair->T_prev_curr_truth();
  EXPECT_NEAR(T.translation().norm(), 0.0216, 1e-4);
  EXPECT_NEAR(Eigen::AngleAxisd(T.linear()).angle() * 180.0 / std::numbers::pi, 1.379, 2e-3);
  EXPECT_NEAR(T(0, 1), -0.002156, 2e-5);
  EXPECT_NEAR(T(0, 3), -0.001302, 2e-5);
}

TEST(RgbdPairFolder, ColourIsRgbOrderAndDepthIsValueOver5000) {
  TESSERA_REQUIRE_DATA(support::data_path(kPairs / "case_1"));
  // A colour PNG written here (io writes only 8-bit PNGs) with the real 16-bit depth image.
  support::TempDir dir;
  RgbImage colour(640, 480, {10, 20, 30});
  colour.set(0, 0, {255, 0, 0});
  const Result<std::string> png = encode_png(colour);
  ASSERT_TRUE(png.ok());
  support::write_bytes(dir / "c.png", *png);
  const Result<RgbdFrame> f =
      read_rgbd_frame(dir / "c.png", support::data_path(kPairs / "case_1/dep_prev.png"),
                      PinholeIntrinsics::tum_freiburg1());
  ASSERT_TRUE(f.ok()) << f.error().message;
  EXPECT_EQ(f->rgb[0], 255);
  EXPECT_EQ(f->rgb[1], 0);
  EXPECT_EQ(f->rgb[3], 10);
  EXPECT_EQ(f->rgb[5], 30);
  // Every depth is a multiple of 1/5000 m.
  for (std::size_t i = 0; i < f->depth_m.size(); i += 997) {
    const double raw = f->depth_m[i] * 5000.0;
    EXPECT_NEAR(raw, std::round(raw), 2e-3 * raw + 1e-3);
  }
}

TEST(RgbdPairFolder, IntrinsicsFileOverridesTheDefault) {
  TESSERA_REQUIRE_DATA(support::data_path(kPairs / "case_1"));
  support::TempDir dir;
  const auto folder = copy_case(dir, "case_1");
  support::write_bytes(folder / "intrinsics.txt", "# fx fy cx cy\n525 525 319.5 239.5\n");
  const Result<RgbdPair> pair = read_rgbd_pair_folder(folder);
  ASSERT_TRUE(pair.ok()) << pair.error().message;
  EXPECT_TRUE(pair->has_intrinsics_file);
  EXPECT_DOUBLE_EQ(pair->curr.intrinsics.fx_px, 525.0);
  EXPECT_DOUBLE_EQ(pair->curr.intrinsics.cy_px, 239.5);
  EXPECT_EQ(pair->curr.intrinsics.width_px, 640);
}

TEST(RgbdPairFolder, WithoutPosesThereIsNoGroundTruth) {
  TESSERA_REQUIRE_DATA(support::data_path(kPairs / "case_1"));
  support::TempDir dir;
  const auto folder = copy_case(dir, "case_1");
  std::filesystem::remove(folder / "pose_prev.txt");
  std::filesystem::remove(folder / "pose_curr.txt");
  const Result<RgbdPair> pair = read_rgbd_pair_folder(folder);
  ASSERT_TRUE(pair.ok()) << pair.error().message;
  EXPECT_FALSE(pair->has_ground_truth);
}

/// Bad input: one kInput error naming the file (and line where there is one).
struct BadCase {
  const char* name;
  void (*spoil)(const std::filesystem::path& folder);
  const char* file;
  const char* message;
};

void expect_error(const std::filesystem::path& folder, const BadCase& c) {
  const Result<RgbdPair> pair = read_rgbd_pair_folder(folder);
  ASSERT_FALSE(pair.ok()) << c.name;
  EXPECT_EQ(pair.error().kind, ErrorKind::kInput) << c.name;
  EXPECT_THAT(pair.error().message, HasSubstr(c.file)) << c.name;
  EXPECT_THAT(pair.error().message, HasSubstr(c.message)) << c.name;
  EXPECT_THAT(pair.error().message, Not(HasSubstr("\n"))) << c.name;
}

TEST(RgbdPairFolder, BadInputIsAOneLineErrorNamingTheFile) {
  TESSERA_REQUIRE_DATA(support::data_path(kPairs / "case_1"));
  const BadCase cases[] = {
      {"missing depth",
       [](const std::filesystem::path& f) { std::filesystem::remove(f / "dep_curr.png"); },
       "dep_curr.png", "no such file"},
      {"8-bit depth",
       [](const std::filesystem::path& f) {
         support::write_bytes(f / "dep_prev.png", *encode_png(GrayImage(640, 480)));
       },
       "dep_prev.png",
       "depth must be a 16-bit single-channel PNG (value / 5000 = metres), got "
       "8-bit with 1 channel"},
      {"colour depth size mismatch",
       [](const std::filesystem::path& f) {
         support::write_bytes(f / "img_prev.png", *encode_png(RgbImage(320, 240)));
       },
       "dep_prev.png", "depth image is 640 x 480 but colour image"},
      {"truncated colour",
       [](const std::filesystem::path& f) {
         const std::string bytes = support::read_bytes(f / "img_curr.png");
         support::write_bytes(f / "img_curr.png", bytes.substr(0, bytes.size() / 2));
       },
       "img_curr.png", "truncated PNG"},
      {"malformed pose line",
       [](const std::filesystem::path& f) {
         support::write_bytes(f / "pose_prev.txt", "\n1.3160 0.6254 1.6302\n");
       },
       "pose_prev.txt:2:", "expected 7 numbers 'tx ty tz qx qy qz qw', got 3 fields"},
      {"pose not a number",
       [](const std::filesystem::path& f) {
         support::write_bytes(f / "pose_curr.txt", "1 2 3 0 0 x 1\n");
       },
       "pose_curr.txt:1:", "expected a number, got 'x'"},
      {"quaternion not unit",
       [](const std::filesystem::path& f) {
         support::write_bytes(f / "pose_curr.txt", "1 2 3 0 0 0 2\n");
       },
       "pose_curr.txt", "unit length"},
      {"one pose only",
       [](const std::filesystem::path& f) { std::filesystem::remove(f / "pose_prev.txt"); },
       "pose_prev.txt", "no such file"},
      {"bad intrinsics",
       [](const std::filesystem::path& f) {
         support::write_bytes(f / "intrinsics.txt", "517.3 516.5 318.6\n");
       },
       "intrinsics.txt:1:", "expected 4 numbers 'fx fy cx cy'"},
  };
  for (const BadCase& c : cases) {
    support::TempDir dir;
    const auto folder = copy_case(dir, "case_1");
    c.spoil(folder);
    expect_error(folder, c);
  }
}

TEST(RgbdPairFolder, MissingFolderIsAnInputError) {
  const Result<RgbdPair> pair = read_rgbd_pair_folder("/nonexistent/pair");
  ASSERT_FALSE(pair.ok());
  EXPECT_EQ(pair.error().kind, ErrorKind::kInput);
  EXPECT_THAT(pair.error().message, HasSubstr("/nonexistent/pair: not a folder"));
}

}  // namespace
}  // namespace tessera
