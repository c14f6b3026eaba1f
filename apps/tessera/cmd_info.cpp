#include <fmt/format.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "tessera/io/map_file.hpp"
#include "tessera/io/robot_bag.hpp"
#include "tessera/io/ros_bag.hpp"
#include "tessera/io/session_file.hpp"

namespace tessera::cli {

InfoCommand::InfoCommand(CLI::App& app) {
  sub_ =
      app.add_subcommand("info",
                         "Describe a map file (format, size, resolution, cell counts), a ROS "
                         "bag (topics, types, message counts, rates, duration, and per laser "
                         "scan topic what `slam --bag` takes from it) or a saved session (.tsm)");
  sub_->add_option("file", file_,
                   "Map file (any format tessera reads), ROS bag (.bag, .db3, .mcap or a "
                   "rosbag2 folder) or session (.tsm)")
      ->required();
  sub_->add_option("--map-resolution-m", map_resolution_m_,
                   "Cell size for map files that carry none (images, Moving AI)");
  sub_->add_flag("--json", json_, "Print JSON instead of text");
}

namespace {

/// What `slam --bag --scan-topic TOPIC` would take from the bag (io/robot_bag.hpp): the laser
/// and robot frames, the laser's pose on the robot, and where the odometry comes from; or why
/// it cannot (no odometry, no tf chain to the laser).
nlohmann::json laser_reading(const RosBag& bag, const std::string& file, const std::string& topic) {
  RobotBagOptions options;
  options.scan_topic = topic;
  Result<RobotBag> r = robot_bag_from(bag, file, options);
  if (!r) return {{"topic", topic}, {"error", r.error().message}};
  const Pose2 T = r->log.scans.front().laser_in_robot;
  return {{"topic", topic},
          {"scans", r->log.scans.size()},
          {"laser_frame", r->laser_frame},
          {"base_frame", r->base_frame},
          {"laser_in_robot_m_rad", {T.x, T.y, T.theta}},
          {"odom_topic", r->odom_topic},
          {"odom_frame", r->odom_frame}};
}

}  // namespace

/// Like `ros2 bag info`: the storage, the span, and per topic its type, count and rate; then per
/// LaserScan topic what `slam --bag` would take from it.
int InfoCommand::run_bag() const {
  BagReadOptions keep;
  keep.keep = robot_bag_needs;
  Result<RosBag> read = read_ros_bag(file_, keep);
  if (!read) return report_error(read.error());
  const RosBag& bag = *read;
  nlohmann::json lasers = nlohmann::json::array();
  for (const BagTopic& t : bag.topics) {
    if (is_laser_scan_type(t.type)) {
      lasers.push_back(laser_reading(bag, file_.string(), t.name));
    }
  }
  nlohmann::json topics = nlohmann::json::array();
  for (const BagTopic& t : bag.topics) {
    topics.push_back({{"name", t.name},
                      {"type", t.type},
                      {"serialization", t.serialization},
                      {"message_count", t.message_count},
                      {"rate_hz", t.rate_hz()},
                      {"first_s", 1e-9 * static_cast<double>(t.first_ns)},
                      {"last_s", 1e-9 * static_cast<double>(t.last_ns)}});
  }
  nlohmann::json files = nlohmann::json::array();
  for (const auto& f : bag.files) files.push_back(f.string());
  const nlohmann::json j = {{"file", file_.string()},
                            {"format", bag.format},
                            {"files", files},
                            {"message_count", bag.message_count()},
                            {"start_s", 1e-9 * static_cast<double>(bag.start_ns())},
                            {"end_s", 1e-9 * static_cast<double>(bag.end_ns())},
                            {"duration_s", bag.duration_s()},
                            {"topics", topics},
                            {"laser_scans", lasers}};
  if (json_) {
    fmt::print("{}\n", j.dump(2));
    return kExitOk;
  }
  fmt::print("{}: {}\n", file_.string(), bag.format);
  fmt::print("  duration    {:.3f} s (start {:.3f} s, end {:.3f} s)\n", bag.duration_s(),
             1e-9 * static_cast<double>(bag.start_ns()), 1e-9 * static_cast<double>(bag.end_ns()));
  fmt::print("  messages    {} on {} topics\n", bag.message_count(), bag.topics.size());
  std::size_t name_w = 5, type_w = 4;
  for (const BagTopic& t : bag.topics) {
    name_w = std::max(name_w, t.name.size());
    type_w = std::max(type_w, t.type.size());
  }
  fmt::print("  {:<{}}  {:<{}}  {:>8}  {:>8}  {}\n", "topic", name_w, "type", type_w, "count",
             "rate_hz", "serialization");
  for (const BagTopic& t : bag.topics) {
    fmt::print("  {:<{}}  {:<{}}  {:>8}  {:>8.2f}  {}\n", t.name, name_w, t.type, type_w,
               t.message_count, t.rate_hz(), t.serialization);
  }
  for (const nlohmann::json& l : lasers) {
    if (l.contains("error")) {
      fmt::print("  slam --bag --scan-topic {}: {}\n", l["topic"].get<std::string>(),
                 l["error"].get<std::string>());
      continue;
    }
    const auto& T = l["laser_in_robot_m_rad"];
    const std::string odometry =
        l["odom_topic"].get<std::string>().empty()
            ? std::string("no odometry (the scans alone are matched)")
            : fmt::format("odometry from {} ({} -> {})", l["odom_topic"].get<std::string>(),
                          l["odom_frame"].get<std::string>(), l["base_frame"].get<std::string>());
    fmt::print(
        "  slam --bag --scan-topic {}: {} scans from {} at ({:.3f} m, {:.3f} m, {:.3f} rad) "
        "in {}, {}\n",
        l["topic"].get<std::string>(), l["scans"].get<std::size_t>(),
        l["laser_frame"].get<std::string>(), T[0].get<double>(), T[1].get<double>(),
        T[2].get<double>(), l["base_frame"].get<std::string>(), odometry);
  }
  return kExitOk;
}

int InfoCommand::run() const {
  if (is_ros_bag_path(file_)) return run_bag();
  if (is_session_path(file_)) return run_session();
  MapLoadOptions load_options;
  load_options.resolution_m = map_resolution_m_;
  Result<LoadedMap> loaded = load_map(file_, load_options);
  if (!loaded) return report_error(loaded.error());
  const OccupancyGrid& map = loaded->map;
  const GridGeometry& g = map.geometry();

  const CellCounts counts = map.count_states();
  const World world = World::from_map(map);
  const std::size_t packed_bytes =
      static_cast<std::size_t>((g.width() + 7) / 8) * static_cast<std::size_t>(g.height());

  nlohmann::json j = {{"file", file_.string()},
                      {"format", loaded->format},
                      {"width_cells", g.width()},
                      {"height_cells", g.height()},
                      {"resolution_m", g.resolution_m()},
                      {"origin_m", {g.origin().x, g.origin().y}},
                      {"extent_m", {g.width() * g.resolution_m(), g.height() * g.resolution_m()}},
                      {"free_cells", counts.free},
                      {"occupied_cells", counts.occupied},
                      {"unknown_cells", counts.unknown},
                      {"memory_bytes_occupancy_grid", map.memory_bytes()},
                      {"memory_bytes_one_bit", packed_bytes},
                      {"world_free_cells", world.free_count()}};
  if (json_) {
    fmt::print("{}\n", j.dump(2));
    return kExitOk;
  }
  fmt::print("{}: {} map\n", file_.string(), loaded->format);
  fmt::print("  size        {} x {} cells at {} m ({:.2f} x {:.2f} m), origin ({}, {})\n",
             g.width(), g.height(), g.resolution_m(), g.width() * g.resolution_m(),
             g.height() * g.resolution_m(), g.origin().x, g.origin().y);
  fmt::print("  cells       {} free, {} occupied, {} unknown\n", counts.free, counts.occupied,
             counts.unknown);
  fmt::print("  memory      {} bytes as an occupancy grid, {} bytes at one bit per cell\n",
             map.memory_bytes(), packed_bytes);
  return kExitOk;
}

}  // namespace tessera::cli
