#include "tessera/explore/frontier_set.hpp"

#include <algorithm>
#include <limits>

namespace tessera {

FrontierSet::FrontierSet(const OccupancyGrid& map, double low)
    : low_(low), low_log_odds_(log_odds(low)) {
  TESSERA_ASSERT(low > 0.0 && low < 1.0);
  reset(map);
}

std::uint8_t FrontierSet::state_of(const OccupancyGrid& map, Cell c) const {
  if (!map.known(c)) return 0;
  return map.is_free_below(c, low_log_odds_) ? (kKnown | kFree) : kKnown;
}

void FrontierSet::reset(const OccupancyGrid& map) {
  geometry_ = map.geometry();
  TESSERA_ASSERT(geometry_.size() < std::numeric_limits<std::uint32_t>::max());
  state_.assign(geometry_.size(), 0);
  slot_.assign(geometry_.size(), kAbsent);
  members_.clear();
  for (int y = 0; y < geometry_.height(); ++y) {
    for (int x = 0; x < geometry_.width(); ++x) {
      const Cell c{x, y};
      state_[geometry_.index_of(c)] = state_of(map, c);
    }
  }
  for (int y = 0; y < geometry_.height(); ++y) {
    for (int x = 0; x < geometry_.width(); ++x) recheck({x, y}, geometry_.index_of({x, y}));
  }
  ++revision_;
}

void FrontierSet::insert(Cell c, std::size_t index) {
  slot_[index] = static_cast<std::uint32_t>(members_.size());
  state_[index] |= kMember;
  members_.push_back(c);
}

void FrontierSet::erase(std::size_t index) {
  const std::uint32_t pos = slot_[index];
  const Cell last = members_.back();
  members_[pos] = last;
  slot_[geometry_.index_of(last)] = pos;
  members_.pop_back();
  slot_[index] = kAbsent;
  state_[index] &= static_cast<std::uint8_t>(~kMember);
}

bool FrontierSet::recheck(Cell c, std::size_t i) {
  bool frontier = false;
  if ((state_[i] & (kKnown | kFree)) == (kKnown | kFree)) {
    const auto w = static_cast<std::size_t>(geometry_.width());
    if (c.x > 0 && c.y > 0 && c.x + 1 < geometry_.width() && c.y + 1 < geometry_.height()) {
      // Interior cell: the four neighbours are at i + w, i + 1, i - w, i - 1 (N, E, S, W).
      frontier = ((state_[i + w] & state_[i + 1] & state_[i - w] & state_[i - 1]) & kKnown) == 0;
    } else {
      for (const Cell d : kNeighbors4) {
        const Cell n = c + d;
        if (geometry_.contains(n) && (state_[geometry_.index_of(n)] & kKnown) == 0) {
          frontier = true;
          break;
        }
      }
    }
  }
  const bool member = (state_[i] & kMember) != 0;
  if (frontier == member) return false;
  if (frontier) {
    insert(c, i);
  } else {
    erase(i);
  }
  return true;
}

void FrontierSet::update(const OccupancyGrid& map, std::span<const Cell> touched) {
  TESSERA_ASSERT(map.geometry() == geometry_);
  bool changed = false;
  for (const Cell c : touched) {
    if (!geometry_.contains(c)) continue;
    const std::size_t i = geometry_.index_of(c);
    const std::uint8_t s = state_of(map, c);
    const auto old = static_cast<std::uint8_t>(state_[i] & (kKnown | kFree));
    if (s == old) continue;
    // Correct even while later touched cells are still stale: each changed cell re-examines what
    // its change can affect, so the last changed cell next to any cell re-examines it with final
    // data. A cell's own status reads its known and free bits; its neighbours' statuses read only
    // its known bit.
    state_[i] = static_cast<std::uint8_t>(s | (state_[i] & kMember));
    changed = true;
    recheck(c, i);
    if (((s ^ old) & kKnown) == 0) continue;
    for (const Cell d : kNeighbors4) {
      const Cell n = c + d;
      if (!geometry_.contains(n)) continue;
      const std::size_t j = geometry_.index_of(n);
      // Only an open cell can be or become a frontier cell (a member that stopped being open was
      // re-examined when it changed), so skip the rest without a look at their neighbours.
      if ((state_[j] & (kKnown | kFree)) == (kKnown | kFree)) recheck(n, j);
    }
  }
  if (changed) ++revision_;
}

std::vector<Cell> FrontierSet::cells() const {
  std::vector<Cell> sorted = members_;
  std::sort(sorted.begin(), sorted.end(),
            [](Cell a, Cell b) { return a.y != b.y ? a.y < b.y : a.x < b.x; });
  return sorted;
}

}  // namespace tessera
