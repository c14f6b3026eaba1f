#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "tessera/io/map_file.hpp"

namespace tessera::cli {

InfoCommand::InfoCommand(CLI::App& app) {
  sub_ = app.add_subcommand("info", "Describe a map file: format, size, resolution, cell counts");
  sub_->add_option("file", file_, "Map file (any format tessera reads)")->required();
  sub_->add_option("--map-resolution-m", map_resolution_m_,
                   "Cell size for map files that carry none (images, Moving AI)");
  sub_->add_flag("--json", json_, "Print JSON instead of text");
}

int InfoCommand::run() const {
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
