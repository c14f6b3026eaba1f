#pragma once
// The navigation of the Fusion SLAM thesis, section 4.3.5 ("Robot Navigation"), as written:
// every stored cell starts at -1 ("not heading towards the goal"); the goal cell gets the number of
// cells stored; the map is swept repeatedly, each cell adjacent to a valued cell getting that value
// minus one; the robot then moves to the adjacent cell with a HIGHER value until it is in the goal
// (the thesis' "trying to increase the points of the current cell", Figure 4.8; after RatSLAM's
// goal memory, Milford & Wyeth).
//
// The sweeps are layered (a cell takes the value of the previous sweep's neighbours), so the value
// of a cell is (number of cells) - (fewest steps to the goal) and climbing the values is a shortest
// path over the adjacency. The thesis stops sweeping once the robot's cell has a value; we sweep
// until nothing changes so a robot that strays still finds values around it (the values of the
// cells the thesis labels are the same). Which adjacency is used is the caller's choice
// (fusion::HexCellMap::graph): the thesis uses the traversed adjacency.
#include <cstddef>
#include <vector>

#include "tessera/grid/cell_graph.hpp"

namespace tessera {

/// The value of a cell the wavefront did not reach (the thesis' -1).
inline constexpr int kNoWavefrontValue = -1;

struct WavefrontField {
  std::size_t goal = 0;
  /// value[i]: cell_count - steps from i to the goal; kNoWavefrontValue where the goal is
  /// unreachable.
  std::vector<int> value;
};

/// The field for `goal`. Precondition: goal < graph.size(). Cost: O(cells + adjacencies).
[[nodiscard]] WavefrontField wavefront(const CellGraph& graph, std::size_t goal);

/// The neighbour of `cell` the thesis' robot moves to: the adjacent cell with the highest value,
/// if higher than the cell's own. Ties (two neighbours one step nearer the goal) go to the one
/// whose centre is nearer the goal cell's centre, then to the lower id. Returns `cell` itself when
/// it is the goal or has no higher neighbour. Precondition: cell < graph.size(), field from graph.
[[nodiscard]] std::size_t wavefront_next(const CellGraph& graph, const WavefrontField& field,
                                         std::size_t cell);

/// The cells from `start` to the goal, both included, climbing the values with wavefront_next.
/// Empty when start cannot reach the goal. Precondition: start < graph.size().
[[nodiscard]] std::vector<std::size_t> wavefront_path(const CellGraph& graph,
                                                      const WavefrontField& field,
                                                      std::size_t start);

/// Length of the polyline through the centres of `cells` (the "cell-path length"), metres.
[[nodiscard]] double cell_path_length_m(const CellGraph& graph,
                                        const std::vector<std::size_t>& cells);

}  // namespace tessera
