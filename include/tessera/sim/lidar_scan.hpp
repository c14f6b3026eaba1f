#pragma once
// One simulated 2D lidar scan of a world: what the simulator, the simulated laser runs and the
// simulator node (nodes/sim_node.hpp) all measure with.
#include <span>

#include "tessera/core/pose2.hpp"
#include "tessera/core/rng.hpp"
#include "tessera/sensors/lidar.hpp"
#include "tessera/sensors/range_scan.hpp"
#include "tessera/sim/world.hpp"

namespace tessera {

/// A scan from T_world_laser: each beam is World::cast_ray plus a Gaussian draw from `rng` (one
/// draw per beam, hit or not, so a beam's noise does not depend on the others) truncated at
/// 3 sigma, like a datasheet's maximum range error (with ScanInsertOptions::free_margin_m >=
/// 3 sigma no beam can clear the wall cell it hit), clamped to [0, max_range_m]. A beam that hits
/// nothing within max_range_m reports exactly max_range_m ("no return"), without noise.
/// Cost: O(beams * max_range_m / resolution).
[[nodiscard]] RangeScan simulate_lidar_scan(const World& world, const Pose2& T_world_laser,
                                            const LidarOptions& lidar, Rng& rng);

/// The same for a lidar that sweeps its beams one after the other while it moves: beam i is cast
/// from T_world_laser_per_beam[i] (one pose per beam, lidar.beams of them). The scan's beam times
/// are the caller's to set.
[[nodiscard]] RangeScan simulate_lidar_scan(const World& world,
                                            std::span<const Pose2> T_world_laser_per_beam,
                                            const LidarOptions& lidar, Rng& rng);

}  // namespace tessera
