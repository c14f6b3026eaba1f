#pragma once
// Where a team of round robots starts in a world (issue 14's team runs): together, as robots
// unloaded at one door would be. The first robot stands at the cell with room for it nearest the
// centroid of the largest area with room (sim/tour.hpp's room_for_robot); each further robot at
// the next cell with room, in breadth-first order from the first, that is at least spacing_m from
// every robot placed. Every start is a cell centre, heading 0. The same world gives the same
// starts, so a team of one and a team of three start alike.
#include <vector>

#include "tessera/core/pose2.hpp"
#include "tessera/core/result.hpp"
#include "tessera/sim/world.hpp"

namespace tessera {

/// T_world_robot per robot. Input error when no cell has room for a robot, or when the area around
/// the first start has room for fewer robots than asked.
[[nodiscard]] Result<std::vector<Pose2>> team_starts(const World& world, int robots,
                                                     double clearance_m, double spacing_m);

}  // namespace tessera
