#pragma once
// In-memory entry points of the readers: each takes the file's bytes and the name its errors
// name, and does everything the path-taking reader in include/tessera/io/ does after reading the
// file. The public readers are these plus io_internal::read_file_bytes; the fuzz harnesses
// (fuzz/) and their regression tests (tests/fuzz/) call them directly.
// (decode_pgm and decode_bob_map are public; the image decoder is decode_raw_image in
// raw_image.hpp, the TUM RGB-D list decoders are in tum_rgbd_lists.hpp.)
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "tessera/core/relation.hpp"
#include "tessera/core/result.hpp"
#include "tessera/core/stamped_pose2.hpp"
#include "tessera/grid/occupancy_grid.hpp"
#include "tessera/grid/polygon_map.hpp"
#include "tessera/io/carmen_log.hpp"
#include "tessera/io/map_yaml.hpp"
#include "tessera/io/stage_world.hpp"
#include "tessera/posegraph/pose_graph.hpp"
#include "tessera/sensors/laser_log.hpp"
#include "tessera/trajectory/stamped_pose3.hpp"

namespace tessera::io_internal {

/// read_houseexpo_json / read_houseexpo_map (io/houseexpo.hpp).
[[nodiscard]] Result<PolygonMap> decode_houseexpo_json(std::string_view text,
                                                       const std::string& name);
/// The grid decode_houseexpo_map rasterises `plan` on: its bounding box plus one cell of margin
/// on every side, sizes in cells as doubles (far-apart vertices would overflow an int).
struct HouseExpoGridSize {
  double width = 0.0;
  double height = 0.0;
};
[[nodiscard]] HouseExpoGridSize houseexpo_grid_size(const PolygonMap& plan, double resolution_m);
[[nodiscard]] Result<OccupancyGrid> decode_houseexpo_map(std::string_view text,
                                                         const std::string& name,
                                                         double resolution_m);

/// parse_map_yaml (io/map_yaml.hpp): `yaml_path` is named in errors and locates the image (which
/// must exist; it is not read).
[[nodiscard]] Result<MapYaml> decode_map_yaml(std::string_view text,
                                              const std::filesystem::path& yaml_path);

/// read_movingai_map (io/movingai_map.hpp).
[[nodiscard]] Result<OccupancyGrid> decode_movingai_map(std::string_view text,
                                                        const std::string& name,
                                                        double cell_size_m);

/// parse_stage_world (io/stage_world.hpp): `path` is named in errors and locates the bitmap
/// (which must exist; it is not read).
[[nodiscard]] Result<StageFloorplan> decode_stage_world(std::string_view text,
                                                        const std::filesystem::path& path);

/// read_carmen_log (io/carmen_log.hpp); options as validated by the caller.
[[nodiscard]] Result<LaserLog> decode_carmen_log(std::string_view text, const std::string& file,
                                                 const CarmenReadOptions& options);

/// read_g2o (io/g2o_file.hpp).
[[nodiscard]] Result<posegraph::PoseGraph> decode_g2o(std::string_view text,
                                                      const std::string& file);

/// read_relations (io/relations_file.hpp).
[[nodiscard]] Result<std::vector<Relation>> decode_relations(std::string_view text,
                                                             const std::string& file);

/// read_tum_trajectory3 (io/tum_trajectory.hpp).
[[nodiscard]] Result<std::vector<StampedPose3>> decode_tum_trajectory3(std::string_view text,
                                                                       const std::string& name);

}  // namespace tessera::io_internal
