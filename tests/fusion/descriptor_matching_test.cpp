// ratio_test_matches against OpenCV's BFMatcher, which it replaces: the same pairs for binary and
// float descriptors, ties included (random 64-bit binary descriptors tie often).
#include "tessera/fusion/descriptor_matching.hpp"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/features2d.hpp>
#include <random>
#include <utility>
#include <vector>

namespace tessera::fusion {
namespace {

Descriptors random_binary(int count, int length, std::mt19937& rng) {
  Descriptors d{count, length, {}, {}};
  std::uniform_int_distribution<int> byte(0, 255);
  for (int i = 0; i < count * length; ++i) d.binary.push_back(static_cast<std::uint8_t>(byte(rng)));
  return d;
}

Descriptors random_real(int count, int length, std::mt19937& rng) {
  Descriptors d{count, length, {}, {}};
  std::uniform_real_distribution<float> value(0.0f, 100.0f);
  for (int i = 0; i < count * length; ++i) d.real.push_back(value(rng));
  return d;
}

/// A copy of `d` whose rows are those of `from` at `rows`, each with some noise: the same
/// features seen again, so that the ratio test passes some and fails others.
Descriptors seen_again(const Descriptors& from, const std::vector<int>& rows, bool binary,
                       std::mt19937& rng) {
  Descriptors d{static_cast<int>(rows.size()), from.length, {}, {}};
  std::uniform_int_distribution<int> bit(0, 7);
  std::normal_distribution<float> noise(0.0f, 3.0f);
  for (const int r : rows) {
    for (int k = 0; k < from.length; ++k) {
      const auto at = static_cast<std::size_t>(r * from.length + k);
      if (binary) {
        d.binary.push_back(static_cast<std::uint8_t>(from.binary[at] ^ (bit(rng) == 0 ? 1u : 0u)));
      } else {
        d.real.push_back(from.real[at] + noise(rng));
      }
    }
  }
  return d;
}

/// What the code before ratio_test_matches did with OpenCV (node_matcher.cpp until 2026-12-06).
std::vector<std::pair<int, int>> with_bfmatcher(const Descriptors& query, const Descriptors& train,
                                                bool binary, double ratio, bool mutual) {
  const auto mat = [&](const Descriptors& d) {
    return binary ? cv::Mat(d.count, d.length, CV_8U, const_cast<std::uint8_t*>(d.binary.data()))
                  : cv::Mat(d.count, d.length, CV_32F, const_cast<float*>(d.real.data()));
  };
  cv::BFMatcher matcher(binary ? cv::NORM_HAMMING : cv::NORM_L2);
  std::vector<std::vector<cv::DMatch>> knn;
  matcher.knnMatch(mat(query), mat(train), knn, 2);
  std::vector<cv::DMatch> reverse;
  matcher.match(mat(train), mat(query), reverse);
  std::vector<int> back(static_cast<std::size_t>(train.count), -1);
  for (const cv::DMatch& m : reverse) back[static_cast<std::size_t>(m.queryIdx)] = m.trainIdx;
  std::vector<std::pair<int, int>> out;
  for (const std::vector<cv::DMatch>& k : knn) {
    if (k.size() < 2 || !(k[0].distance < ratio * k[1].distance)) continue;
    if (mutual && back[static_cast<std::size_t>(k[0].trainIdx)] != k[0].queryIdx) continue;
    out.emplace_back(k[0].queryIdx, k[0].trainIdx);
  }
  return out;
}

std::vector<std::pair<int, int>> pairs(const std::vector<DescriptorMatch>& matches) {
  std::vector<std::pair<int, int>> out;
  for (const DescriptorMatch& m : matches) out.emplace_back(m.query, m.train);
  return out;
}

struct Case {
  FeatureType type;
  int length;
};

TEST(DescriptorMatching, TheSameMatchesAsOpenCvsBruteForceMatcher) {
  // ORB's 32 bytes, AKAZE's 61 (not a whole number of 64-bit words), a short 8-byte descriptor
  // whose distances tie often, and SIFT's 128 floats.
  for (const Case c : {Case{FeatureType::kOrb, 32}, Case{FeatureType::kAkaze, 61},
                       Case{FeatureType::kOrb, 8}, Case{FeatureType::kSift, 128}}) {
    std::mt19937 rng(7);
    const bool binary = is_binary(c.type);
    const Descriptors train =
        binary ? random_binary(300, c.length, rng) : random_real(300, c.length, rng);
    std::vector<int> rows;
    for (int r = 0; r < 300; r += 3) rows.push_back(r);
    Descriptors query = seen_again(train, rows, binary, rng);
    const Descriptors others =
        binary ? random_binary(150, c.length, rng) : random_real(150, c.length, rng);
    query.count += others.count;
    query.binary.insert(query.binary.end(), others.binary.begin(), others.binary.end());
    query.real.insert(query.real.end(), others.real.begin(), others.real.end());
    for (const bool mutual : {false, true}) {
      for (const double ratio : {0.8, 1.0}) {
        const auto expected = with_bfmatcher(query, train, binary, ratio, mutual);
        const auto got = pairs(ratio_test_matches(query, train, c.type, ratio, mutual));
        EXPECT_EQ(got, expected) << to_string(c.type) << " length " << c.length << " mutual "
                                 << mutual << " ratio " << ratio;
        if (ratio < 1.0) {
          EXPECT_GE(got.size(), rows.size() / 2) << to_string(c.type);
        }
      }
    }
  }
}

TEST(DescriptorMatching, FewerThanTwoTrainRowsGiveNoMatch) {
  std::mt19937 rng(3);
  const Descriptors one = random_binary(1, 32, rng);
  const Descriptors many = random_binary(10, 32, rng);
  EXPECT_TRUE(ratio_test_matches(many, one, FeatureType::kOrb, 0.8, true).empty());
  EXPECT_TRUE(ratio_test_matches(Descriptors{}, many, FeatureType::kOrb, 0.8, true).empty());
  EXPECT_EQ(ratio_test_matches(many, many, FeatureType::kOrb, 0.8, true).size(), 10u);
}

}  // namespace
}  // namespace tessera::fusion
