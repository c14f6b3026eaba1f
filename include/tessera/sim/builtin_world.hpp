#pragma once
#include <string>
#include <vector>

#include "tessera/sim/world.hpp"

namespace tessera {

/// Names of the floor plans tessera ships (made in code, no data files).
[[nodiscard]] std::vector<std::string> builtin_world_names();

/// A built-in floor plan rasterised at `resolution_m`, or an empty World (size 0) for an unknown
/// name. "office": 16 m x 12 m, four rooms off a corridor, a hall with a pillar; walls 0.2 m thick.
/// "labyrinth": the lecture's small maze of corridors one metre wide, 8 m x 8 m.
/// "bob-arena": a BOBMapping-like 2.42 m x 3.08 m arena (11 x 14 cells of 0.22 m, section 4.2)
/// with polystyrene barriers, closed by boards; "bob-arena-open": the same barriers on an open
/// floor 0.44 m wider all round (crop 0.44,0.44,2.86,3.52 for the 11 x 14 grid). Both are drawn
/// at 0.22 / n m, n >= 20, the coarsest such resolution no coarser than `resolution_m`.
/// "lecture-corner": the corner of a room with a pillar from the lecture's numerical SLAM example,
/// 12 x 9 cells of 0.3 m (3.6 m x 2.7 m), open on the right; `tessera gridmatch` runs the example
/// in it at 0.3 m.
[[nodiscard]] World builtin_world(const std::string& name, double resolution_m = 0.1);

/// An empty room of width_cells x height_cells cells of resolution_m whose border cells are
/// walls (one cell thick), origin at (0, 0): the rooms of the camera tests (stationary_scene.hpp,
/// blank_room.hpp).
[[nodiscard]] World walled_room(int width_cells, int height_cells, double resolution_m,
                                std::string name);

}  // namespace tessera
