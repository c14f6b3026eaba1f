#pragma once
// Stage simulator world files (rtv/Stage, "worldfile" syntax: `key value`, `key [a b c]`,
// `type ( ... )` model blocks, `define name parent ( ... )` macros, '#' comments). The environment
// is the model with a `bitmap "file"` (normally the `floorplan`): Stage scales the bitmap to the
// model's `size [w h z]` and centres it on its `pose [x y z a]` (a in degrees).
#include <filesystem>
#include <string>

#include "tessera/core/result.hpp"
#include "tessera/core/vec2.hpp"
#include "tessera/grid/occupancy_grid.hpp"

namespace tessera {

/// The environment model a .world file describes.
struct StageFloorplan {
  /// Resolved: relative to the .world's folder; when nothing is there, a file of the same name
  /// beside the .world (datasets often copy "bitmaps/cave.png" next to the world file).
  std::filesystem::path bitmap;
  Vec2 size_m;           // extent the bitmap is scaled to, before rotation
  Vec2 center_m;         // pose x, y
  double yaw_rad = 0.0;  // pose a
  int line = 0;          // line of the block in the .world file
};

/// Finds the floorplan: among top-level model blocks whose properties (their own, then those of
/// their `define` chain) include a bitmap, the first whose type chain reaches "floorplan" or "map",
/// else the first. kInput errors: syntax errors (with the line), no bitmap, missing or malformed
/// size, bitmap file missing.
[[nodiscard]] Result<StageFloorplan> parse_stage_world(const std::filesystem::path& path);

/// Reads the environment of a .world as a map. Stage bitmaps may be anisotropic (autolab: 20 x 20 m
/// over 809 x 689 px), so the bitmap is resampled onto an isotropic grid of resolution
/// min(w / px_w, h / px_h): a cell is occupied when any pixel it overlaps is not free under
/// map_server's trinary thresholds (0.65 / 0.196); Stage has no unknown, so unknown pixels count as
/// obstacles (Stage itself uses "first channel <= 127 is an obstacle", stage.cc). Every cell is
/// known. The origin is pose.xy - size / 2. Yaws that are multiples of 90 degrees rotate the grid
/// (willow-erratic.world uses 90); other yaws are a kInput error.
[[nodiscard]] Result<OccupancyGrid> read_stage_world(const std::filesystem::path& path);

}  // namespace tessera
