// tessera gridmatch: one step of the lecture's grid-matching SLAM (slam/gridmatch.hpp) for a
// student to see: the map the robot made before it moved, what its sensor perceives after the move,
// every test pose's expected map with its similarity S, and the pose chosen. By default the
// lecture's own example ("Numerical example for a SLAM algorithm"): a robot near a corner with a
// pillar to its left moves one cell up, and its right wheel slips, so it is turned 15 degrees
// clockwise.
#include <fmt/format.h>

#include <cctype>
#include <chrono>
#include <cmath>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "tessera/core/angle.hpp"
#include "tessera/io/atomic_file.hpp"
#include "tessera/io/json_file.hpp"
#include "tessera/render/gridmatch_svg.hpp"
#include "tessera/report/core_report.hpp"
#include "tessera/sim/lidar_scan.hpp"
#include "tessera/slam/gridmatch.hpp"

namespace tessera::cli {
namespace {

constexpr const char* kLectureWorld = "lecture-corner";
constexpr double kLectureCellM = 0.3;

// The lecture's table (a.t): S per test pose, rows intended position, up, down, left, right one
// cell; columns intended orientation, 15 deg CW, 15 deg CCW.
constexpr int kLectureTable[5][3] = {
    {22, 32, 20}, {23, 25, 16}, {19, 28, 21}, {6, 7, 18}, {22, 18, 18}};
// Our candidate offsets in that layout.
constexpr slam::CandidateOffset kLectureRows[5] = {
    {0, 0, 0}, {0, 1, 0}, {0, -1, 0}, {-1, 0, 0}, {1, 0, 0}};
constexpr int kLectureColumns[3] = {0, -1, 1};

std::string offset_label(const slam::CandidateOffset& o, double heading_step_deg) {
  std::string where;
  if (o.dx_steps == 0 && o.dy_steps == 0) where = "intended position";
  if (o.dx_steps == 0 && o.dy_steps == 1) where = "up one cell";
  if (o.dx_steps == 0 && o.dy_steps == -1) where = "down one cell";
  if (o.dx_steps == -1 && o.dy_steps == 0) where = "left one cell";
  if (o.dx_steps == 1 && o.dy_steps == 0) where = "right one cell";
  if (where.empty()) where = fmt::format("{:+d}, {:+d} cells", o.dx_steps, o.dy_steps);
  if (o.dheading_steps == 0) return where;
  const double deg = std::abs(o.dheading_steps) * heading_step_deg;
  return fmt::format("{}, {:g} deg {}", where, deg, o.dheading_steps < 0 ? "CW" : "CCW");
}

int score_of(const slam::GridMatchResult& r, const slam::CandidateOffset& o) {
  for (const slam::GridMatchCandidate& c : r.candidates) {
    if (c.offset == o) return c.similarity.score;
  }
  return 0;
}

// The S table in the lecture's layout (the command's test poses are always the lecture's 5 x 3),
// with the lecture's numbers beside ours when the step is the lecture's example.
std::string similarity_markdown(const slam::GridMatchResult& r, bool lecture) {
  std::string md = "| | Intended orientation | 15 deg CW | 15 deg CCW |\n|---|---|---|---|\n";
  for (int row = 0; row < 5; ++row) {
    std::string name = offset_label(kLectureRows[row], 0.0);
    name[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(name[0])));
    md += fmt::format("| {} |", name);
    for (int col = 0; col < 3; ++col) {
      slam::CandidateOffset o = kLectureRows[row];
      o.dheading_steps = kLectureColumns[col];
      const bool best = r.winner().offset == o;
      md += fmt::format(" {}{}{}{} |", best ? "**" : "", score_of(r, o), best ? "**" : "",
                        lecture ? fmt::format(" (lecture {})", kLectureTable[row][col]) : "");
    }
    md += "\n";
  }
  return md;
}

}  // namespace

GridmatchCommand::GridmatchCommand(CLI::App& app) {
  sub_ = app.add_subcommand(
      "gridmatch",
      "One step of the lecture's grid-matching SLAM, drawn for a student: the map made before a "
      "move, the sensor's perception after it, every test pose's expected map with its "
      "similarity S, and the pose chosen. Default: the lecture's numerical example (a robot near a "
      "corner moves one cell up and is turned 15 deg clockwise). Writes gridmatch.svg, "
      "candidates/*.svg, similarity.md and report.json to --out");
  world_.builtin = kLectureWorld;
  add_world_options(*sub_, world_);
  sub_->add_option("--resolution-m", cell_m_,
                   "Cell size, about the robot's (the lecture's 0.3 m); a floor plan is resampled "
                   "to it")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  sub_->add_option("--before", before_,
                   "X,Y,THETA (m, m, rad) where the robot made its map (default: the lecture's, in "
                   "the lecture-corner world)");
  sub_->add_option("--odometry", odometry_,
                   "X,Y,THETA where odometry says the robot is after the move (default: one cell "
                   "ahead of --before)");
  sub_->add_option("--actual", actual_,
                   "X,Y,THETA where the robot really is (default: --odometry turned 15 deg "
                   "clockwise, as the lecture's slipping wheel turns it)");
  sub_->add_option("--range-cells", range_cells_, "Sensor range in cells (the lecture: 5)")
      ->check(CLI::Range(1, 50))
      ->capture_default_str();
  sub_->add_option("--out", out_, "Output folder")->capture_default_str();
  sub_->add_flag("--quiet", quiet_, "No summary");
}

int GridmatchCommand::run() const {
  const bool lecture_world = !world_.file && world_.builtin == kLectureWorld;
  if (!before_ && !lecture_world) {
    return report_error(usage_error("--before is needed outside the lecture-corner world"));
  }
  Result<World> world = load_world(world_, cell_m_);
  if (!world) return report_error(world.error());
  // The lecture's cells are about the robot's size: a floor plan is resampled to them (a coarse
  // cell is solid when any of its fine cells is).
  if (std::abs(world->geometry().resolution_m() - cell_m_) > 1e-9) {
    world = world->resampled(cell_m_);
  }
  const double cell_m = cell_m_;
  Pose2 before{3.5 * kLectureCellM, 3.5 * kLectureCellM, 0.5 * std::numbers::pi};
  if (before_) {
    Result<Pose2> p = parse_pose(*before_, "--before");
    if (!p) return report_error(p.error());
    before = *p;
  }
  Pose2 odometry = before * Pose2{cell_m, 0.0, 0.0};
  if (odometry_) {
    Result<Pose2> p = parse_pose(*odometry_, "--odometry");
    if (!p) return report_error(p.error());
    odometry = *p;
  }
  Pose2 actual = odometry * Pose2{0.0, 0.0, -deg_to_rad(15.0)};
  if (actual_) {
    Result<Pose2> p = parse_pose(*actual_, "--actual");
    if (!p) return report_error(p.error());
    actual = *p;
  }
  for (const auto& [name, pose] : {std::pair{"--before", before}, std::pair{"--actual", actual}}) {
    if (world->solid(world->geometry().cell_at_unchecked(pose.translation()))) {
      return report_error(usage_error(fmt::format("{} {:.2f},{:.2f} is not in free space of {}",
                                                  name, pose.x, pose.y, world->name())));
    }
  }
  const bool lecture = lecture_world && !before_ && !odometry_ && !actual_ &&
                       std::abs(cell_m - kLectureCellM) < 1e-9 && range_cells_ == 5;

  // The lecture's sensor: walls up to range_cells cells away, no noise.
  const auto t0 = std::chrono::steady_clock::now();
  LidarOptions lidar;
  lidar.max_range_m = range_cells_ * cell_m;
  lidar.range_noise_stddev_m = 0.0;
  Rng unused(1);
  OccupancyGrid map(world->geometry());
  (void)slam::update_map(
      map,
      slam::perception_from_scan(simulate_lidar_scan(*world, before, lidar, unused),
                                 slam::robot_window(cell_m, lidar.max_range_m)),
      before);
  // The lecture's 8 x 5 maps: 2 cells behind, range_cells ahead, 2 to each side.
  const slam::TernaryGrid perception =
      slam::perception_from_scan(simulate_lidar_scan(*world, actual, lidar, unused),
                                 slam::robot_window(cell_m, 2, range_cells_, 2));
  const slam::GridMatchOptions options;
  const slam::GridMatchResult r = slam::match(map, perception, odometry, options);
  const double wall_s = seconds_since(t0);

  GridMatchStep step{&map, &perception, &r, {}};
  for (const slam::GridMatchCandidate& c : r.candidates) {
    step.labels.push_back(offset_label(c.offset, rad_to_deg(options.heading_step_rad)));
  }
  nlohmann::json candidates = nlohmann::json::array();
  for (std::size_t k = 0; k < r.candidates.size(); ++k) {
    const slam::GridMatchCandidate& c = r.candidates[k];
    candidates.push_back({{"label", step.labels[k]},
                          {"dx_steps", c.offset.dx_steps},
                          {"dy_steps", c.offset.dy_steps},
                          {"dheading_steps", c.offset.dheading_steps},
                          {"pose", {c.T_map_robot.x, c.T_map_robot.y, c.T_map_robot.theta}},
                          {"similarity", c.similarity.score},
                          {"overlap_cells", c.similarity.overlap_cells},
                          {"agree_cells", c.similarity.agree_cells}});
  }
  const nlohmann::json options_json = {{"world", world->name()},
                                       {"resolution_m", cell_m},
                                       {"before", {before.x, before.y, before.theta}},
                                       {"odometry", {odometry.x, odometry.y, odometry.theta}},
                                       {"actual", {actual.x, actual.y, actual.theta}},
                                       {"range_cells", range_cells_}};
  nlohmann::json report = core_report({"gridmatch", std::nullopt, options_json, wall_s, {}});
  const Pose2 error = between(actual, r.T_map_robot());
  report["gridmatch"] = {{"candidates", candidates},
                         {"best", r.best},
                         {"margin", r.margin},
                         {"chosen", step.labels[r.best]},
                         {"error_m", std::hypot(error.x, error.y)},
                         {"error_rad", std::abs(normalize_angle(error.theta))}};
  if (lecture) report["gridmatch"]["lecture_table"] = kLectureTable;

  // The files' bytes first: PendingFile only views them.
  const std::string table = similarity_markdown(r, lecture);
  std::vector<std::pair<std::filesystem::path, std::string>> contents{
      {out_ / "gridmatch.svg", gridmatch_sheet_svg(step)},
      {out_ / "report.json", encode_json(report)},
      {out_ / "similarity.md", table}};
  for (std::size_t k = 0; k < r.candidates.size(); ++k) {
    const slam::CandidateOffset& o = r.candidates[k].offset;
    contents.emplace_back(out_ / "candidates" /
                              fmt::format("{:02d}_dx{:+d}_dy{:+d}_turn{:+d}.svg", k, o.dx_steps,
                                          o.dy_steps, o.dheading_steps),
                          gridmatch_candidate_svg(step, k));
  }
  std::vector<PendingFile> files;
  for (const auto& [path, bytes] : contents) files.push_back({path, bytes});
  if (Status s = ensure_directory(out_ / "candidates"); !s) return report_error(s.error());
  if (Status s = write_files_atomic(files); !s) return report_error(s.error());
  if (!quiet_) {
    fmt::print("{}", table);
    fmt::print(
        "chosen: {} (S = {}, {} ahead of the next), {:.3f} m and {:.1f} deg from the actual "
        "pose\noutputs: {}/gridmatch.svg candidates/ similarity.md report.json\n",
        step.labels[r.best], r.winner().similarity.score, r.margin, std::hypot(error.x, error.y),
        rad_to_deg(std::abs(normalize_angle(error.theta))), out_.string());
  }
  return kExitOk;
}

}  // namespace tessera::cli
