#pragma once
// HouseExpo floor plans (Li et al., "HouseExpo", IROS 2020; github.com/TeaganLi/HouseExpo): JSON
// with id, room_num, bbox {min: [x, y], max: [x, y]}, verts [[x, y], ...] (the outer contour of the
// free space, metres) and room_category.
#include <filesystem>

#include "tessera/core/result.hpp"
#include "tessera/grid/occupancy_grid.hpp"
#include "tessera/grid/polygon_map.hpp"

namespace tessera {

/// The contour as a PolygonMap with Meaning::kFreeSpace. kInput errors: no such file, JSON syntax
/// error (with the line), missing or malformed verts, fewer than 3 vertices.
[[nodiscard]] Result<PolygonMap> read_houseexpo_json(const std::filesystem::path& path);

/// The plan rasterised with PolygonMap::rasterize on a grid that covers the vertices' bounding box
/// plus one cell on every side (so the outer wall is always inside the grid). Every cell is known.
/// kInput error also when resolution_m <= 0.
[[nodiscard]] Result<OccupancyGrid> read_houseexpo_map(const std::filesystem::path& path,
                                                       double resolution_m = 0.05);

}  // namespace tessera
