#include "commands.hpp"
#include "tessera/io/map_file.hpp"
#include "tessera/io/tum_trajectory.hpp"
#include "tessera/render/render.hpp"

namespace tessera::cli {

RenderCommand::RenderCommand(CLI::App& app) {
  sub_ =
      app.add_subcommand("render", "Draw a map as PNG, with trajectories and ground-truth errors");
  sub_->add_option("map", map_, "Map file (any format tessera reads)")->required();
  sub_->add_option("--out", out_, "PNG file to write")->required();
  sub_->add_option("--map-resolution-m", map_resolution_m_,
                   "Cell size for map files that carry none (images, Moving AI)");
  sub_->add_option("--trajectory", trajectories_, "TUM trajectory files to draw (repeatable)");
  sub_->add_option("--truth", truth_, "Ground-truth map: cells that disagree are coloured");
  sub_->add_option("--pixels-per-cell", pixels_per_cell_, "Scale (0: automatic)")
      ->check(CLI::Range(0, 64));
}

int RenderCommand::run() const {
  MapLoadOptions load_options;
  load_options.resolution_m = map_resolution_m_;
  Result<LoadedMap> map = load_map(map_, load_options);
  if (!map) return report_error(map.error());

  std::optional<World> truth;
  if (truth_) {
    Result<LoadedMap> t = load_map(*truth_, load_options);
    if (!t) return report_error(t.error());
    if (!(t->map.geometry() == map->map.geometry())) {
      return report_error(input_error(truth_->string() +
                                      ": ground truth must have the same size, resolution and "
                                      "origin as the map"));
    }
    truth = World::from_map(t->map);
  }

  RenderLayers layers;
  layers.map = &map->map;
  layers.truth = truth ? &*truth : nullptr;
  for (const auto& file : trajectories_) {
    Result<std::vector<StampedPose2>> poses = read_tum_trajectory(file);
    if (!poses) return report_error(poses.error());
    std::vector<Vec2> points;
    for (const auto& p : *poses) points.push_back(p.pose.translation());
    if (!points.empty()) layers.robots_m.push_back(points.back());
    layers.paths_m.push_back(std::move(points));
  }
  if (Status s = write_png(out_, layers, pixels_per_cell_); !s) return report_error(s.error());
  return kExitOk;
}

}  // namespace tessera::cli
