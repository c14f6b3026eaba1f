#include "tessera/mission/bob_mission.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "tessera/bob/final_map.hpp"
#include "tessera/bob/packed_map.hpp"

namespace tessera {
namespace {

constexpr int kSafetyMovesPerCell = 64;
constexpr std::size_t kMapBytes = static_cast<std::size_t>(kMaxBobCells);  // >= ceil(w/2) * h
constexpr std::size_t kScratchBytes = bob::Explorer::scratch_bytes(kMaxBobCells, 1);
constexpr std::size_t kFinalBytes = static_cast<std::size_t>(kMaxBobCells);  // >= ceil(w/8) * h

/// The robot's memory: fixed buffers, as on the microcontroller.
struct RobotBuffers {
  std::array<std::uint8_t, kMapBytes> map{};
  std::array<std::uint8_t, kScratchBytes> scratch{};
  std::array<std::uint8_t, kFinalBytes> final_map{};
};

std::string metres_text(double m) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", m);
  return buf;
}

bob::GridCell to_grid(Cell c) { return {c.x, c.y}; }

/// See BobMissionOptions::start.
std::optional<Cell> default_start(const World& world) {
  const GridGeometry& g = world.geometry();
  const World::FreeComponents components = world.free_components();
  const std::vector<std::int32_t>& label = components.label;
  const std::vector<std::size_t>& sizes = components.sizes;
  // Components from largest to smallest (ties: the first found); the first with a usable cell.
  std::vector<std::int32_t> order(sizes.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<std::int32_t>(i);
  std::stable_sort(order.begin(), order.end(), [&](std::int32_t a, std::int32_t b) {
    return sizes[static_cast<std::size_t>(a)] > sizes[static_cast<std::size_t>(b)];
  });
  for (const std::int32_t l : order) {
    for (std::size_t i = 0; i < g.size(); ++i) {
      if (label[i] != l) continue;
      const Cell c = g.cell_of(i);
      if (world.free(c + kNeighbors4[0])) return c;
    }
  }
  return std::nullopt;
}

/// `world` with one more solid cell all round and `free_cell` (which may lie in that ring) free.
World with_free_cell(const World& world, Cell free_cell) {
  const GridGeometry& g = world.geometry();
  const double r = g.resolution_m();
  const GridGeometry padded(g.origin() - Vec2{r, r}, r, g.width() + 2, g.height() + 2);
  std::vector<std::uint8_t> solid(padded.size(), 1);
  for (int y = -1; y <= g.height(); ++y) {
    for (int x = -1; x <= g.width(); ++x) {
      const Cell c{x, y};
      const bool is_free = c == free_cell || world.free(c);
      solid[padded.index_of({x + 1, y + 1})] = is_free ? 0 : 1;
    }
  }
  return World(padded, std::move(solid), world.name());
}

void report(bob::Explorer& explorer, const StepSensing& s) {
  for (const CellDetection* d : {&s.left, &s.front, &s.right}) {
    (void)explorer.sense(to_grid(d->cell), d->occupied);  // kOutOfBounds past the edge: ignored
  }
}

}  // namespace

const char* bob_variant_name(BobVariant v) {
  return v == BobVariant::kTrail ? "trail" : "map-aware";
}

Result<BobResult> run_bob(const World& world, const BobMissionOptions& options) {
  const GridGeometry& g = world.geometry();
  BobSensingOptions sensing;
  sensing.layout.cell_m = g.resolution_m();
  sensing.layout.robot_length_m = options.robot_length_m;
  sensing.layout.robot_width_m = options.robot_width_m;
  sensing.samples_per_move = options.samples_per_move;
  if (!options.noise) {
    sensing.lateral = without_noise(sensing.lateral);
    sensing.front = without_noise(sensing.front);
  }
  if (validate(sensing.layout)) {
    return input_error("cell " + metres_text(g.resolution_m()) + " m does not fit the robot (" +
                       metres_text(options.robot_length_m) + " x " +
                       metres_text(options.robot_width_m) + " m)");
  }
  const long long n_cells = static_cast<long long>(g.width()) * g.height();
  if (n_cells > kMaxBobCells) {
    return input_error("world is " + std::to_string(g.width()) + " x " +
                       std::to_string(g.height()) + " = " + std::to_string(n_cells) +
                       " cells, more than the robot's buffers hold (" +
                       std::to_string(kMaxBobCells) + ")");
  }
  if (n_cells < 1) return input_error("world has no cells");

  if (auto problem = validate(sensing)) return usage_error(*problem);

  Cell start{};
  if (options.start) {
    start = *options.start;
    if (!g.contains(start)) return input_error("start " + to_string(start) + " is outside the map");
    if (world.solid(start)) {
      return input_error("start " + to_string(start) + " is inside an obstacle");
    }
  } else {
    const std::optional<Cell> s = default_start(world);
    if (!s) return input_error("no free cell with a free cell in front (North) to start from");
    start = *s;
  }
  const Cell front = start + kNeighbors4[0];
  if (world.solid(front)) {
    return input_error("start " + to_string(start) +
                       ": the cell in front must be free (BOBMapping 3.4)");
  }

  const bob::Backtrack backtrack = options.variant == BobVariant::kTrail
                                       ? bob::Backtrack::kTrail
                                       : bob::Backtrack::kShortestKnownPath;
  auto buffers = std::make_unique<RobotBuffers>();
  bob::Explorer explorer;
  if (const bob::Status s =
          explorer.init(bob::ExplorerOptions{backtrack}, buffers->map.data(), buffers->map.size(),
                        g.width(), g.height(), buffers->scratch.data(), buffers->scratch.size());
      s != bob::Status::kOk) {
    return runtime_error(std::string("explorer init: ") + bob::status_name(s));
  }

  Rng rng(options.seed);
  BobResult out;
  out.start = start;
  out.width = g.width();
  out.height = g.height();
  out.route.push_back(start);

  // At rest: the three cells around the start, as if the robot had just driven in from behind.
  {
    const Cell behind = start - kNeighbors4[0];
    const World approach = with_free_cell(world, behind);
    report(explorer,
           sense_cells_while_moving(approach, g, centred_pose(g, behind, 0), sensing, rng));
  }
  if (const bob::Status s = explorer.start(to_grid(start), bob::Direction::kNorth);
      s != bob::Status::kOk) {
    // Only kFrontBlocked is possible here: the sensors read the free front cell as occupied.
    return input_error("start " + to_string(start) +
                       ": the cell in front must be free (BOBMapping 3.4), sensed " +
                       bob::status_name(s));
  }

  const long long max_moves = kSafetyMovesPerCell * n_cells;
  Cell pos = start;
  for (;;) {
    bob::Direction d{};
    const bob::Status s = explorer.next_move(d);
    if (s == bob::Status::kFinished) break;
    if (s != bob::Status::kOk) {
      return runtime_error(std::string("explorer: ") + bob::status_name(s));
    }
    const int h = static_cast<int>(d);
    const Cell next = pos + kNeighbors4[static_cast<std::size_t>(h)];
    if (world.solid(next)) {
      return runtime_error("the robot drove into an obstacle at " + to_string(next));
    }
    report(explorer, sense_cells_while_moving(world, g, centred_pose(g, pos, h), sensing, rng));
    pos = next;
    out.route.push_back(pos);
    if (static_cast<long long>(out.route.size()) > max_moves) {
      return runtime_error("the explorer did not stop within " + std::to_string(max_moves) +
                           " moves");
    }
  }
  out.stop_reason = explorer.stop_reason();

  const std::size_t final_bytes = bob::FinalMap::bytes_needed(g.width(), g.height());
  if (const bob::Status s = explorer.write_final_map(buffers->final_map.data(), final_bytes);
      s != bob::Status::kOk) {
    return runtime_error(std::string("final map: ") + bob::status_name(s));
  }
  out.final_map.assign(buffers->final_map.begin(),
                       buffers->final_map.begin() + static_cast<std::ptrdiff_t>(final_bytes));

  // Table 1.
  BobTableRow& row = out.row;
  const bob::PackedMap& map = explorer.map();
  row.cells = static_cast<int>(n_cells);
  out.sensed.assign(g.size(), 0);
  std::vector<std::uint8_t> visited(g.size(), 0);
  for (const Cell c : out.route) visited[g.index_of(c)] = 1;
  for (std::size_t i = 0; i < g.size(); ++i) {
    const Cell c = g.cell_of(i);
    const bob::CellState st = map.state(to_grid(c));
    row.visited_cells += visited[i];
    if (st == bob::CellState::kUnsensed) continue;
    out.sensed[i] = 1;
    ++row.sensed_cells;
    const bool occupied = st == bob::CellState::kOccupied;
    if (occupied && world.free(c)) ++row.empty_as_occupied;
    if (!occupied && world.solid(c)) ++row.occupied_as_empty;
  }
  row.resensed = static_cast<int>(explorer.resensed());
  row.path_cells = static_cast<int>(explorer.moves());
  row.turns = static_cast<int>(explorer.turns());
  row.success_rate =
      static_cast<double>(row.cells - row.empty_as_occupied - row.occupied_as_empty) / row.cells;
  row.path_share = static_cast<double>(row.path_cells) / row.cells;
  row.visited_share = static_cast<double>(row.visited_cells) / row.cells;
  const std::vector<std::uint8_t> reachable = world.reachable_from(start);
  for (std::size_t i = 0; i < g.size(); ++i) {
    if (reachable[i] == 0) continue;
    ++row.free_reachable;
    const Cell c = g.cell_of(i);
    for (const Cell d : kNeighbors4) {
      const Cell m = c + d;
      if (!g.contains(m) || reachable[g.index_of(m)] == 0) ++row.boundary_edges;
    }
  }
  const double c_cells = row.free_reachable;
  row.path_per_c = c_cells > 0 ? row.path_cells / c_cells : 0.0;
  const double bound = c_cells + 0.5 * row.boundary_edges - 3.0;
  row.path_per_smartdfs = bound > 0 ? row.path_cells / bound : 0.0;
  return out;
}

}  // namespace tessera
