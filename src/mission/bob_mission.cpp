#include "tessera/mission/bob_mission.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "internal/bob_body.hpp"
#include "tessera/sim/bob_explorer_port.hpp"
#include "tessera/bob/final_map.hpp"
#include "tessera/bob/packed_map.hpp"
#include "tessera/core/angle.hpp"
#include "tessera/core/assert.hpp"

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


/// The sensing and body options a run derives from BobMissionOptions (noise off: exact readings,
/// motion and fixes, no encoder quantisation either).
struct BobSetup {
  BobSensingOptions sensing;
  internal::BobBodyOptions body;
};

BobSetup bob_setup(const BobMissionOptions& options, const GridGeometry& g) {
  BobSetup s;
  s.sensing.layout.cell_m = options.cell_m;
  s.sensing.layout.robot_length_m = options.robot_length_m;
  s.sensing.layout.robot_width_m = options.robot_width_m;
  s.sensing.samples_per_move = options.samples_per_move;
  s.sensing.edge_tolerance_m = options.boundary_tolerance_m;
  s.body.perfect = options.perfect_localisation || !options.noise;
  s.body.encoders = options.encoders;
  s.body.slip_detection_m = options.reposition_threshold_m;
  s.body.beacons = options.beacons ? *options.beacons : default_beacons(g);
  if (!options.noise) {
    s.body.slip_probability = 0.0;
    s.sensing.lateral = without_noise(s.sensing.lateral);
    s.sensing.front = without_noise(s.sensing.front);
    s.body.encoders.scale_error_stddev = 0.0;
    s.body.encoders.tick_noise_stddev = 0.0;
    s.body.beacons.range_noise_stddev_m = 0.0;
    s.body.fix_stddev_m = 0.0;
  }
  return s;
}

/// Errors of BobMission::create that the options and the grid alone decide.
Status check_setup(const BobMissionOptions& options, const GridGeometry& g, const BobSetup& s) {
  if (validate(s.sensing.layout)) {
    return input_error("cell " + metres_text(options.cell_m) + " m does not fit the robot (" +
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
  if (auto problem = validate(s.sensing)) return usage_error(*problem);
  if (auto problem = validate(s.body.encoders)) return usage_error("encoders." + *problem);
  if (auto problem = validate(s.body.beacons)) return usage_error("beacons." + *problem);
  if (options.max_step_attempts < 1) return usage_error("max_step_attempts: must be >= 1");
  return Ok{};
}

/// options.start, checked, or the default candidates in order of preference.
Result<std::vector<Cell>> bob_start_cells(const World& truth, const BobMissionOptions& options) {
  const GridGeometry& g = truth.geometry();
  if (!options.start) {
    std::vector<Cell> candidates = start_candidates(truth);
    if (candidates.empty()) {
      return input_error("no free cell with a free cell in front (North) to start from");
    }
    return candidates;
  }
  const Cell start = *options.start;
  if (!g.contains(start)) return input_error("start " + to_string(start) + " is outside the map");
  if (truth.solid(start)) return input_error("start " + to_string(start) + " is inside an obstacle");
  if (truth.solid(start + kNeighbors4[0])) {
    return input_error("start " + to_string(start) +
                       ": the cell in front must be free (BOBMapping 3.4)");
  }
  return std::vector<Cell>{start};
}

/// Status of an explorer call that must be kOk.
Status expect_ok(const Result<bob::Status>& s, const char* what) {
  if (!s) return s.error();
  if (*s != bob::Status::kOk) return runtime_error(std::string(what) + bob::status_name(*s));
  return Ok{};
}

/// The grid's cells as the user gets them: sensed, and occupied in the final map (decision 0008).
/// A map of the wrong size (a snapshot a link has not filled yet) leaves its cells 0.
void fill_cells(const BobExplorerSummary& sum, const GridGeometry& g, BobResult& out) {
  out.sensed.assign(g.size(), 0);
  out.occupied.assign(g.size(), 0);
  std::vector<std::uint8_t> bytes(bob::PackedMap::bytes_needed(g.width(), g.height()));
  bob::PackedMap map;
  if (map.init(bytes.data(), bytes.size(), g.width(), g.height()) == bob::Status::kOk &&
      sum.packed_map.size() == bytes.size()) {
    std::copy(sum.packed_map.begin(), sum.packed_map.end(), bytes.begin());
    for (std::size_t i = 0; i < g.size(); ++i) {
      out.sensed[i] = map.state(to_grid(g.cell_of(i))) != bob::CellState::kUnsensed ? 1 : 0;
    }
  }
  std::vector<std::uint8_t> final_bytes(bob::FinalMap::bytes_needed(g.width(), g.height()));
  bob::FinalMap final_map;
  if (final_map.init(final_bytes.data(), final_bytes.size(), g.width(), g.height()) ==
          bob::Status::kOk &&
      sum.final_map.size() == final_bytes.size()) {
    std::copy(sum.final_map.begin(), sum.final_map.end(), final_bytes.begin());
    for (std::size_t i = 0; i < g.size(); ++i) {
      out.occupied[i] = final_map.occupied(to_grid(g.cell_of(i))) ? 1 : 0;
    }
  }
}

/// kRuntime unless the explorer's maps have the grid's sizes.
Status check_map_sizes(const BobExplorerSummary& sum, const GridGeometry& g) {
  const std::size_t packed = bob::PackedMap::bytes_needed(g.width(), g.height());
  const std::size_t final_bytes = bob::FinalMap::bytes_needed(g.width(), g.height());
  if (sum.packed_map.size() == packed && sum.final_map.size() == final_bytes) return Ok{};
  return runtime_error("explorer: the maps it returned are " +
                       std::to_string(sum.packed_map.size()) + " and " +
                       std::to_string(sum.final_map.size()) + " bytes, expected " +
                       std::to_string(packed) + " and " + std::to_string(final_bytes));
}

}  // namespace

const char* bob_variant_name(BobVariant v) {
  return v == BobVariant::kTrail ? "trail" : "map-aware";
}

Result<World> bob_grid_truth(const World& world, const BobMissionOptions& options) {
  if (!(options.cell_m > 0.0)) return usage_error("cell_m: must be > 0");
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

std::unique_ptr<BobExplorerPort> local_bob_explorer() {
  return std::make_unique<LocalExplorerPort>();
}

struct BobMission::State {
  const World* world = nullptr;
  const World* truth = nullptr;
  BobMissionOptions options;
  BobExplorerPort* explorer = nullptr;
  BobSetup setup;
  GridGeometry g;
  Rng rng{1};
  std::optional<internal::BobBody> body;
  std::vector<Cell> route;
  Cell start;
  Cell pos;
  bob::Direction heading = bob::Direction::kNorth;
  BobLocalisationStats loc;
  double fix_error_sum_m = 0.0;
  int linear_since_fix = 0;
  long long moves = 0;  // step() calls that asked the explorer
  long long max_moves = 0;
  Cell last_bumped{-1, -1};
  int bumps_in_a_row = 0;
  bool finished = false;

  Status place(const std::vector<Cell>& candidates);
  bool take_fix();
  void back_to(Vec2 cell_m);
  bool drive(Cell next, bool after_turn, StepSensing& seen);
  Status bumped(Cell next);
  Status entered(Cell next, const StepSensing& seen);
};

/// Placed by hand in a start cell facing North, the robot senses the three cells around it as if
/// it had just driven in from behind. Section 3.4 needs the front cell free: when the sensors read
/// it occupied (a wall just beyond it can mark it, errors falling on the safe side), a default
/// start moves on to the next candidate; a given start is refused.
Status BobMission::State::place(const std::vector<Cell>& candidates) {
  const bob::Backtrack backtrack = options.variant == BobVariant::kTrail
                                       ? bob::Backtrack::kTrail
                                       : bob::Backtrack::kShortestKnownPath;
  bob::Status started = bob::Status::kFrontBlocked;
  for (std::size_t k = 0; k < candidates.size() && started != bob::Status::kOk; ++k) {
    start = candidates[k];
    const Result<bob::Status> s =
        explorer->begin(bob::ExplorerOptions{backtrack, options.resense}, g.width(), g.height());
    if (Status ok = expect_ok(s, "explorer init: "); !ok) return ok;
    const Cell behind = start - kNeighbors4[0];
    const Result<bob::Status> r = explorer->report(sense_cells_while_moving(
        with_free_cell(*world, g, behind), g, centred_pose(g, behind, 0), setup.sensing, rng));
    if (!r) return r.error();
    const Result<bob::Status> st = explorer->start(start);
    if (!st) return st.error();
    started = *st;
  }
  if (started == bob::Status::kOk) return Ok{};
  if (options.start) {
    return input_error("start " + to_string(start) +
                       ": the cell in front must be free (BOBMapping 3.4), sensed " +
                       bob::status_name(started));
  }
  return input_error("no start cell whose front cell the sensors read free (BOBMapping 3.4)");
}

/// A beacon fix; false when it disagrees with odometry by more than the threshold.
bool BobMission::State::take_fix() {
  const Vec2 true_m = body->truth().translation();
  loc.max_drift_m = std::max(loc.max_drift_m, (body->belief().translation() - true_m).norm());
  const std::optional<double> disagreement_m = body->fix(rng);
  if (!disagreement_m) {
    ++loc.failed_fixes;
    return true;
  }
  ++loc.fixes;
  fix_error_sum_m += (body->belief().translation() - true_m).norm();
  return *disagreement_m <= options.reposition_threshold_m;
}

/// Backwards to the believed centre of `cell_m`: turn so that the back faces it, reverse.
void BobMission::State::back_to(Vec2 cell_m) {
  const Vec2 here_m = body->belief().translation();
  body->face(here_m + (here_m - cell_m), rng);
  body->drive(-(cell_m - here_m).norm(), rng);
}

/// Drives from pos to the centre of `next`; true when the body met an obstacle on the way (it
/// stopped there). BOBMapping 3.3: "after two linear movements or after the linear movement
/// following a rotation" a fix; 3.4: on disagreement, back to the previous cell's centre and
/// repeat the step, sensing again (the readings of the rejected step are discarded).
bool BobMission::State::drive(Cell next, bool after_turn, StepSensing& seen) {
  const Vec2 from_m = g.center_of(pos);
  const Vec2 to_m = g.center_of(next);
  for (int attempt = 1;; ++attempt) {
    body->face(to_m, rng);
    const Pose2 true_start = body->truth();
    const Pose2 believed_start = body->belief();
    const double command_m = (to_m - believed_start.translation()).norm();
    // The motors stall where the body meets an obstacle (explorer.hpp, blocked()).
    const double free_m =
        free_travel(*world, true_start, command_m, options.robot_length_m, options.robot_width_m);
    // A cell the robot has stood in stays free (3.4), so the explorer asks for the same move
    // again; after kMaxBumps tries the robot squeezes through (a collision, counted).
    const bool squeeze = next == last_bumped && bumps_in_a_row >= kMaxBumps;
    if (free_m < command_m && squeeze) ++loc.collisions;
    if (free_m < command_m && !squeeze) {
      body->drive(free_m, rng);
      return true;
    }
    body->drive(command_m, rng);
    // The uncertainty at the end of the move bounds it over the move.
    const PoseUncertainty uncertainty{body->position_stddev_m(), body->heading_stddev_rad()};
    seen = sense_cells_while_moving(*world, g, true_start, believed_start, setup.sensing, rng,
                                    uncertainty);
    ++linear_since_fix;
    if (options.perfect_localisation || (!after_turn && linear_since_fix < 2)) return false;
    linear_since_fix = 0;
    if (take_fix()) return false;
    if (attempt == options.max_step_attempts) {
      ++loc.unresolved_steps;
      return false;
    }
    ++loc.repositionings;
    back_to(from_m);
    after_turn = true;  // the repeated step ends with a fix
  }
}

/// Back to where it came from, the cell it could not enter marked occupied; a fix there.
Status BobMission::State::bumped(Cell next) {
  ++loc.bumps;
  bumps_in_a_row = next == last_bumped ? bumps_in_a_row + 1 : 1;
  last_bumped = next;
  back_to(g.center_of(pos));
  if (Status ok = expect_ok(explorer->blocked(), "explorer: "); !ok) return ok;
  if (!options.perfect_localisation) {
    linear_since_fix = 0;
    (void)take_fix();
  }
  return Ok{};
}

Status BobMission::State::entered(Cell next, const StepSensing& seen) {
  bumps_in_a_row = 0;
  if (const Result<bob::Status> r = explorer->report(seen); !r) return r.error();
  const Pose2& t = body->truth();
  const Pose2& b = body->belief();
  loc.max_position_error_m =
      std::max(loc.max_position_error_m, (b.translation() - t.translation()).norm());
  loc.max_heading_error_rad =
      std::max(loc.max_heading_error_rad, std::abs(normalize_angle(b.theta - t.theta)));
  pos = next;
  route.push_back(pos);
  return Ok{};
}

Result<BobMission> BobMission::create(const World& world, const World& grid_truth,
                                      const BobMissionOptions& options,
                                      BobExplorerPort& explorer) {
  auto s = std::make_unique<State>();
  s->world = &world;
  s->truth = &grid_truth;
  s->options = options;
  s->options.on_step = nullptr;  // run_bob's, not the mission's
  s->explorer = &explorer;
  s->g = grid_truth.geometry();
  s->setup = bob_setup(options, s->g);
  if (Status ok = check_setup(options, s->g, s->setup); !ok) return ok.error();
  Result<std::vector<Cell>> candidates = bob_start_cells(grid_truth, options);
  if (!candidates) return candidates.error();
  s->rng = Rng(options.seed);
  if (Status ok = s->place(*candidates); !ok) return ok.error();
  s->body.emplace(s->setup.body, centred_pose(s->g, s->start, 0), s->rng);
  s->pos = s->start;
  s->route.push_back(s->start);
  s->max_moves = kSafetyMovesPerCell * static_cast<long long>(s->g.size());
  return BobMission(std::move(s));
}

BobMission::BobMission(std::unique_ptr<State> state) : s_(std::move(state)) {}
BobMission::BobMission(BobMission&&) noexcept = default;
BobMission& BobMission::operator=(BobMission&&) noexcept = default;
BobMission::~BobMission() = default;

Status BobMission::step() {
  State& s = *s_;
  if (s.finished) return Ok{};
  if (s.moves > s.max_moves) {
    return runtime_error("the explorer did not stop within " + std::to_string(s.max_moves) +
                         " moves");
  }
  ++s.moves;
  bob::Direction d{};
  const Result<bob::Status> st = s.explorer->next_move(d);
  if (!st) return st.error();
  if (*st == bob::Status::kFinished) {
    s.finished = true;
    return Ok{};
  }
  if (*st != bob::Status::kOk) {
    return runtime_error(std::string("explorer: ") + bob::status_name(*st));
  }
  const Cell next = s.pos + kNeighbors4[static_cast<std::size_t>(static_cast<int>(d))];
  const bool after_turn = d != s.heading;
  s.heading = d;
  StepSensing seen;
  if (s.drive(next, after_turn, seen)) return s.bumped(next);
  return s.entered(next, seen);
}

bool BobMission::finished() const { return s_->finished; }
const GridGeometry& BobMission::grid() const { return s_->g; }
Cell BobMission::start() const { return s_->start; }
const std::vector<Cell>& BobMission::route() const { return s_->route; }
Pose2 BobMission::true_pose() const { return s_->body->truth(); }
Pose2 BobMission::believed_pose() const { return s_->body->belief(); }

BobLocalisationStats BobMission::localisation() const {
  BobLocalisationStats loc = s_->loc;
  if (loc.fixes > 0) loc.mean_fix_error_m = s_->fix_error_sum_m / loc.fixes;
  return loc;
}

Result<BobResult> BobMission::snapshot() {
  const State& s = *s_;
  Result<BobExplorerSummary> now = s.explorer->snapshot();
  if (!now) return now.error();
  BobResult view;
  view.start = s.start;
  view.width = s.g.width();
  view.height = s.g.height();
  view.route = s.route;
  view.final_map = now->final_map;
  fill_cells(*now, s.g, view);
  return view;
}

Result<BobResult> BobMission::result() {
  TESSERA_ASSERT(finished());
  const State& s = *s_;
  Result<BobExplorerSummary> summary = s.explorer->summary();
  if (!summary) return summary.error();
  const BobExplorerSummary& sum = *summary;
  if (Status ok = check_map_sizes(sum, s.g); !ok) return ok.error();
  BobResult out;
  out.route = s.route;
  out.width = s.g.width();
  out.height = s.g.height();
  out.start = s.start;
  out.final_map = sum.final_map;
  fill_cells(sum, s.g, out);
  out.moves = static_cast<int>(sum.moves);
  out.turns = static_cast<int>(sum.turns);
  out.resensed = static_cast<int>(sum.resensed);
  out.ignored_readings = static_cast<int>(sum.ignored_readings);
  out.localisation = localisation();
  out.stop_reason = sum.stop_reason;
  return out;
}

namespace {

Status notify(BobMission& mission, const BobMissionOptions& options) {
  if (!options.on_step) return Ok{};
  Result<BobResult> view = mission.snapshot();
  if (!view) return view.error();
  options.on_step(*view);
  return Ok{};
}

}  // namespace

Result<BobResult> run_bob(const World& world, const World& grid_truth,
                          const BobMissionOptions& options, BobExplorerPort& explorer) {
  Result<BobMission> mission = BobMission::create(world, grid_truth, options, explorer);
  if (!mission) return mission.error();
  if (Status n = notify(*mission, options); !n) return n.error();
  while (!mission->finished()) {
    if (Status s = mission->step(); !s) return s.error();
    if (mission->finished()) break;
    if (Status n = notify(*mission, options); !n) return n.error();
  }
  return mission->result();
}

Result<BobResult> run_bob(const World& world, const BobMissionOptions& options) {
  Result<World> truth = bob_grid_truth(world, options);
  if (!truth) return truth.error();
  const std::unique_ptr<BobExplorerPort> explorer = local_bob_explorer();
  return run_bob(world, *truth, options, *explorer);
}

}  // namespace tessera
