#include "tessera/explore/frontier_explorer.hpp"

#include <algorithm>
#include <cstdlib>

namespace tessera {

const char* to_string(FrontierStrategy s) {
  switch (s) {
    case FrontierStrategy::kNearest:
      return "nearest";
    case FrontierStrategy::kPriority:
      return "priority";
  }
  return "unknown";
}

std::optional<std::string> validate(const FrontierExplorerOptions& o) {
  if (!(o.low > 0.0 && o.low < 1.0)) return "low must be in (0, 1)";
  if (o.spread_radius_cells < 0) return "spread_radius_cells must be >= 0";
  if (o.strategy != FrontierStrategy::kNearest && o.strategy != FrontierStrategy::kPriority) {
    return "strategy must be nearest or priority";
  }
  return std::nullopt;
}

FrontierExplorer::FrontierExplorer(const FrontierExplorerOptions& options, int robots)
    : options_(options),
      claims_(static_cast<std::size_t>(robots)),
      failures_(static_cast<std::size_t>(robots)) {
  TESSERA_ASSERT(!validate(options).has_value());
  TESSERA_ASSERT(robots >= 1);
}

std::optional<Cell> FrontierExplorer::claim(int robot) const {
  TESSERA_ASSERT(0 <= robot && robot < robot_count());
  return claims_[static_cast<std::size_t>(robot)];
}

void FrontierExplorer::release(int robot) {
  TESSERA_ASSERT(0 <= robot && robot < robot_count());
  auto& claim = claims_[static_cast<std::size_t>(robot)];
  if (claim.has_value()) {
    claim.reset();
    ++claims_version_;
  }
}

void FrontierExplorer::blacklist(Cell c) {
  if (blacklisted(c)) return;
  blacklist_list_.push_back(c);
  if (blacklist_geometry_.contains(c)) blacklist_[blacklist_geometry_.index_of(c)] = 1;
  // Blacklisting can make a failed robot's answer stale only by removing candidates, never by
  // adding them, so the failure memo stays valid.
}

bool FrontierExplorer::blacklisted(Cell c) const {
  if (blacklist_geometry_.contains(c)) return blacklist_[blacklist_geometry_.index_of(c)] != 0;
  return std::find(blacklist_list_.begin(), blacklist_list_.end(), c) != blacklist_list_.end();
}

bool FrontierExplorer::claimed_by_other(Cell c, int robot) const {
  for (std::size_t r = 0; r < claims_.size(); ++r) {
    if (static_cast<int>(r) != robot && claims_[r] == c) return true;
  }
  return false;
}

bool FrontierExplorer::near_other_claim(Cell c, int robot) const {
  const int radius = options_.spread_radius_cells;
  for (std::size_t r = 0; r < claims_.size(); ++r) {
    if (static_cast<int>(r) == robot || !claims_[r].has_value()) continue;
    const Cell d = c - *claims_[r];
    if (std::abs(d.x) <= radius && std::abs(d.y) <= radius) return true;
  }
  return false;
}

void FrontierExplorer::record_unreachable(const FrontierSet& frontier) {
  unreachable_.clear();
  for (const Cell c : frontier.cells()) {
    if (!bfs_.discovered(c) && !blacklisted(c)) unreachable_.push_back({c, frontier.revision()});
  }
}

std::optional<FrontierPlan> FrontierExplorer::plan(const OccupancyGrid& map,
                                                   const FrontierSet& frontier, int robot,
                                                   Cell robot_cell) {
  TESSERA_ASSERT(0 <= robot && robot < robot_count());
  TESSERA_ASSERT(frontier.low() == options_.low);
  const auto r = static_cast<std::size_t>(robot);
  release(robot);

  // Nothing changed since this robot's search last came back empty: the answer is the same.
  if (const auto& f = failures_[r]; f.has_value() && f->revision == frontier.revision() &&
                                    f->claims_version == claims_version_ && f->cell == robot_cell) {
    return std::nullopt;
  }

  if (!(blacklist_geometry_ == map.geometry())) {
    blacklist_geometry_ = map.geometry();
    blacklist_.assign(blacklist_geometry_.size(), 0);
    for (const Cell c : blacklist_list_) {
      if (blacklist_geometry_.contains(c)) blacklist_[blacklist_geometry_.index_of(c)] = 1;
    }
  }

  // Best candidate away from other robots' targets, and the fallback near them.
  std::optional<Cell> best, fallback;
  int best_a = 0, best_d = 1, fallback_a = 0, fallback_d = 1;
  // a / d > a' / d'  <=>  a * d' > a' * d (all positive): exact integer comparison.
  const auto better = [](int a, int d, int a2, int d2) { return a * d2 > a2 * d; };
  const bool priority = options_.strategy == FrontierStrategy::kPriority;

  bfs_.start(map, robot_cell, options_.low);
  while (const std::optional<Cell> c = bfs_.next()) {
    const int d = std::max(bfs_.distance(*c), 1);  // d = 0 (robot on the frontier) counts as 1
    // Priority pruning: a <= 4, so a cell at depth d has p <= 4 / d; once 4 / d <= p_best no deeper
    // cell can win (ties go to the cell found first).
    if (priority && best.has_value() && 4 * best_d <= best_a * d) break;
    if (!frontier.contains(*c) || blacklisted(*c) || claimed_by_other(*c, robot)) continue;
    const bool near_claim = near_other_claim(*c, robot);
    if (!priority) {
      if (!near_claim) {
        best = *c;
        break;
      }
      if (!fallback.has_value()) fallback = *c;
      continue;
    }
    const int a = unknown_neighbors(map, *c);
    if (near_claim) {
      if (!fallback.has_value() || better(a, d, fallback_a, fallback_d)) {
        fallback = *c;
        fallback_a = a;
        fallback_d = d;
      }
    } else if (!best.has_value() || better(a, d, best_a, best_d)) {
      best = *c;
      best_a = a;
      best_d = d;
    }
  }

  const std::optional<Cell> chosen = best.has_value() ? best : fallback;
  if (!chosen.has_value()) {
    failures_[r] = Failure{frontier.revision(), claims_version_, robot_cell};
    record_unreachable(frontier);
    return std::nullopt;
  }
  failures_[r].reset();
  FrontierPlan plan;
  plan.target = *chosen;
  plan.path = bfs_.path_to(*chosen);
  plan.distance_cells = static_cast<int>(plan.path.size()) - 1;
  plan.unknown_neighbors = unknown_neighbors(map, *chosen);
  plan.priority = static_cast<double>(plan.unknown_neighbors) /
                  static_cast<double>(std::max(plan.distance_cells, 1));
  claims_[r] = *chosen;
  ++claims_version_;
  return plan;
}

std::vector<std::optional<FrontierPlan>> FrontierExplorer::plan_all(
    const OccupancyGrid& map, const FrontierSet& frontier, std::span<const Cell> robot_cells) {
  TESSERA_ASSERT(static_cast<int>(robot_cells.size()) == robot_count());
  std::vector<std::optional<FrontierPlan>> plans;
  plans.reserve(robot_cells.size());
  for (std::size_t r = 0; r < robot_cells.size(); ++r) {
    plans.push_back(plan(map, frontier, static_cast<int>(r), robot_cells[r]));
  }
  return plans;
}

}  // namespace tessera
