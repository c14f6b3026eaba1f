#pragma once
// A loop-closure test set as RTAB-Map ships one (../shared/data/rgbd/rtabmap_loop_samples, see its
// SOURCES.md): numbered monocular images 1.jpg .. N.jpg, processed in numeric order, and an N x N
// 8-bit ground-truth matrix (samples_GT.bmp) where GT(i, j) == 255 means image i + 1 revisits the
// place of image j + 1 (rows are queries, columns earlier images, both 0-based). Decoded with
// OpenCV's imgcodecs, here in io only; fusion/appearance_recall.hpp scores the images.
#include <cstdint>
#include <filesystem>
#include <vector>

#include "tessera/core/result.hpp"
#include "tessera/io/gray_image.hpp"

namespace tessera {

struct LoopGroundTruth {
  int size = 0;                     // N: images, rows and columns
  std::vector<std::uint8_t> loop;   // N * N, row-major (row = query); 1 = loop, 0 = none

  /// True when the matrix holds a loop between query image `query` and earlier image `earlier`
  /// (0-based). Precondition: both in [0, size).
  [[nodiscard]] bool is_loop(int query, int earlier) const;
  /// Whether query image `query` (0-based) has at least one true loop.
  [[nodiscard]] bool has_loop(int query) const;
  /// How many query images have at least one true loop (RTAB-Map's set: 44).
  [[nodiscard]] int queries_with_loop() const;
};

/// Reads the ground-truth matrix. Input errors name the file: "<file>: no such file",
/// "<file>: cannot decode image", "<file>: expected an 8-bit grey matrix, got 8-bit with 3
/// channels", "<file>: expected an 84 x 84 matrix (one row and column per image), got 80 x 84",
/// "<file>: row 3, column 5: expected 0 (no loop) or 255 (loop), got 17".
[[nodiscard]] Result<LoopGroundTruth> read_loop_ground_truth(const std::filesystem::path& path,
                                                             int expected_images);

/// Reads folder/1.jpg .. folder/<count>.jpg as 8-bit grey (colour becomes OpenCV's luma,
/// 0.299 R + 0.587 G + 0.114 B). Input errors: "<folder>: not a folder",
/// "<folder>/17.jpg: no such file", "<folder>/17.jpg: cannot decode image".
[[nodiscard]] Result<std::vector<GrayImage>> read_loop_closure_images(
    const std::filesystem::path& folder, int count);

}  // namespace tessera
