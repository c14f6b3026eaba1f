#include "tessera/io/map_file.hpp"

#include <string>
#include <system_error>

#include "internal/file_util.hpp"
#include "tessera/io/bob_map_file.hpp"
#include "tessera/io/houseexpo.hpp"
#include "tessera/io/image_map.hpp"
#include "tessera/io/map_yaml.hpp"
#include "tessera/io/movingai_map.hpp"
#include "tessera/io/stage_world.hpp"

namespace tessera {
namespace {

Result<LoadedMap> tagged(Result<OccupancyGrid> grid, const char* format) {
  if (!grid) return grid.error();
  return LoadedMap{std::move(grid).value(), format};
}

}  // namespace

Result<LoadedMap> load_map(const std::filesystem::path& path, const MapLoadOptions& options) {
  const std::string name = path.string();
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return input_error(name + ": no such file");
  if (options.resolution_m && !(*options.resolution_m > 0.0)) {
    return input_error(name + ": resolution must be > 0, got " +
                       io_internal::format_double(*options.resolution_m));
  }
  const std::string ext = io_internal::lower_extension(path);
  if (ext == ".yaml" || ext == ".yml") return tagged(read_map_yaml(path), "ros_map_server");
  if (ext == ".world") return tagged(read_stage_world(path), "stage");
  if (ext == ".bob") {  // tessera bob's map.bob (bob_map_file.hpp)
    Result<BobMapFile> bob = read_bob_map(path);
    if (!bob) return bob.error();
    return tagged(bob_map_to_grid(*bob, name), "bob");
  }
  if (ext == ".map") {
    return tagged(read_movingai_map(path, options.resolution_m.value_or(1.0)), "movingai");
  }
  if (ext == ".json") {
    return tagged(read_houseexpo_map(path, options.resolution_m.value_or(0.05)), "houseexpo");
  }
  if (ext == ".png" || ext == ".pgm") {
    if (!options.resolution_m) {
      return input_error(name +
                         ": a plain image needs a resolution (--resolution-m); "
                         "images carry no scale");
    }
    return tagged(read_image_map(path, *options.resolution_m), "image");
  }
  return input_error(name + ": unknown map format '" + (ext.empty() ? std::string("(none)") : ext) +
                     "' (supported: .yaml/.yml ROS map_server, .png/.pgm image, .map Moving AI, "
                     ".world Stage, .json HouseExpo, .bob BOBMapping)");
}

}  // namespace tessera
