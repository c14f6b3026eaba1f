// Nearest-neighbour descriptor matching with the ratio and mutual tests (descriptor_matching.hpp).
#include "tessera/fusion/descriptor_matching.hpp"

#include <bit>
#include <cstdint>
#include <cstring>
#include <limits>
#include <opencv2/core.hpp>

#include "internal/opencv_features.hpp"
#include "tessera/core/assert.hpp"

namespace tessera::fusion {
namespace {

/// Each row of binary descriptors in 64-bit words, zero-padded: the Hamming distance of two rows
/// is the popcount of their words' exclusive or.
std::vector<std::uint64_t> packed_rows(const Descriptors& d, int words) {
  std::vector<std::uint64_t> out(
      static_cast<std::size_t>(d.count) * static_cast<std::size_t>(words), 0);
  for (int r = 0; r < d.count; ++r) {
    std::memcpy(out.data() + static_cast<std::size_t>(r) * static_cast<std::size_t>(words),
                d.binary.data() + static_cast<std::size_t>(r) * static_cast<std::size_t>(d.length),
                static_cast<std::size_t>(d.length));
  }
  return out;
}

// The distances of one query row to every train row; always inlined, so that the popcnt copy
// below has the instruction in its own loop.
[[gnu::always_inline]] inline void hamming_row_body(const std::uint64_t* query,
                                                    const std::uint64_t* train, int rows, int words,
                                                    float* out) {
  for (int j = 0; j < rows; ++j) {
    const std::uint64_t* t = train + static_cast<std::ptrdiff_t>(j) * words;
    int d = 0;
    for (int w = 0; w < words; ++w) d += std::popcount(query[w] ^ t[w]);
    out[j] = static_cast<float>(d);
  }
}

// On x86-64 GCC the loop is compiled a second time with the popcnt instruction, taken when the
// processor has it. The choice is made here at run time, not by target_clones: its load-time
// resolver (an ifunc) runs before ThreadSanitizer's runtime is up and crashes the program.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
__attribute__((target("popcnt"))) void hamming_row_popcnt(const std::uint64_t* query,
                                                          const std::uint64_t* train, int rows,
                                                          int words, float* out) {
  hamming_row_body(query, train, rows, words, out);
}

void hamming_row(const std::uint64_t* query, const std::uint64_t* train, int rows, int words,
                 float* out) {
  static const bool has_popcnt = __builtin_cpu_supports("popcnt");
  if (has_popcnt) {
    hamming_row_popcnt(query, train, rows, words, out);
  } else {
    hamming_row_body(query, train, rows, words, out);
  }
}
#else
void hamming_row(const std::uint64_t* query, const std::uint64_t* train, int rows, int words,
                 float* out) {
  hamming_row_body(query, train, rows, words, out);
}
#endif

}  // namespace

std::vector<DescriptorMatch> ratio_test_matches(const Descriptors& query, const Descriptors& train,
                                                FeatureType type, double ratio, bool mutual) {
  TESSERA_ASSERT(query.length == train.length || query.count == 0 || train.count == 0);
  TESSERA_ASSERT(ratio > 0.0 && ratio <= 1.0);
  std::vector<DescriptorMatch> out;
  const int n = query.count;
  const int m = train.count;
  if (n < 1 || m < 2) return out;

  // Distances row by row: Hamming from packed words, L2 from OpenCV's own kernel (one call for
  // the whole matrix, the values BFMatcher compares).
  std::vector<float> row(static_cast<std::size_t>(m));
  std::vector<std::uint64_t> q_words, t_words;
  const int words = (query.length + 7) / 8;
  cv::Mat l2;
  if (is_binary(type)) {
    q_words = packed_rows(query, words);
    t_words = packed_rows(train, words);
  } else {
    cv::batchDistance(internal::descriptor_mat(query, type), internal::descriptor_mat(train, type),
                      l2, CV_32F, cv::noArray(), cv::NORM_L2, 0);
  }
  const auto distances = [&](int i) -> const float* {
    if (!is_binary(type)) return l2.ptr<float>(i);
    hamming_row(q_words.data() + static_cast<std::ptrdiff_t>(i) * words, t_words.data(), m, words,
                row.data());
    return row.data();
  };

  // Per query row its nearest and second nearest train rows (the first of equals nearest, as
  // BFMatcher keeps them); per train row its nearest query row, over the same pass.
  constexpr float kFar = std::numeric_limits<float>::max();
  std::vector<float> column_best(static_cast<std::size_t>(m), kFar);
  std::vector<int> column_arg(static_cast<std::size_t>(m), -1);
  struct Nearest {
    int train = -1;
    float d0 = kFar, d1 = kFar;
  };
  std::vector<Nearest> nearest(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    const float* d = distances(i);
    Nearest& k = nearest[static_cast<std::size_t>(i)];
    for (int j = 0; j < m; ++j) {
      const float dij = d[j];
      if (dij < k.d0) {
        k.d1 = k.d0;
        k.d0 = dij;
        k.train = j;
      } else if (dij < k.d1) {
        k.d1 = dij;
      }
      if (dij < column_best[static_cast<std::size_t>(j)]) {
        column_best[static_cast<std::size_t>(j)] = dij;
        column_arg[static_cast<std::size_t>(j)] = i;
      }
    }
  }
  for (int i = 0; i < n; ++i) {
    const Nearest& k = nearest[static_cast<std::size_t>(i)];
    if (k.train < 0 || !(k.d0 < ratio * k.d1)) continue;
    if (mutual && column_arg[static_cast<std::size_t>(k.train)] != i) continue;
    out.push_back({i, k.train});
  }
  return out;
}

}  // namespace tessera::fusion
