#include "tessera/render/wall_textures.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "support/data.hpp"
#include "support/temp_dir.hpp"
#include "tessera/io/image_file.hpp"

namespace tessera {
namespace {

using ::testing::HasSubstr;

TEST(WallTextures, ReadsRtabmapsPhotosInNumericOrder) {
  const auto folder = support::data_path("rgbd/rtabmap_loop_samples/images");
  TESSERA_REQUIRE_DATA(folder);
  const auto files = list_texture_images(folder);
  ASSERT_TRUE(files.ok()) << files.error().message;
  ASSERT_EQ(files->size(), 84u);
  EXPECT_EQ((*files)[0].filename(), "1.jpg");
  EXPECT_EQ((*files)[1].filename(), "2.jpg");
  EXPECT_EQ((*files)[9].filename(), "10.jpg");
  EXPECT_EQ(files->back().filename(), "84.jpg");
  const auto textures = read_wall_textures({(*files)[0], (*files)[83]});
  ASSERT_TRUE(textures.ok()) << textures.error().message;
  EXPECT_EQ((*textures)[0].width, 512);
  EXPECT_EQ((*textures)[0].height, 384);
  EXPECT_TRUE((*textures)[0].consistent());
  EXPECT_EQ((*textures)[1].name, "84.jpg");
}

TEST(WallTextures, FindsTheTumColourFramesButNotTheirDepth) {
  const auto folder = support::data_path("rgbd/tum_fr1_xyz_pairs");
  TESSERA_REQUIRE_DATA(folder);
  const auto files = list_texture_images(folder, /*recursive=*/true, "img_");
  ASSERT_TRUE(files.ok()) << files.error().message;
  ASSERT_EQ(files->size(), 4u);
  EXPECT_EQ((*files)[0].parent_path().filename(), "case_1");
  const auto t = read_wall_texture((*files)[0]);
  ASSERT_TRUE(t.ok());
  EXPECT_EQ(t->width, 640);
  // A 16-bit depth image is no photo: the error names the file.
  const auto depth = read_wall_texture(folder / "case_1" / "dep_prev.png");
  ASSERT_FALSE(depth.ok());
  EXPECT_EQ(depth.error().kind, ErrorKind::kInput);
  EXPECT_THAT(depth.error().message,
              HasSubstr("dep_prev.png: a wall texture must be an 8-bit grey, RGB or RGBA image, "
                        "got 16-bit with 1 channel"));
}

TEST(WallTextures, GreyImagesBecomeGreyRgb) {
  support::TempDir dir;
  GrayImage g(3, 2, 77);
  support::write_bytes(dir / "g.png", *encode_png(g));
  const auto t = read_wall_texture(dir / "g.png");
  ASSERT_TRUE(t.ok());
  EXPECT_EQ(t->rgb, std::vector<std::uint8_t>(18, 77));
}

TEST(WallTextures, BadFoldersAndFilesAreNamed) {
  support::TempDir dir;
  EXPECT_THAT(list_texture_images(dir / "nope").error().message, HasSubstr("nope: not a folder"));
  support::write_bytes(dir / "notes.txt", "hello");
  EXPECT_THAT(list_texture_images(dir.path()).error().message, HasSubstr("no .jpg, .jpeg or .png"));
  support::write_bytes(dir / "broken.jpg", "not a jpeg");
  const auto broken = read_wall_textures({dir / "broken.jpg"});
  ASSERT_FALSE(broken.ok());
  EXPECT_THAT(broken.error().message, HasSubstr("broken.jpg: cannot decode image"));
  EXPECT_THAT(read_wall_texture(dir / "missing.png").error().message,
              HasSubstr("missing.png: no such file"));
}

}  // namespace
}  // namespace tessera
