#pragma once
// Pictures of maps and runs (PNG). North up: cell row y grows upward, image row 0 is the top row.
#include <filesystem>
#include <string>
#include <vector>

#include "tessera/core/cell.hpp"
#include "tessera/core/pose2.hpp"
#include "tessera/core/result.hpp"
#include "tessera/core/vec2.hpp"
#include "tessera/grid/occupancy_grid.hpp"
#include "tessera/io/rgb_image.hpp"
#include "tessera/sim/world.hpp"

namespace tessera {

/// What to draw. Only `map` is required; the pointers are not owned and must outlive the call.
struct RenderLayers {
  const OccupancyGrid* map = nullptr;
  /// Ground truth: when given, map errors are coloured (map free where truth is solid: red;
  /// map occupied where truth is free: orange). Cells are matched by the map cell's centre.
  const World* truth = nullptr;
  /// Where the map's frame lies in the truth's (compare_to_truth_at_centres in eval/map_accuracy).
  Pose2 T_truth_map;
  std::vector<std::vector<Vec2>> paths_m;  // one polyline per robot, map frame, metres
  std::vector<Cell> frontier;              // map cells
  std::vector<Vec2> robots_m;              // final positions; robot i has path i's colour
};

/// The colours render uses.
inline constexpr Rgb kUnknownColor{128, 128, 128};
inline constexpr Rgb kFrontierColor{30, 100, 255};
inline constexpr Rgb kOccupiedAsEmptyColor{220, 0, 0};    // map free, truth solid
inline constexpr Rgb kEmptyAsOccupiedColor{255, 150, 0};  // map occupied, truth free
/// Colour of robot i's path and dot: kPathPalette[i % size].
inline constexpr Rgb kPathPalette[] = {{0, 160, 0},   {200, 0, 200}, {0, 170, 170},  {120, 60, 200},
                                       {150, 90, 30}, {130, 130, 0}, {255, 90, 170}, {0, 0, 140}};

/// Pixels per cell for a map: 0 asks for automatic, max(1, ceil(1000 / long side)) so the long side
/// is about 1000-2000 px (longer only for maps of more than 2000 cells).
[[nodiscard]] int auto_pixels_per_cell(int width_cells, int height_cells);

/// The picture: known cells grey by probability (free white, occupied black), unknown mid grey,
/// truth errors, frontier cells, then each path as lines between the centres of the cells its
/// points fall in, and each robot as a filled dot. kInput errors: no map, pixels_per_cell < 0, or
/// an image of more than 2^28 pixels.
[[nodiscard]] Result<RgbImage> render_image(const RenderLayers& layers, int pixels_per_cell = 0);

/// render_image encoded as PNG.
[[nodiscard]] Result<std::string> render_png(const RenderLayers& layers, int pixels_per_cell = 0);

/// render_png written to `path` atomically.
[[nodiscard]] Status write_png(const std::filesystem::path& path, const RenderLayers& layers,
                               int pixels_per_cell = 0);

}  // namespace tessera
