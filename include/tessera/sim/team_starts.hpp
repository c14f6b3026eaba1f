#pragma once
// Where a team of round robots starts in a world (issue 14's team runs): together, as robots
// unloaded at one door would be. The first robot stands at the cell with room for it nearest the
// centroid of the largest area with room (sim/tour.hpp's room_for_robot); each further robot at
// the next cell with room, in breadth-first order from the first, that is at least spacing_m from
// every robot placed. Heading 0. The same world gives the same starts, so a team of one and a team
// of three start alike.
//
// Each start is the centre of a cell of the robots' map grid (lattice_m, laid from the world's
// origin) inside the chosen world cell. A SLAM map's grid starts at the robot's start, so every
// border of the world's cells, where a simulated world's walls are, then runs through the middle
// of map cells: no wall face falls on a map cell border, where lidar noise would split its hits
// between two cells and scan matching would be biased by them (decision 0022).
#include <vector>

#include "tessera/core/pose2.hpp"
#include "tessera/core/result.hpp"
#include "tessera/sim/world.hpp"

namespace tessera {

/// T_world_robot per robot. Input error when no cell has room for a robot, or when the area around
/// the first start has room for fewer robots than asked.
/// Precondition: lattice_m > 0.
[[nodiscard]] Result<std::vector<Pose2>> team_starts(const World& world, int robots,
                                                     double clearance_m, double spacing_m,
                                                     double lattice_m);

}  // namespace tessera
