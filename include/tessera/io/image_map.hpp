#pragma once
// Plain floor-plan images without a YAML beside them (Stage bitmaps, HouseExpo and Brain Corp PNGs,
// Willow Garage PGMs whose resolution is given elsewhere): the caller supplies the resolution.
#include <filesystem>

#include "tessera/core/result.hpp"
#include "tessera/core/vec2.hpp"
#include "tessera/grid/occupancy_grid.hpp"

namespace tessera {

/// Trinary thresholds, ROS map_server defaults.
struct ImageMapThresholds {
  double occupied_thresh = 0.65;
  double free_thresh = 0.196;
  bool negate = false;  // true: white is occupied
};

/// Reads a PNG or PGM as a map with map_server's trinary semantics (map_yaml.hpp, read_map_yaml):
/// occ = 1 - shade (shade if negate); occ > occupied_thresh -> occupied, occ < free_thresh -> free,
/// otherwise unknown. Image row 0 is the top; the lower-left pixel's corner is `origin_m`.
/// kInput errors: resolution_m <= 0, thresholds outside [0, 1] or free > occupied, unreadable
/// image.
[[nodiscard]] Result<OccupancyGrid> read_image_map(const std::filesystem::path& path,
                                                   double resolution_m, Vec2 origin_m = {},
                                                   const ImageMapThresholds& thresholds = {});

}  // namespace tessera
