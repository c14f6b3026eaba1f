#pragma once
// One entry point for every map format io reads, chosen by the file's extension.
#include <filesystem>
#include <optional>
#include <string>

#include "tessera/core/result.hpp"
#include "tessera/grid/occupancy_grid.hpp"

namespace tessera {

struct MapLoadOptions {
  /// Cell size for formats that carry none: required for .png/.pgm images, default 1.0 for Moving
  /// AI .map, 0.05 for HouseExpo .json. Ignored by .yaml and .world, which carry their own.
  std::optional<double> resolution_m;
};

struct LoadedMap {
  OccupancyGrid map;
  std::string format;  // "ros_map_server", "image", "movingai", "stage" or "houseexpo"
};

/// .yaml/.yml -> read_map_yaml; .world -> read_stage_world; .map -> read_movingai_map;
/// .json -> read_houseexpo_map; .png/.pgm -> read_image_map at origin (0, 0) (needs resolution_m).
/// Extensions are matched case-insensitively. kInput errors: "<path>: no such file", an unknown
/// extension (the message lists the supported ones), a plain image without resolution_m, and
/// whatever the format's reader reports.
[[nodiscard]] Result<LoadedMap> load_map(const std::filesystem::path& path,
                                         const MapLoadOptions& options = {});

}  // namespace tessera
