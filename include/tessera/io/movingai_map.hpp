#pragma once
// Moving AI Lab grid benchmark maps (movingai.com/benchmarks/formats.html, Sturtevant 2012):
//   type octile
//   height H
//   width W
//   map
// then H rows of W characters. '.', 'G' (ground) and 'S' (swamp) are passable; '@' and 'O' (out of
// bounds), 'T' (trees), 'W' (water) and any other character are blocked.
#include <filesystem>

#include "tessera/core/result.hpp"
#include "tessera/grid/occupancy_grid.hpp"

namespace tessera {

/// Reads a .map file. Every cell is known: passable p = 0, blocked p = 1. File row 0 is the top
/// (cell row H - 1); the origin is (0, 0). kInput errors name the line: bad header, "height says 32
/// but 31 rows follow", a row of the wrong width, cell_size_m <= 0.
[[nodiscard]] Result<OccupancyGrid> read_movingai_map(const std::filesystem::path& path,
                                                      double cell_size_m = 1.0);

}  // namespace tessera
