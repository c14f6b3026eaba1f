#pragma once
// A topological map: cell centres and which cells are adjacent. The hex-cell map of the Fusion SLAM
// thesis hands one of these to navigation (nav/wavefront.hpp, nav/cell_polyline.hpp), so planning
// does not depend on how the cells were made.
#include <cstddef>
#include <vector>

#include "tessera/core/vec2.hpp"

namespace tessera {

struct CellGraph {
  /// Centre of cell i in the map frame, metres.
  std::vector<Vec2> centres_m;
  /// adjacent[i]: the cells adjacent to i, ascending, without i itself. Symmetric.
  std::vector<std::vector<std::size_t>> adjacent;

  [[nodiscard]] std::size_t size() const { return centres_m.size(); }

  /// The cell whose centre is nearest to p_m; ties go to the lower id. Precondition: size() > 0.
  /// Cost: O(size()).
  [[nodiscard]] std::size_t nearest(Vec2 p_m) const;
};

}  // namespace tessera
