#include "tessera/io/image_map.hpp"

#include <string>

#include "internal/file_util.hpp"
#include "internal/raw_image.hpp"

namespace tessera {

Result<OccupancyGrid> read_image_map(const std::filesystem::path& path, double resolution_m,
                                     Vec2 origin_m, const ImageMapThresholds& thresholds) {
  if (!(resolution_m > 0.0)) {
    return input_error(path.string() + ": resolution must be > 0, got " +
                       io_internal::format_double(resolution_m));
  }
  if (const std::string problem =
          io_internal::threshold_problem(thresholds.occupied_thresh, thresholds.free_thresh);
      !problem.empty()) {
    return input_error(path.string() + ": " + problem);
  }
  Result<io_internal::RawImage> image = io_internal::read_raw_image(path);
  if (!image) return image.error();
  io_internal::PixelRules rules;
  rules.mode = io_internal::PixelMode::kTrinary;
  rules.negate = thresholds.negate;
  rules.occupied_thresh = thresholds.occupied_thresh;
  rules.free_thresh = thresholds.free_thresh;
  return io_internal::grid_from_image(*image, origin_m, resolution_m, rules);
}

}  // namespace tessera
