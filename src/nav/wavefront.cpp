#include "tessera/nav/wavefront.hpp"

#include "tessera/core/assert.hpp"

namespace tessera {

WavefrontField wavefront(const CellGraph& graph, std::size_t goal) {
  TESSERA_ASSERT(goal < graph.size());
  TESSERA_ASSERT(graph.adjacent.size() == graph.size());
  WavefrontField f;
  f.goal = goal;
  f.value.assign(graph.size(), kNoWavefrontValue);
  f.value[goal] = static_cast<int>(graph.size());
  // One layered sweep per value: the cells labelled in the last sweep hand value - 1 to their
  // unlabelled neighbours. Keeping the frontier of the last sweep makes the whole field
  // O(cells + adjacencies) instead of O(cells^2) for full re-sweeps; the values are identical.
  std::vector<std::size_t> layer{goal};
  std::vector<std::size_t> next;
  while (!layer.empty()) {
    next.clear();
    for (const std::size_t c : layer) {
      for (const std::size_t n : graph.adjacent[c]) {
        if (f.value[n] == kNoWavefrontValue) {
          f.value[n] = f.value[c] - 1;
          next.push_back(n);
        }
      }
    }
    layer.swap(next);
  }
  return f;
}

std::size_t wavefront_next(const CellGraph& graph, const WavefrontField& field, std::size_t cell) {
  TESSERA_ASSERT(cell < graph.size() && field.value.size() == graph.size());
  if (cell == field.goal || field.value[cell] == kNoWavefrontValue) return cell;
  const Vec2 goal_c = graph.centres_m[field.goal];
  std::size_t best = cell;
  int best_value = field.value[cell];
  double best_d = 0.0;
  for (const std::size_t n : graph.adjacent[cell]) {  // ascending ids: ties keep the lower id
    const int v = field.value[n];
    const double d = (graph.centres_m[n] - goal_c).norm();
    if (v > best_value || (v == best_value && best != cell && d < best_d)) {
      best = n;
      best_value = v;
      best_d = d;
    }
  }
  return best;
}

std::vector<std::size_t> wavefront_path(const CellGraph& graph, const WavefrontField& field,
                                        std::size_t start) {
  TESSERA_ASSERT(start < graph.size() && field.value.size() == graph.size());
  if (field.value[start] == kNoWavefrontValue) return {};
  std::vector<std::size_t> path{start};
  // Each step raises the value by exactly one, so the loop ends at the goal.
  while (path.back() != field.goal) {
    const std::size_t n = wavefront_next(graph, field, path.back());
    TESSERA_ASSERT(n != path.back());
    path.push_back(n);
  }
  return path;
}

double cell_path_length_m(const CellGraph& graph, const std::vector<std::size_t>& cells) {
  double len = 0.0;
  for (std::size_t i = 1; i < cells.size(); ++i) {
    len += (graph.centres_m[cells[i]] - graph.centres_m[cells[i - 1]]).norm();
  }
  return len;
}

}  // namespace tessera
