#include "tessera/grid/cell_graph.hpp"

#include <limits>

#include "tessera/core/assert.hpp"

namespace tessera {

std::size_t CellGraph::nearest(Vec2 p_m) const {
  TESSERA_ASSERT(!centres_m.empty());
  std::size_t best = 0;
  double best_d2 = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < centres_m.size(); ++i) {
    const Vec2 d = p_m - centres_m[i];
    const double d2 = d.dot(d);
    if (d2 < best_d2) {  // strict: ties keep the lower id
      best_d2 = d2;
      best = i;
    }
  }
  return best;
}

}  // namespace tessera
