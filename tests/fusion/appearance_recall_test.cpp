#include "tessera/fusion/appearance_recall.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "support/data.hpp"
#include "tessera/core/rng.hpp"
#include "tessera/fusion/loop_recall.hpp"
#include "tessera/io/loop_closure_set.hpp"

namespace tessera::fusion {
namespace {

using ::testing::HasSubstr;

constexpr FeatureType kAllTypes[] = {FeatureType::kOrb, FeatureType::kSift, FeatureType::kAkaze};

/// A grey scene of random filled rectangles (corners and blobs for every detector), drawn on a
/// canvas larger than the image so that shifted crops of it share content.
struct Canvas {
  int width = 0, height = 0;
  std::vector<std::uint8_t> pixels;
};

Canvas random_canvas(int width, int height, std::uint64_t seed) {
  Canvas c{width, height, std::vector<std::uint8_t>(static_cast<std::size_t>(width * height), 128)};
  Rng rng(seed);
  for (int k = 0; k < 400; ++k) {
    const int w = rng.uniform_int(6, 40), h = rng.uniform_int(6, 40);
    const int x0 = rng.uniform_int(0, width - w), y0 = rng.uniform_int(0, height - h);
    const auto v = static_cast<std::uint8_t>(rng.uniform_int(0, 255));
    for (int y = y0; y < y0 + h; ++y) {
      for (int x = x0; x < x0 + w; ++x) c.pixels[static_cast<std::size_t>(y * width + x)] = v;
    }
  }
  return c;
}

/// The width x height crop of `c` whose top-left corner is (x0, y0).
std::vector<std::uint8_t> crop(const Canvas& c, int x0, int y0, int width, int height) {
  std::vector<std::uint8_t> out(static_cast<std::size_t>(width * height));
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      out[static_cast<std::size_t>(y * width + x)] =
          c.pixels[static_cast<std::size_t>((y0 + y) * c.width + x0 + x)];
    }
  }
  return out;
}

AppearanceOptions options_for(FeatureType t) {
  AppearanceOptions o;
  o.feature_type = t;
  return o;
}

ImageDescription describe(const std::vector<std::uint8_t>& pixels, int w, int h, FeatureType t) {
  return describe_image({w, h, pixels}, options_for(t));
}

TEST(AppearanceOptions, ValidateNamesTheBrokenField) {
  EXPECT_FALSE(validate(AppearanceOptions{}).has_value());
  AppearanceOptions o;
  o.min_matches = 7;
  EXPECT_THAT(validate(o).value_or(""), HasSubstr("min_matches"));
  o = {};
  o.short_term_memory = -1;
  EXPECT_THAT(validate(o).value_or(""), HasSubstr("short_term_memory"));
  o = {};
  o.ratio = 1.5;
  EXPECT_THAT(validate(o).value_or(""), HasSubstr("ratio"));
  o = {};
  o.epipolar_threshold_px = 0.0;
  EXPECT_THAT(validate(o).value_or(""), HasSubstr("epipolar_threshold_px"));
}

TEST(AppearanceRecall, AShiftedViewOfTheSamePlaceOutscoresAnotherPlace) {
  const Canvas place = random_canvas(400, 300, 1);
  const Canvas other = random_canvas(400, 300, 2);
  const auto a = crop(place, 0, 0, 320, 240);
  const auto b = crop(place, 40, 25, 320, 240);  // the same place, the camera moved
  const auto c = crop(other, 20, 20, 320, 240);
  for (const FeatureType t : kAllTypes) {
    const ImageDescription da = describe(a, 320, 240, t);
    const ImageDescription db = describe(b, 320, 240, t);
    const ImageDescription dc = describe(c, 320, 240, t);
    ASSERT_GT(da.size(), 50) << to_string(t);
    const AppearanceOptions o = options_for(t);
    const PairScore same = score_image_pair(db, da, o);
    const PairScore different = score_image_pair(dc, da, o);
    EXPECT_GE(same.inliers, 40) << to_string(t);
    EXPECT_LE(same.inliers, same.matches);
    EXPECT_LT(different.inliers, same.inliers / 3) << to_string(t);
  }
}

TEST(AppearanceRecall, ScoresAreTheSameOnEveryCall) {
  const Canvas place = random_canvas(400, 300, 3);
  const auto a = crop(place, 0, 0, 320, 240);
  const auto b = crop(place, 30, 10, 320, 240);
  for (const FeatureType t : kAllTypes) {
    const AppearanceOptions o = options_for(t);
    const ImageDescription da = describe(a, 320, 240, t);
    const ImageDescription db = describe(b, 320, 240, t);
    const PairScore first = score_image_pair(db, da, o);
    for (int k = 0; k < 3; ++k) {
      const PairScore again = score_image_pair(db, describe(a, 320, 240, t), o);
      EXPECT_EQ(again.inliers, first.inliers) << to_string(t);
      EXPECT_EQ(again.matches, first.matches) << to_string(t);
    }
  }
}

TEST(AppearanceRecall, ImagesInTheShortTermMemoryAreNotCandidates) {
  // Images 0 and 3 show one place, 1 and 2 another; image 2 would match image 1, but with a
  // short-term memory of 1 image 2 may only be compared with image 0.
  const Canvas p = random_canvas(400, 300, 4);
  const Canvas q = random_canvas(400, 300, 5);
  const std::vector<std::vector<std::uint8_t>> pixels = {
      crop(p, 0, 0, 320, 240), crop(q, 0, 0, 320, 240), crop(q, 30, 20, 320, 240),
      crop(p, 35, 15, 320, 240)};
  AppearanceOptions o;
  o.short_term_memory = 1;
  std::vector<ImageDescription> d;
  for (const auto& px : pixels) d.push_back(describe_image({320, 240, px}, o));
  const std::vector<LoopHypothesis> h = best_loop_hypotheses(d, o);
  ASSERT_EQ(h.size(), 4u);
  EXPECT_EQ(h[0].candidate, -1);  // nothing earlier
  EXPECT_EQ(h[1].candidate, -1);  // image 0 is in the short-term memory
  EXPECT_NE(h[2].candidate, 1);   // image 1 is in the short-term memory
  EXPECT_EQ(h[3].candidate, 0);   // the same place, outside the short-term memory
  EXPECT_GE(h[3].score, 40);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(h[static_cast<std::size_t>(i)].query, i);
}

// best_loop_hypotheses verifies only the candidates whose matches could beat the best so far;
// its answer must be that of scoring every candidate, ties to the lower index included (images 0
// and 1 are the same picture, so they tie on every later view of that place).
TEST(AppearanceRecall, HypothesesAreTheBestOfScoringEveryCandidate) {
  const Canvas p = random_canvas(400, 300, 8);
  const Canvas q = random_canvas(400, 300, 9);
  const std::vector<std::vector<std::uint8_t>> pixels = {
      crop(p, 0, 0, 320, 240),   crop(p, 0, 0, 320, 240),   crop(q, 0, 0, 320, 240),
      crop(q, 40, 30, 320, 240), crop(p, 20, 10, 320, 240), crop(q, 10, 50, 320, 240),
      crop(p, 60, 40, 320, 240)};
  for (const FeatureType t : kAllTypes) {
    AppearanceOptions o = options_for(t);
    o.short_term_memory = 0;
    std::vector<ImageDescription> d;
    for (const auto& px : pixels) d.push_back(describe_image({320, 240, px}, o));
    const std::vector<LoopHypothesis> h = best_loop_hypotheses(d, o);
    ASSERT_EQ(h.size(), pixels.size());
    for (std::size_t i = 0; i < d.size(); ++i) {
      LoopHypothesis every;
      every.query = static_cast<int>(i);
      for (std::size_t j = 0; j < i; ++j) {
        const PairScore s = score_image_pair(d[i], d[j], o);
        if (s.inliers > every.score)
          every = {static_cast<int>(i), static_cast<int>(j), s.inliers, s.matches};
      }
      EXPECT_EQ(h[i].candidate, every.candidate) << to_string(t) << " query " << i;
      EXPECT_EQ(h[i].score, every.score) << to_string(t) << " query " << i;
      EXPECT_EQ(h[i].matches, every.matches) << to_string(t) << " query " << i;
    }
    EXPECT_EQ(h[4].candidate, 0) << to_string(t);  // a view of p: image 0 wins its tie with 1
  }
}

TEST(AppearanceRecall, AnImageWithoutFeaturesScoresZero) {
  const std::vector<std::uint8_t> flat(320 * 240, 200);
  const Canvas place = random_canvas(400, 300, 6);
  for (const FeatureType t : kAllTypes) {
    const ImageDescription blank = describe(flat, 320, 240, t);
    EXPECT_EQ(blank.size(), 0) << to_string(t);
    const AppearanceOptions o = options_for(t);
    const PairScore s = score_image_pair(blank, describe(crop(place, 0, 0, 320, 240), 320, 240, t), o);
    EXPECT_EQ(s.matches, 0);
    EXPECT_EQ(s.inliers, 0);
  }
}

// Issue 5: the recall at 100% precision on RTAB-Map's loop set, per feature type. The floors sit
// one query below what docs/fusion-recall.md records (ORB 39, SIFT 37, AKAZE 39 of 44), so that
// a regression fails. Slow (20 to 60 s per feature type: 84 descriptions and ~2600 pair scores),
// so one test per type, which ctest runs in parallel.
void expect_recall_on_rtabmap_set(FeatureType type, int min_found) {
  const std::filesystem::path set = support::data_path("rgbd/rtabmap_loop_samples");
  TESSERA_REQUIRE_DATA(set);
  const Result<LoopGroundTruth> gt = read_loop_ground_truth(set / "samples_GT.bmp", 84);
  ASSERT_TRUE(gt.ok()) << gt.error().message;
  const Result<std::vector<GrayImage>> images = read_loop_closure_images(set / "images", 84);
  ASSERT_TRUE(images.ok()) << images.error().message;
  ASSERT_EQ(gt->queries_with_loop(), 44);
  const AppearanceOptions o = options_for(type);
  std::vector<ImageDescription> d;
  for (const GrayImage& g : *images) d.push_back(describe_image({g.width, g.height, g.pixels}, o));
  const std::vector<LoopHypothesis> hyps = best_loop_hypotheses(d, o);
  std::vector<ScoredHypothesis> scored;
  for (const LoopHypothesis& h : hyps) {
    if (h.candidate >= 0) scored.push_back({double(h.score), gt->is_loop(h.query, h.candidate)});
  }
  const RecallAtFullPrecision r = recall_at_full_precision(scored, 44);
  EXPECT_GE(r.found, min_found) << to_string(type);
  // Precision at that threshold, counted afresh from the hypotheses: 100%.
  int accepted = 0, wrong = 0;
  for (const LoopHypothesis& h : hyps) {
    if (h.candidate < 0 || h.score < r.threshold) continue;
    ++accepted;
    if (!gt->is_loop(h.query, h.candidate)) ++wrong;
  }
  EXPECT_EQ(wrong, 0) << to_string(type);
  EXPECT_EQ(accepted, r.found) << to_string(type);
}

TEST(AppearanceRecall, RtabmapLoopSetRecallAtFullPrecisionOrb) {
  expect_recall_on_rtabmap_set(FeatureType::kOrb, 38);
}
TEST(AppearanceRecall, RtabmapLoopSetRecallAtFullPrecisionSift) {
  expect_recall_on_rtabmap_set(FeatureType::kSift, 36);
}
TEST(AppearanceRecall, RtabmapLoopSetRecallAtFullPrecisionAkaze) {
  expect_recall_on_rtabmap_set(FeatureType::kAkaze, 38);
}

}  // namespace
}  // namespace tessera::fusion
