#include "tessera/mission/bob_mission.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "internal/bob_body.hpp"
#include "tessera/sim/bob_explorer_port.hpp"
#include "tessera/bob/final_map.hpp"
#include "tessera/bob/packed_map.hpp"
#include "tessera/core/angle.hpp"

namespace tessera {
namespace {

constexpr int kSafetyMovesPerCell = 64;
constexpr int kMaxBumps = 3;  // tries of one move into a visited cell that the body cannot enter
constexpr std::size_t kMapBytes = static_cast<std::size_t>(kMaxBobCells);    // >= ceil(w/2) * h
constexpr std::size_t kFinalBytes = static_cast<std::size_t>(kMaxBobCells);  // >= ceil(w/8) * h

/// The robot's memory: fixed buffers, as on the microcontroller. The explorer keeps the final map
/// current in `final_map` (it also holds obstacles inside visited cells, decision 0008).
struct RobotBuffers {
  std::array<std::uint8_t, kMapBytes> map{};
  std::array<std::uint8_t, kFinalBytes> final_map{};
};

std::string metres_text(double m) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", m);
  return buf;
}

bob::GridCell to_grid(Cell c) { return {c.x, c.y}; }

/// See BobMissionOptions::start: the candidates in order of preference.
std::vector<Cell> start_candidates(const World& world) {
  std::vector<Cell> out;
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
  // Preferably a cell in open space (all eight neighbours free), so that the first readings are
  // not of a wall grazing the front cell; otherwise any cell with a free front neighbour.
  const auto open_space = [&](Cell c) {
    for (const Cell d : kNeighbors8) {
      if (world.solid(c + d)) return false;
    }
    return true;
  };
  for (const bool need_open_space : {true, false}) {
    for (const std::int32_t l : order) {
      for (std::size_t i = 0; i < g.size(); ++i) {
        if (label[i] != l) continue;
        const Cell c = g.cell_of(i);
        if (world.free(c + kNeighbors4[0]) && open_space(c) == need_open_space) {
          out.push_back(c);
        }
      }
    }
  }
  return out;
}

/// `world` with the fine cells whose centres lie in robot cell `cell` of `cells` free, padded by
/// one robot cell of solid all round so that `cell` may lie just outside the grid.
World with_free_cell(const World& world, const GridGeometry& cells, Cell cell) {
  const GridGeometry& g = world.geometry();
  const double r = g.resolution_m();
  const int pad = static_cast<int>(std::ceil(cells.resolution_m() / r)) + 1;
  const GridGeometry padded(g.origin() - Vec2{pad * r, pad * r}, r, g.width() + 2 * pad,
                            g.height() + 2 * pad);
  std::vector<std::uint8_t> solid(padded.size(), 1);
  for (std::size_t i = 0; i < padded.size(); ++i) {
    const Cell p = padded.cell_of(i);
    const bool in_cell = cells.cell_at_unchecked(padded.center_of(p)) == cell;
    solid[i] = in_cell || world.free(p - Cell{pad, pad}) ? 0 : 1;
  }
  return World(padded, std::move(solid), world.name());
}

/// True when the robot's rectangular body (length along its heading) at pose T overlaps a solid
/// cell of `world`; sampled on points no farther apart than half a world cell.
bool body_hits(const World& world, const Pose2& T, double length_m, double width_m) {
  const double spacing = 0.5 * world.geometry().resolution_m();
  const int nx = static_cast<int>(std::ceil(length_m / spacing));
  const int ny = static_cast<int>(std::ceil(width_m / spacing));
  for (int i = 0; i <= nx; ++i) {
    for (int j = 0; j <= ny; ++j) {
      const Vec2 p_robot{(i / static_cast<double>(nx) - 0.5) * length_m,
                         (j / static_cast<double>(ny) - 0.5) * width_m};
      if (world.solid(world.geometry().cell_at_unchecked(T * p_robot))) return true;
    }
  }
  return false;
}

/// How far the body can drive straight ahead from T, up to distance_m, before it touches a solid
/// cell of `world` (checked every half world cell, at most 5 mm).
double free_travel(const World& world, const Pose2& T, double distance_m, double length_m,
                   double width_m) {
  const double step_m = std::min(0.005, 0.5 * world.geometry().resolution_m());
  const int n = static_cast<int>(std::ceil(distance_m / step_m));
  for (int k = 0; k <= n; ++k) {
    const double s_m = std::min(distance_m, k * step_m);
    if (body_hits(world, T * Pose2{s_m, 0.0, 0.0}, length_m, width_m)) {
      return std::max(0.0, s_m - step_m);
    }
  }
  return distance_m;
}

/// The robot's grid over `world` (or over options.grid_rect_m of it) and the ground truth of each
/// of its cells: occupied when any solid cell of `world` overlaps it (World::resampled's rule; a
/// cell reaching past the rectangle looks at the world there, not at the rectangle's edge).
World robot_grid_truth(const World& world, const BobMissionOptions& options) {
  if (!options.grid_rect_m) return world.resampled(options.cell_m);
  const World rect = world.cropped((*options.grid_rect_m)[0], (*options.grid_rect_m)[1]);
  const GridGeometry g = rect.resampled(options.cell_m).geometry();
  std::vector<std::uint8_t> solid(g.size(), 0);
  const Vec2 half{0.5 * options.cell_m, 0.5 * options.cell_m};
  for (std::size_t i = 0; i < g.size(); ++i) {
    const Vec2 centre = g.center_of(g.cell_of(i));
    solid[i] = world.any_solid_in(centre - half, centre + half) ? 1 : 0;
  }
  return World(g, std::move(solid), world.name());
}

BeaconOptions default_beacons(const GridGeometry& g) {
  constexpr double kInsetM = 0.2;
  constexpr double kCeilingM = 2.5;
  const Vec2 lo = g.origin() + Vec2{kInsetM, kInsetM};
  const Vec2 hi = g.origin() + Vec2{g.width() * g.resolution_m() - kInsetM,
                                    g.height() * g.resolution_m() - kInsetM};
  BeaconOptions b;
  b.beacons = {{{lo.x, lo.y, kCeilingM}, {hi.x, lo.y, kCeilingM}, {lo.x, hi.y, kCeilingM}}};
  return b;
}

/// The explorer in this process, in the robot's fixed buffers.
class LocalExplorerPort final : public BobExplorerPort {
 public:
  Result<bob::Status> begin(const bob::ExplorerOptions& options, int width, int height) override {
    return explorer_.init(options, buffers_->map.data(), buffers_->map.size(),
                          buffers_->final_map.data(), buffers_->final_map.size(), width, height);
  }
  Result<bob::Status> report(const StepSensing& s) override {
    // kOutOfBounds past the grid's edge: ignored.
    for (const CellDetection* d : {&s.left, &s.front, &s.right}) {
      if (d->seen) (void)explorer_.report_target(to_grid(d->cell), d->occupied);
    }
    for (const Cell c : s.also_occupied) (void)explorer_.report_detection(to_grid(c));
    return bob::Status::kOk;
  }
  Result<bob::Status> start(Cell cell) override {
    return explorer_.start(to_grid(cell), bob::Direction::kNorth);
  }
  Result<bob::Status> next_move(bob::Direction& move) override {
    return explorer_.next_move(move);
  }
  Result<bob::Status> blocked() override { return explorer_.blocked(); }
  Result<BobExplorerSummary> snapshot() override { return summary(); }
  Result<BobExplorerSummary> summary() override {
    BobExplorerSummary out;
    out.stop_reason = explorer_.stop_reason();
    out.moves = explorer_.moves();
    out.turns = explorer_.turns();
    out.resensed = explorer_.resensed();
    out.ignored_readings = explorer_.ignored_readings();
    const bob::PackedMap& map = explorer_.map();
    const bob::FinalMap& final_map = explorer_.final_map();
    out.packed_map.assign(map.data(), map.data() + map.memory_bytes());
    out.final_map.assign(final_map.data(), final_map.data() + final_map.memory_bytes());
    return out;
  }

 private:
  std::unique_ptr<RobotBuffers> buffers_ = std::make_unique<RobotBuffers>();
  bob::Explorer explorer_;
};

}  // namespace

const char* bob_variant_name(BobVariant v) {
  return v == BobVariant::kTrail ? "trail" : "map-aware";
}

Result<BobResult> run_bob(const World& world, const BobMissionOptions& options) {
  LocalExplorerPort port;
  return run_bob(world, options, port);
}

Result<BobResult> run_bob(const World& world, const BobMissionOptions& options,
                          BobExplorerPort& explorer) {
  if (!(options.cell_m > 0.0)) return usage_error("cell_m: must be > 0");
  BobSensingOptions sensing;
  sensing.layout.cell_m = options.cell_m;
  sensing.layout.robot_length_m = options.robot_length_m;
  sensing.layout.robot_width_m = options.robot_width_m;
  sensing.samples_per_move = options.samples_per_move;
  sensing.edge_tolerance_m = options.boundary_tolerance_m;
  internal::BobBodyOptions body_options;
  // Noise off: exact readings, motion and fixes (no encoder quantisation either).
  body_options.perfect = options.perfect_localisation || !options.noise;
  body_options.encoders = options.encoders;
  body_options.slip_detection_m = options.reposition_threshold_m;
  if (!options.noise) {
    body_options.slip_probability = 0.0;
    sensing.lateral = without_noise(sensing.lateral);
    sensing.front = without_noise(sensing.front);
    body_options.encoders.scale_error_stddev = 0.0;
    body_options.encoders.tick_noise_stddev = 0.0;
  }
  if (validate(sensing.layout)) {
    return input_error("cell " + metres_text(options.cell_m) + " m does not fit the robot (" +
                       metres_text(options.robot_length_m) + " x " +
                       metres_text(options.robot_width_m) + " m)");
  }
  // The robot's grid and the ground truth of each of its cells.
  const World truth = robot_grid_truth(world, options);
  const GridGeometry& g = truth.geometry();
  const long long n_cells = static_cast<long long>(g.width()) * g.height();
  if (n_cells > kMaxBobCells) {
    return input_error("world is " + std::to_string(g.width()) + " x " +
                       std::to_string(g.height()) + " = " + std::to_string(n_cells) +
                       " cells, more than the robot's buffers hold (" +
                       std::to_string(kMaxBobCells) + ")");
  }
  if (n_cells < 1) return input_error("world has no cells");
  body_options.beacons = options.beacons ? *options.beacons : default_beacons(g);
  if (!options.noise) {
    body_options.beacons.range_noise_stddev_m = 0.0;
    body_options.fix_stddev_m = 0.0;
  }
  if (auto problem = validate(sensing)) return usage_error(*problem);
  if (auto problem = validate(body_options.encoders)) return usage_error("encoders." + *problem);
  if (auto problem = validate(body_options.beacons)) return usage_error("beacons." + *problem);
  if (options.max_step_attempts < 1) return usage_error("max_step_attempts: must be >= 1");

  std::vector<Cell> candidates;
  if (options.start) {
    const Cell start = *options.start;
    if (!g.contains(start)) return input_error("start " + to_string(start) + " is outside the map");
    if (truth.solid(start)) {
      return input_error("start " + to_string(start) + " is inside an obstacle");
    }
    if (truth.solid(start + kNeighbors4[0])) {
      return input_error("start " + to_string(start) +
                         ": the cell in front must be free (BOBMapping 3.4)");
    }
    candidates.push_back(start);
  } else {
    candidates = start_candidates(truth);
    if (candidates.empty()) {
      return input_error("no free cell with a free cell in front (North) to start from");
    }
  }

  const bob::Backtrack backtrack = options.variant == BobVariant::kTrail
                                       ? bob::Backtrack::kTrail
                                       : bob::Backtrack::kShortestKnownPath;
  Rng rng(options.seed);
  // Placed by hand in a start cell facing North, the robot senses the three cells around it as if
  // it had just driven in from behind. Section 3.4 needs the front cell free: when the sensors
  // read it occupied (a wall just beyond it can mark it, errors falling on the safe side), a
  // default start moves on to the next candidate; a given start is refused.
  Cell start{};
  bob::Status started = bob::Status::kFrontBlocked;
  for (std::size_t k = 0; k < candidates.size() && started != bob::Status::kOk; ++k) {
    start = candidates[k];
    const Result<bob::Status> s =
        explorer.begin(bob::ExplorerOptions{backtrack, options.resense}, g.width(), g.height());
    if (!s) return s.error();
    if (*s != bob::Status::kOk) {
      return runtime_error(std::string("explorer init: ") + bob::status_name(*s));
    }
    const Cell behind = start - kNeighbors4[0];
    const Result<bob::Status> r = explorer.report(sense_cells_while_moving(
        with_free_cell(world, g, behind), g, centred_pose(g, behind, 0), sensing, rng));
    if (!r) return r.error();
    const Result<bob::Status> st = explorer.start(start);
    if (!st) return st.error();
    started = *st;
  }
  if (started != bob::Status::kOk) {
    if (options.start) {
      return input_error("start " + to_string(start) +
                         ": the cell in front must be free (BOBMapping 3.4), sensed " +
                         bob::status_name(started));
    }
    return input_error("no start cell whose front cell the sensors read free (BOBMapping 3.4)");
  }

  BobResult out;
  out.start = start;
  out.width = g.width();
  out.height = g.height();
  out.route.push_back(start);
  // The monitor's view of the run so far (BobMissionOptions::on_step).
  const auto notify = [&]() -> Status {
    if (!options.on_step) return Ok{};
    Result<BobExplorerSummary> now = explorer.snapshot();
    if (!now) return now.error();
    BobResult view;
    view.start = out.start;
    view.width = out.width;
    view.height = out.height;
    view.route = out.route;
    view.final_map = now->final_map;
    view.sensed.assign(g.size(), 0);
    std::vector<std::uint8_t> bytes(bob::PackedMap::bytes_needed(g.width(), g.height()));
    bob::PackedMap map;
    if (map.init(bytes.data(), bytes.size(), g.width(), g.height()) == bob::Status::kOk &&
        now->packed_map.size() == bytes.size()) {
      std::copy(now->packed_map.begin(), now->packed_map.end(), bytes.begin());
      for (std::size_t i = 0; i < g.size(); ++i) {
        view.sensed[i] = map.state(to_grid(g.cell_of(i))) != bob::CellState::kUnsensed ? 1 : 0;
      }
    }
    options.on_step(view);
    return Ok{};
  };
  if (Status s = notify(); !s) return s.error();

  internal::BobBody body(body_options, centred_pose(g, start, 0), rng);
  BobLocalisationStats& loc = out.localisation;
  double fix_error_sum_m = 0.0;
  int linear_since_fix = 0;
  const long long max_moves = kSafetyMovesPerCell * n_cells;
  Cell pos = start;
  bob::Direction heading = bob::Direction::kNorth;
  // Backwards to the believed centre of `cell_m`: turn so that the back faces it, reverse.
  const auto back_to = [&](Vec2 cell_m) {
    const Vec2 here_m = body.belief().translation();
    body.face(here_m + (here_m - cell_m), rng);
    body.drive(-(cell_m - here_m).norm(), rng);
  };
  // A beacon fix; false when it disagrees with odometry by more than the threshold.
  const auto take_fix = [&]() {
    const Vec2 true_m = body.truth().translation();
    loc.max_drift_m = std::max(loc.max_drift_m, (body.belief().translation() - true_m).norm());
    const std::optional<double> disagreement_m = body.fix(rng);
    if (!disagreement_m) {
      ++loc.failed_fixes;
      return true;
    }
    ++loc.fixes;
    fix_error_sum_m += (body.belief().translation() - true_m).norm();
    return *disagreement_m <= options.reposition_threshold_m;
  };
  Cell last_bumped{-1, -1};
  int bumps_in_a_row = 0;
  for (long long moves = 0;; ++moves) {
    if (moves > max_moves) {
      return runtime_error("the explorer did not stop within " + std::to_string(max_moves) +
                           " moves");
    }
    bob::Direction d{};
    const Result<bob::Status> s = explorer.next_move(d);
    if (!s) return s.error();
    if (*s == bob::Status::kFinished) break;
    if (*s != bob::Status::kOk) {
      return runtime_error(std::string("explorer: ") + bob::status_name(*s));
    }
    const Cell next = pos + kNeighbors4[static_cast<std::size_t>(static_cast<int>(d))];
    const Vec2 from_m = g.center_of(pos);
    const Vec2 to_m = g.center_of(next);
    // BOBMapping 3.3: "after two linear movements or after the linear movement following a
    // rotation" a fix; 3.4: on disagreement, back to the previous cell's centre and repeat.
    bool after_turn = d != heading;
    heading = d;
    StepSensing step;
    bool bumped = false;
    for (int attempt = 1;; ++attempt) {
      body.face(to_m, rng);
      const Pose2 true_start = body.truth();
      const Pose2 believed_start = body.belief();
      const double command_m = (to_m - believed_start.translation()).norm();
      // The motors stall where the body meets an obstacle (explorer.hpp, blocked()).
      const double free_m =
          free_travel(world, true_start, command_m, options.robot_length_m, options.robot_width_m);
      // A cell the robot has stood in stays free (3.4), so the explorer asks for the same move
      // again; after kMaxBumps tries the robot squeezes through (a collision, counted).
      const bool squeeze = next == last_bumped && bumps_in_a_row >= kMaxBumps;
      if (free_m < command_m && squeeze) ++loc.collisions;
      if (free_m < command_m && !squeeze) {
        body.drive(free_m, rng);
        bumped = true;
        break;
      }
      body.drive(command_m, rng);
      // The uncertainty at the end of the move bounds it over the move.
      const PoseUncertainty uncertainty{body.position_stddev_m(), body.heading_stddev_rad()};
      step =
          sense_cells_while_moving(world, g, true_start, believed_start, sensing, rng, uncertainty);
      ++linear_since_fix;
      if (options.perfect_localisation || (!after_turn && linear_since_fix < 2)) break;
      linear_since_fix = 0;
      if (take_fix()) break;
      if (attempt == options.max_step_attempts) {
        ++loc.unresolved_steps;
        break;
      }
      ++loc.repositionings;
      back_to(from_m);
      after_turn = true;  // the repeated step ends with a fix
    }
    if (bumped) {
      // Back to where it came from, the cell it could not enter marked occupied; a fix there.
      ++loc.bumps;
      bumps_in_a_row = next == last_bumped ? bumps_in_a_row + 1 : 1;
      last_bumped = next;
      back_to(from_m);
      const Result<bob::Status> b = explorer.blocked();
      if (!b) return b.error();
      if (*b != bob::Status::kOk) {
        return runtime_error(std::string("explorer: ") + bob::status_name(*b));
      }
      if (Status n = notify(); !n) return n.error();
      if (!options.perfect_localisation) {
        linear_since_fix = 0;
        (void)take_fix();
      }
      continue;
    }
    bumps_in_a_row = 0;
    if (const Result<bob::Status> r = explorer.report(step); !r) return r.error();
    const Pose2& t = body.truth();
    const Pose2& b = body.belief();
    loc.max_position_error_m =
        std::max(loc.max_position_error_m, (b.translation() - t.translation()).norm());
    loc.max_heading_error_rad =
        std::max(loc.max_heading_error_rad, std::abs(normalize_angle(b.theta - t.theta)));
    pos = next;
    out.route.push_back(pos);
    if (Status n = notify(); !n) return n.error();
  }
  if (loc.fixes > 0) loc.mean_fix_error_m = fix_error_sum_m / loc.fixes;
  Result<BobExplorerSummary> summary = explorer.summary();
  if (!summary) return summary.error();
  BobExplorerSummary& sum = *summary;
  out.stop_reason = sum.stop_reason;
  // The explorer kept the final map current in the robot's buffer.
  std::vector<std::uint8_t> packed_bytes(bob::PackedMap::bytes_needed(g.width(), g.height()));
  std::vector<std::uint8_t> final_bytes(bob::FinalMap::bytes_needed(g.width(), g.height()));
  if (sum.packed_map.size() != packed_bytes.size() || sum.final_map.size() != final_bytes.size()) {
    return runtime_error("explorer: the maps it returned are " +
                         std::to_string(sum.packed_map.size()) + " and " +
                         std::to_string(sum.final_map.size()) + " bytes, expected " +
                         std::to_string(packed_bytes.size()) + " and " +
                         std::to_string(final_bytes.size()));
  }
  bob::PackedMap map;
  bob::FinalMap final_map;
  (void)map.init(packed_bytes.data(), packed_bytes.size(), g.width(), g.height());
  (void)final_map.init(final_bytes.data(), final_bytes.size(), g.width(), g.height());
  std::copy(sum.packed_map.begin(), sum.packed_map.end(), packed_bytes.begin());
  std::copy(sum.final_map.begin(), sum.final_map.end(), final_bytes.begin());
  out.final_map = sum.final_map;

  // Table 1.
  BobTableRow& row = out.row;
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
    // What the user gets: the final map, in which a visited cell with an obstacle detected inside
    // is occupied (decision 0008).
    const bool occupied = final_map.occupied(to_grid(c));
    // Scored with a band of boundary_tolerance_m either side of the cell's edges (see
    // BobTableRow); the strict counts use the cell's own edges.
    const Vec2 centre = g.center_of(c);
    const Vec2 half{0.5 * options.cell_m, 0.5 * options.cell_m};
    const Vec2 band{options.boundary_tolerance_m, options.boundary_tolerance_m};
    if (occupied) {
      if (truth.free(c)) ++row.empty_as_occupied_strict;
      if (!world.any_solid_in(centre - half - band, centre + half + band)) {
        ++row.empty_as_occupied;
      }
    } else {
      if (truth.solid(c)) ++row.occupied_as_empty_strict;
      if (world.any_solid_in(centre - half + band, centre + half - band)) {
        ++row.occupied_as_empty;
      }
    }
  }
  row.resensed = static_cast<int>(sum.resensed);
  row.ignored_readings = static_cast<int>(sum.ignored_readings);
  row.path_cells = static_cast<int>(sum.moves);
  row.turns = static_cast<int>(sum.turns);
  row.success_rate =
      static_cast<double>(row.cells - row.empty_as_occupied - row.occupied_as_empty) / row.cells;
  row.success_rate_strict =
      static_cast<double>(row.cells - row.empty_as_occupied_strict - row.occupied_as_empty_strict) /
      row.cells;
  row.path_share = static_cast<double>(row.path_cells) / row.cells;
  row.visited_share = static_cast<double>(row.visited_cells) / row.cells;
  const std::vector<std::uint8_t> reachable = truth.reachable_from(start);
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
