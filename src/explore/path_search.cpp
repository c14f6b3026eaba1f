#include "tessera/explore/path_search.hpp"

#include <algorithm>
#include <limits>

#include "tessera/explore/frontier_set.hpp"

namespace tessera {

void FreeSpaceBfs::start(const OccupancyGrid& map, Cell start, double low) {
  const GridGeometry& g = map.geometry();
  TESSERA_ASSERT(g.contains(start));
  TESSERA_ASSERT(low > 0.0 && low < 1.0);
  TESSERA_ASSERT(g.size() < std::numeric_limits<std::uint32_t>::max());
  map_ = &map;
  low_log_odds_ = log_odds(low);
  start_ = start;
  if (stamp_.size() != g.size()) {
    stamp_.assign(g.size(), 0);
    distance_.assign(g.size(), 0);
    from_dir_.assign(g.size(), 0);
    generation_ = 0;
  }
  if (++generation_ == 0) {  // wrapped after 2^32 searches: forget every stamp once
    std::fill(stamp_.begin(), stamp_.end(), 0u);
    generation_ = 1;
  }
  queue_.clear();
  head_ = 0;
  const auto i = static_cast<std::uint32_t>(g.index_of(start));
  stamp_[i] = generation_;
  distance_[i] = 0;
  from_dir_[i] = 0;
  queue_.push_back(i);
}

void FreeSpaceBfs::expand(std::uint32_t index) {
  const GridGeometry& g = map_->geometry();
  const Cell c = g.cell_of(index);
  const std::int32_t next_distance = distance_[index] + 1;
  for (std::uint8_t dir = 0; dir < kNeighbors4.size(); ++dir) {
    const Cell n = c + kNeighbors4[dir];
    if (!g.contains(n)) continue;
    const auto j = static_cast<std::uint32_t>(g.index_of(n));
    if (stamp_[j] == generation_ || !map_->is_free_below(n, low_log_odds_)) continue;
    stamp_[j] = generation_;
    distance_[j] = next_distance;
    from_dir_[j] = dir;
    queue_.push_back(j);
  }
}

std::optional<Cell> FreeSpaceBfs::next() {
  if (map_ == nullptr || head_ == queue_.size()) return std::nullopt;
  const std::uint32_t i = queue_[head_++];
  expand(i);
  return map_->geometry().cell_of(i);
}

std::size_t FreeSpaceBfs::run_to_completion() {
  while (next()) {
  }
  return queue_.size();
}

bool FreeSpaceBfs::discovered(Cell c) const {
  if (map_ == nullptr || !map_->geometry().contains(c)) return false;
  return stamp_[map_->geometry().index_of(c)] == generation_;
}

int FreeSpaceBfs::distance(Cell c) const {
  return discovered(c) ? distance_[map_->geometry().index_of(c)] : -1;
}

std::vector<Cell> FreeSpaceBfs::path_to(Cell c) const {
  if (!discovered(c)) return {};
  const GridGeometry& g = map_->geometry();
  std::vector<Cell> path(static_cast<std::size_t>(distance_[g.index_of(c)]) + 1);
  Cell at = c;
  for (std::size_t k = path.size(); k-- > 0;) {
    path[k] = at;
    if (k > 0) at = at - kNeighbors4[from_dir_[g.index_of(at)]];
  }
  return path;
}

std::vector<int> free_space_distances(const OccupancyGrid& map, Cell start, double low) {
  FreeSpaceBfs bfs;
  bfs.start(map, start, low);
  std::vector<int> distances(map.geometry().size(), -1);
  while (const std::optional<Cell> c = bfs.next()) {
    distances[map.geometry().index_of(*c)] = bfs.distance(*c);
  }
  return distances;
}

std::vector<Cell> shortest_free_path(const OccupancyGrid& map, Cell start, Cell goal, double low) {
  FreeSpaceBfs bfs;
  bfs.start(map, start, low);
  while (const std::optional<Cell> c = bfs.next()) {
    if (*c == goal) return bfs.path_to(goal);
  }
  return {};
}

std::optional<FrontierPath> nearest_frontier(FreeSpaceBfs& bfs, const OccupancyGrid& map,
                                             const FrontierSet& frontier, Cell start) {
  bfs.start(map, start, frontier.low());
  while (const std::optional<Cell> c = bfs.next()) {
    if (frontier.contains(*c)) return FrontierPath{*c, bfs.distance(*c), bfs.path_to(*c)};
  }
  return std::nullopt;
}

}  // namespace tessera
