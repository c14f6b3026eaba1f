#include "tessera/sim/poster.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <vector>

#include "tessera/sim/builtin_world.hpp"

namespace tessera {
namespace {

using ::testing::HasSubstr;

std::vector<WallTexture> textures() {
  WallTexture a{4, 3, std::vector<std::uint8_t>(36, 100), "a"};
  WallTexture b{2, 4, std::vector<std::uint8_t>(24, 200), "b"};
  return {a, b};
}

const std::vector<WallFace>& office_faces() {
  static const std::vector<WallFace> faces = find_wall_faces(builtin_world("office", 0.1)).faces;
  return faces;
}

TEST(PlacePosters, SameSeedSamePostersAnotherSeedOthers) {
  const PosterPlacementOptions o;
  const auto a = place_posters(office_faces(), textures(), o, 5);
  const auto b = place_posters(office_faces(), textures(), o, 5);
  const auto c = place_posters(office_faces(), textures(), o, 6);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].face, b[i].face);
    EXPECT_EQ(a[i].center_m, b[i].center_m);
    EXPECT_EQ(a[i].texture, b[i].texture);
  }
  bool differs = a.size() != c.size();
  for (std::size_t i = 0; !differs && i < a.size(); ++i) differs = a[i].center_m != c[i].center_m;
  EXPECT_TRUE(differs);
}

TEST(PlacePosters, EveryPosterFitsItsFaceAtEyeHeightWithTheTexturesAspect) {
  PosterPlacementOptions o;
  o.probability = 1.0;
  const auto posters = place_posters(office_faces(), textures(), o, 1);
  std::size_t long_faces = 0;
  for (const WallFace& f : office_faces()) long_faces += f.length_m() >= o.min_face_length_m;
  EXPECT_EQ(posters.size(), long_faces);
  const auto tex = textures();
  for (const Poster& p : posters) {
    EXPECT_FALSE(validate(p, office_faces(), tex.size(), 2.5).has_value());
    EXPECT_GE(p.width_m, o.min_width_m - 1e-12);
    EXPECT_LE(p.width_m, o.max_width_m);
    const WallTexture& t = tex[static_cast<std::size_t>(p.texture)];
    EXPECT_NEAR(p.height_m, std::min(o.max_height_m, p.width_m * t.height / t.width), 1e-12);
    EXPECT_NEAR(p.bottom_m + 0.5 * p.height_m, o.eye_height_m, o.eye_height_jitter_m + 1e-9);
  }
}

TEST(PlacePosters, NoProbabilityOrNoTexturesMeansNoPosters) {
  PosterPlacementOptions o;
  o.probability = 0.0;
  EXPECT_TRUE(place_posters(office_faces(), textures(), o, 1).empty());
  EXPECT_TRUE(place_posters(office_faces(), {}, PosterPlacementOptions{}, 1).empty());
}

TEST(PosterValidate, NamesWhatDoesNotFit) {
  const auto& faces = office_faces();
  Poster p;
  p.face = 0;
  p.center_m = faces[0].length_m();  // half of it hangs past the end
  EXPECT_THAT(*validate(p, faces, 2, 2.5), HasSubstr("does not fit on face 0"));
  p.center_m = 0.5 * faces[0].length_m();
  p.width_m = std::min(0.5, faces[0].length_m());
  p.bottom_m = 2.2;
  EXPECT_THAT(*validate(p, faces, 2, 2.5), HasSubstr("wall top"));
  p.bottom_m = 0.5;
  p.texture = 2;
  EXPECT_THAT(*validate(p, faces, 2, 2.5), HasSubstr("texture 2 does not exist"));
  p.texture = 0;
  p.face = static_cast<int>(faces.size());
  EXPECT_THAT(*validate(p, faces, 2, 2.5), HasSubstr("does not exist"));
  PosterPlacementOptions o;
  o.min_width_m = 2.0;
  o.max_width_m = 1.0;
  EXPECT_THAT(*validate(o), HasSubstr("min_width_m"));
}

}  // namespace
}  // namespace tessera
