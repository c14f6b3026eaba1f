#include "tessera/io/tum_rgbd_sequence.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "support/data.hpp"
#include "support/temp_dir.hpp"
#include "tessera/io/image_file.hpp"

namespace tessera {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

/// A small synthetic frame: a colour ramp and depths from 0.5 to 3.6 m, some 0.
RgbdFrame small_frame(double t_s, int width = 32, int height = 24) {
  RgbdFrame f;
  f.t_s = t_s;
  f.width = width;
  f.height = height;
  f.intrinsics = {40.0, 41.0, 15.5, 11.5, width, height};
  f.rgb.resize(3 * f.pixel_count());
  f.depth_m.resize(f.pixel_count());
  for (std::size_t i = 0; i < f.pixel_count(); ++i) {
    f.rgb[3 * i] = static_cast<std::uint8_t>(i);
    f.rgb[3 * i + 1] = static_cast<std::uint8_t>(2 * i + static_cast<std::size_t>(t_s * 10));
    f.rgb[3 * i + 2] = 200;
    f.depth_m[i] = i % 7 == 0 ? 0.0F : static_cast<float>(0.5 + 0.004 * static_cast<double>(i));
  }
  return f;
}

/// Writes a valid sequence of `n` small frames at 30 Hz into dir / name.
fs::path write_small_sequence(const support::TempDir& dir, const std::string& name, int n = 3) {
  TumRgbdSequenceContent c;
  c.frame_count = static_cast<std::size_t>(n);
  c.frame_at = [](std::size_t i) { return small_frame(1000.0 + static_cast<double>(i) / 30.0); };
  const fs::path folder = dir / name;
  const Status s = write_tum_rgbd_sequence(folder, c);
  EXPECT_TRUE(s.ok()) << s.error().message;
  return folder;
}

void write_text(const fs::path& path, const std::string& text) { support::write_bytes(path, text); }

TEST(TumRgbdSequence, WritingReplacesAnOldFolderAndAFailedWriteLeavesNothing) {
  support::TempDir dir;
  const fs::path folder = write_small_sequence(dir, "seq", 2);
  write_small_sequence(dir, "seq", 4);  // replaces
  ASSERT_EQ(TumRgbdSequence::open(folder)->size(), 4u);
  TumRgbdSequenceContent bad;
  bad.frame_count = 3;
  bad.frame_at = [](std::size_t i) { return small_frame(i == 2 ? 0.0 : 5.0 + static_cast<double>(i)); };
  const Status s = write_tum_rgbd_sequence(folder, bad);
  ASSERT_FALSE(s.ok());
  EXPECT_THAT(s.error().message, HasSubstr("frame 2: stamp 0.000000 s does not increase"));
  EXPECT_EQ(TumRgbdSequence::open(folder)->size(), 4u);  // untouched
  for (const auto& e : fs::directory_iterator(dir.path())) {
    EXPECT_EQ(e.path().filename(), "seq") << "left behind: " << e.path();
  }
}

TEST(TumRgbdSequence, AssociatesGreedilyBySmallestDifferenceEachStampOnce) {
  support::TempDir dir;
  const fs::path folder = write_small_sequence(dir, "seq", 3);
  // Re-list the three images under chosen stamps: colour 1.000 and 1.010 compete for depth
  // 1.008 (0.002 apart wins); colour 1.100 and depth 1.125 are 0.025 apart: no pair.
  const auto seq0 = TumRgbdSequence::open(folder);
  ASSERT_TRUE(seq0.ok());
  const std::string r0 = seq0->entry(0).rgb_path.filename().string();
  const std::string r1 = seq0->entry(1).rgb_path.filename().string();
  const std::string r2 = seq0->entry(2).rgb_path.filename().string();
  write_text(folder / "rgb.txt", "# colour\n1.000 rgb/" + r0 + "\n1.010 rgb/" + r1 +
                                     "\n1.100 rgb/" + r2 + "\n");
  write_text(folder / "depth.txt", "1.008 depth/" + r1 + "\n1.125 depth/" + r2 + "\n");
  const auto seq = TumRgbdSequence::open(folder);
  ASSERT_TRUE(seq.ok()) << seq.error().message;
  ASSERT_EQ(seq->size(), 1u);
  EXPECT_DOUBLE_EQ(seq->entry(0).t_s, 1.010);
  EXPECT_DOUBLE_EQ(seq->entry(0).depth_t_s, 1.008);
}

TEST(TumRgbdSequence, GroundTruthIsInterpolatedBetweenNeighbours) {
  support::TempDir dir;
  const fs::path folder = write_small_sequence(dir, "seq", 2);
  // Frames at 1000.000000 and 1000.033333; truth at 999.99 and 1000.01 (x 0 -> 1), and far away.
  write_text(folder / "groundtruth.txt",
             "# t x y z qx qy qz qw\n999.99 0 0 0 0 0 0 1\n1000.01 1 2 0 0 0 0 1\n"
             "1000.2 5 5 5 0 0 0 1\n");
  const auto seq = TumRgbdSequence::open(folder);
  ASSERT_TRUE(seq.ok()) << seq.error().message;
  ASSERT_TRUE(seq->entry(0).has_truth);
  EXPECT_NEAR(seq->entry(0).T_world_camera.position_m.x(), 0.5, 1e-9);
  EXPECT_NEAR(seq->entry(0).T_world_camera.position_m.y(), 1.0, 1e-9);
  EXPECT_FALSE(seq->entry(1).has_truth);  // 0.023 s from the nearest sample
}

TEST(TumRgbdSequence, RealTumFramesWithFreiburg1IntrinsicsFromTheFolderName) {
  const fs::path pairs = support::data_path("rgbd/tum_fr1_xyz_pairs/case_1");
  TESSERA_REQUIRE_DATA(pairs);
  support::TempDir dir;
  const fs::path folder = dir / "rgbd_dataset_freiburg1_xyz_cut";
  fs::create_directories(folder / "rgb");
  fs::create_directories(folder / "depth");
  fs::copy_file(pairs / "img_prev.png", folder / "rgb" / "1305031102.175304.png");
  fs::copy_file(pairs / "dep_prev.png", folder / "depth" / "1305031102.160407.png");
  write_text(folder / "rgb.txt", "# color images\n1305031102.175304 rgb/1305031102.175304.png\n");
  write_text(folder / "depth.txt", "# depth\n1305031102.160407 depth/1305031102.160407.png\n");
  const auto seq = TumRgbdSequence::open(folder);
  ASSERT_TRUE(seq.ok()) << seq.error().message;
  EXPECT_EQ(seq->intrinsics_source(), IntrinsicsSource::kFreiburg1);
  EXPECT_DOUBLE_EQ(seq->intrinsics().fx_px, 517.3);
  EXPECT_FALSE(seq->has_ground_truth_file());
  const auto frame = seq->load(0);
  ASSERT_TRUE(frame.ok()) << frame.error().message;
  EXPECT_EQ(frame->width, 640);
  std::size_t valid = 0;
  for (float z : frame->depth_m) valid += z > 0.0F && z >= 0.8F && z <= 4.0F;
  EXPECT_GT(valid, frame->pixel_count() / 2);  // SOURCES.md: about 75 % valid, 0.85 to 3.7 m
}

// --- bad input: one-line errors naming the file (and line) -------------------------------------

TEST(TumRgbdSequenceErrors, NoDepthList) {
  support::TempDir dir;
  const fs::path folder = write_small_sequence(dir, "seq");
  fs::remove(folder / "depth.txt");
  const auto r = TumRgbdSequence::open(folder);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().kind, ErrorKind::kInput);
  EXPECT_THAT(r.error().message, HasSubstr("seq/depth.txt: no such file"));
}

TEST(TumRgbdSequenceErrors, MissingDepthImageNamesTheListAndLine) {
  support::TempDir dir;
  const fs::path folder = write_small_sequence(dir, "seq");
  const auto seq = TumRgbdSequence::open(folder);
  fs::remove(seq->entry(1).depth_path);
  const auto r = TumRgbdSequence::open(folder);
  ASSERT_FALSE(r.ok());
  // depth.txt has two comment lines, so frame 1 is on line 4.
  EXPECT_THAT(r.error().message, HasSubstr("seq/depth.txt:4: depth/"));
  EXPECT_THAT(r.error().message, HasSubstr(": no such file"));
}

TEST(TumRgbdSequenceErrors, DepthThatIsNot16Bit) {
  support::TempDir dir;
  const fs::path folder = write_small_sequence(dir, "seq");
  const auto seq = TumRgbdSequence::open(folder);
  support::write_bytes(seq->entry(0).depth_path, *encode_png(GrayImage(32, 24, 9)));
  const auto frame = seq->load(0);
  ASSERT_FALSE(frame.ok());
  EXPECT_EQ(frame.error().kind, ErrorKind::kInput);
  EXPECT_THAT(frame.error().message, HasSubstr(seq->entry(0).depth_path.string() +
                                               ": depth must be a 16-bit single-channel PNG"));
}

TEST(TumRgbdSequenceErrors, ColourAndDepthOfDifferentSizes) {
  support::TempDir dir;
  const fs::path folder = write_small_sequence(dir, "seq");
  TumRgbdSequenceContent c;
  c.frame_count = 1;
  c.frame_at = [](std::size_t) { return small_frame(1.0, 16, 12); };
  ASSERT_TRUE(write_tum_rgbd_sequence(dir / "small", c).ok());
  const auto small = TumRgbdSequence::open(dir / "small");
  const auto seq = TumRgbdSequence::open(folder);
  fs::copy_file(small->entry(0).depth_path, seq->entry(0).depth_path,
                fs::copy_options::overwrite_existing);
  const auto frame = seq->load(0);
  ASSERT_FALSE(frame.ok());
  EXPECT_THAT(frame.error().message, HasSubstr("depth image is 16 x 12 but colour image"));
}

TEST(TumRgbdSequenceErrors, NoFramePairWithin20Milliseconds) {
  support::TempDir dir;
  const fs::path folder = write_small_sequence(dir, "seq", 1);
  const auto seq = TumRgbdSequence::open(folder);
  const std::string depth_name = "depth/" + seq->entry(0).depth_path.filename().string();
  write_text(folder / "depth.txt", "1000.021 " + depth_name + "\n");
  const auto r = TumRgbdSequence::open(folder);
  ASSERT_FALSE(r.ok());
  EXPECT_THAT(r.error().message, HasSubstr("no colour and depth stamps within 0.02 s"));
  EXPECT_THAT(r.error().message, HasSubstr("seq/rgb.txt"));
}

TEST(TumRgbdSequenceErrors, MalformedListLines) {
  support::TempDir dir;
  const fs::path folder = write_small_sequence(dir, "seq", 1);
  write_text(folder / "rgb.txt", "# c\n1000.0 rgb/a.png extra\n");
  EXPECT_THAT(TumRgbdSequence::open(folder).error().message,
              HasSubstr("seq/rgb.txt:2: expected 't filename', got 3 fields"));
  write_text(folder / "rgb.txt", "abc rgb/a.png\n");
  EXPECT_THAT(TumRgbdSequence::open(folder).error().message,
              HasSubstr("seq/rgb.txt:1: expected a time stamp in seconds, got 'abc'"));
}

TEST(TumRgbdSequenceErrors, BadIntrinsicsOrNoneAtAll) {
  support::TempDir dir;
  const fs::path folder = write_small_sequence(dir, "seq", 1);
  write_text(folder / "intrinsics.txt", "# k\n500 500 320\n");
  EXPECT_THAT(TumRgbdSequence::open(folder).error().message,
              HasSubstr("seq/intrinsics.txt:2: expected 'fx fy cx cy [width height]', got 3"));
  fs::remove(folder / "intrinsics.txt");
  EXPECT_THAT(TumRgbdSequence::open(folder).error().message,
              HasSubstr("intrinsics.txt: no such file, and the folder's name names no TUM camera"));
  // Four numbers: the size comes from the images.
  write_text(folder / "intrinsics.txt", "40 41 15.5 11.5\n");
  const auto seq = TumRgbdSequence::open(folder);
  ASSERT_TRUE(seq.ok()) << seq.error().message;
  EXPECT_EQ(seq->intrinsics().width_px, 32);
  EXPECT_TRUE(seq->load(0).ok());
}

TEST(TumRgbdSequenceErrors, BadGroundTruthLine) {
  support::TempDir dir;
  const fs::path folder = write_small_sequence(dir, "seq", 1);
  write_text(folder / "groundtruth.txt", "1000 1 2 3\n");
  EXPECT_THAT(TumRgbdSequence::open(folder).error().message,
              HasSubstr("seq/groundtruth.txt:1: expected 8 fields"));
}

TEST(TumRgbdSequenceErrors, NotAFolder) {
  support::TempDir dir;
  EXPECT_THAT(TumRgbdSequence::open(dir / "nothing").error().message,
              HasSubstr("nothing: not a folder"));
}

}  // namespace
}  // namespace tessera
