#pragma once
// The text files of a TUM RGB-D sequence folder (io/tum_rgbd_sequence.hpp; formats at
// cvg.cit.tum.de/data/datasets/rgbd-dataset/file_formats): the rgb.txt / depth.txt image lists and
// their association (TUM's associate.py), and tessera's intrinsics.txt and neck.txt. In-memory, so
// that TumRgbdSequence::open and the fuzz harnesses read them the same way.
#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "tessera/core/result.hpp"
#include "tessera/sensors/pinhole_camera.hpp"

namespace tessera::io_internal {

/// One "t filename" line of rgb.txt or depth.txt.
struct ListedImage {
  double t_s = 0.0;
  std::string name;
  int line = 0;
};

/// A TUM image list: every non-comment line "t filename"; sorted by stamp (stable). kInput errors
/// "<path>:<line>: expected 't filename', got 3 fields" and the like.
[[nodiscard]] Result<std::vector<ListedImage>> decode_tum_image_list(std::string_view text,
                                                                     const std::string& path);

/// associate.py (TUM RGB-D tools): candidates |a - b| <= max_difference, greedy by difference,
/// each stamp used once. Both lists sorted by stamp. Returns (rgb index, depth index) pairs
/// sorted by colour stamp. Ties in the difference go to the earlier colour, then depth stamp.
[[nodiscard]] std::vector<std::pair<std::size_t, std::size_t>> associate(
    const std::vector<ListedImage>& rgb, const std::vector<ListedImage>& depth,
    double max_difference_s);

/// intrinsics.txt: one line "fx fy cx cy" or "fx fy cx cy width height" (pixels); has_size tells
/// which. kInput errors name the file and line.
[[nodiscard]] Result<PinholeIntrinsics> decode_tum_intrinsics(std::string_view text,
                                                              const std::string& path,
                                                              bool& has_size);

/// neck.txt: "t neck_pan_rad" per line, sorted by stamp (stable).
[[nodiscard]] Result<std::vector<std::pair<double, double>>> decode_tum_neck(
    std::string_view text, const std::string& path);

}  // namespace tessera::io_internal
