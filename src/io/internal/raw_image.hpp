#pragma once
// An image as the map readers need it: per pixel the sum of R, G and B (3 * grey for grey images),
// and alpha when the file has an alpha channel, so that ROS map_server's shade and alpha rules
// (nav2_map_server map_io.cpp loadMapFromFile) can be applied exactly. Row 0 is the top row.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "tessera/core/result.hpp"
#include "tessera/grid/occupancy_grid.hpp"
#include "tessera/io/gray_image.hpp"

namespace tessera::io_internal {

struct RawImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint16_t> rgb_sum;  // R + G + B, 0..765
  std::vector<std::uint8_t> alpha;     // empty when the image has no alpha channel

  [[nodiscard]] bool has_alpha() const { return !alpha.empty(); }
};

/// Empty when the PNG's chunk structure is sound (every chunk's CRC checked, IEND present); else
/// what is wrong. Lets readers report damaged files themselves instead of libpng printing them.
/// Precondition: `bytes` starts with the PNG signature.
[[nodiscard]] std::string png_structure_problem(const std::string& bytes);

/// Reads a PGM (own reader) or any image OpenCV decodes (PNG, BMP, ...). 16-bit samples are scaled
/// to 8 bits. kInput errors name the file.
[[nodiscard]] Result<RawImage> read_raw_image(const std::filesystem::path& path);

/// read_raw_image on the file's bytes; `name` is the file named in errors.
[[nodiscard]] Result<RawImage> decode_raw_image(const std::string& bytes, const std::string& name);

/// Grey = round(mean(R, G, B)).
[[nodiscard]] GrayImage to_gray(const RawImage& image);

/// nav2 MapMode.
enum class PixelMode { kTrinary, kScale, kRaw };

struct PixelRules {
  PixelMode mode = PixelMode::kTrinary;
  bool negate = false;
  double occupied_thresh = 0.65;
  double free_thresh = 0.196;
};

/// nav2 map cell value for pixel i: 0..100, or -1 for unknown (map_io.cpp loadMapFromFile).
[[nodiscard]] int map_cell_value(const RawImage& image, std::size_t i, const PixelRules& rules);

/// The grid nav2 would publish: geometry = (origin, resolution, image size), image row r is cell
/// row height - 1 - r, cell value v in 0..100 is p = v / 100, -1 stays unknown.
[[nodiscard]] OccupancyGrid grid_from_image(const RawImage& image, Vec2 origin, double resolution_m,
                                            const PixelRules& rules);

/// Checks thresholds as read_map_yaml does: each in [0, 1], free <= occupied. Empty when fine.
[[nodiscard]] std::string threshold_problem(double occupied_thresh, double free_thresh);

}  // namespace tessera::io_internal
