#pragma once
// Pictures of the Fusion SLAM hex-cell map (fusion/hex_cell_map.hpp): the cells as flat-topped
// hexagons, their adjacency, image nodes, the taught, repeated and true paths, start and goal,
// optionally over a floor plan. SVG (vector, for docs and zooming) and PNG (the same drawing
// rasterised). Map frame, north up; 1 m = pixels_per_m pixels.
#include <cstddef>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "tessera/core/result.hpp"
#include "tessera/core/vec2.hpp"
#include "tessera/fusion/hex_cell_map.hpp"
#include "tessera/io/rgb_image.hpp"
#include "tessera/sim/world.hpp"

namespace tessera {

/// What to draw. Only `map` is required; the pointers are not owned and must outlive the call.
struct HexMapPicture {
  const fusion::HexCellMap* map = nullptr;
  /// Background: its solid cells in dark grey (free space stays white).
  const World* floor_plan = nullptr;
  /// Which adjacency to draw as lines between centres (the wavefront's is kTraversed).
  fusion::CellAdjacency adjacency = fusion::CellAdjacency::kTraversed;
  std::vector<Vec2> image_nodes_m;    // dots
  std::vector<Vec2> taught_path_m;    // blue: the estimated path while teaching
  std::vector<Vec2> repeated_path_m;  // orange: the estimated path while repeating
  std::vector<Vec2> true_path_m;      // green: ground truth
  /// Boxes put in the way (the obstacle course), lo and hi corners: filled dark red.
  std::vector<std::pair<Vec2, Vec2>> obstacles_m;
  std::ptrdiff_t start_cell = -1;  // filled green; -1 for none
  std::ptrdiff_t goal_cell = -1;   // filled red; -1 for none
  double pixels_per_m = 100.0;
};

/// The colours, as SVG writes them (#rrggbb) and PNG draws them.
inline constexpr Rgb kHexCellColor{120, 120, 120};
inline constexpr Rgb kHexAdjacencyColor{190, 190, 190};
inline constexpr Rgb kHexFloorPlanColor{70, 70, 70};
inline constexpr Rgb kHexImageNodeColor{148, 0, 211};
inline constexpr Rgb kHexTaughtPathColor{31, 119, 180};
inline constexpr Rgb kHexRepeatedPathColor{255, 127, 14};
inline constexpr Rgb kHexTruePathColor{44, 160, 44};
inline constexpr Rgb kHexStartColor{150, 220, 150};
inline constexpr Rgb kHexGoalColor{240, 140, 140};
inline constexpr Rgb kHexObstacleColor{178, 34, 34};

/// The SVG document. Every cell is one `<polygon class="cell" .../>`. kInput errors: no map, a map
/// without cells, pixels_per_m not > 0, a start or goal cell that does not exist, a coordinate
/// that is not finite, or a picture of more than 2^28 pixels.
[[nodiscard]] Result<std::string> render_hex_map_svg(const HexMapPicture& picture);

/// The same drawing as an RGB raster (same errors).
[[nodiscard]] Result<RgbImage> render_hex_map_image(const HexMapPicture& picture);

/// render_hex_map_svg written to `path` atomically; errors are prefixed with the path.
[[nodiscard]] Status write_hex_map_svg(const std::filesystem::path& path,
                                       const HexMapPicture& picture);

/// render_hex_map_image encoded as PNG and written to `path` atomically.
[[nodiscard]] Status write_hex_map_png(const std::filesystem::path& path,
                                       const HexMapPicture& picture);

}  // namespace tessera
