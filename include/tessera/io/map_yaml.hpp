#pragma once
// ROS map_server maps: a YAML file describing an image (ROS wiki map_server "Map format";
// nav2_map_server map_io.cpp loadMapYaml / loadMapFromFile / saveMapToFile).
#include <filesystem>
#include <optional>
#include <string>

#include "tessera/core/pose2.hpp"
#include "tessera/core/result.hpp"
#include "tessera/grid/occupancy_grid.hpp"
#include "tessera/io/gray_image.hpp"

namespace tessera {

/// The contents of a map_server YAML file.
struct MapYaml {
  /// How pixels become cells (nav2 MapMode).
  enum class Mode { kTrinary, kScale, kRaw };

  std::filesystem::path image;  // resolved: relative names are relative to the YAML's folder
  double resolution_m = 0.0;    // metres per pixel
  /// Pose of the lower-left pixel's lower-left corner. nav2 does not rotate the grid by the yaw,
  /// and neither does read_map_yaml: origin.theta is recorded, the grid stays axis-aligned.
  Pose2 origin;
  bool negate = false;  // true: white is occupied
  double occupied_thresh = 0.65;
  double free_thresh = 0.196;
  Mode mode = Mode::kTrinary;
};

/// Parses and checks a map YAML. Keys: image, resolution and origin ([x, y, yaw], 3 numbers) are
/// required as in nav2; negate (0/1 or bool), occupied_thresh, free_thresh and mode (trinary,
/// scale, raw) are optional with the defaults above. kInput errors, with the line where there is
/// one: no such file, YAML syntax error, missing image, resolution not > 0, bad mode, thresholds
/// outside [0, 1] or free_thresh > occupied_thresh, image file missing.
[[nodiscard]] Result<MapYaml> parse_map_yaml(const std::filesystem::path& yaml_path);

/// Reads the map: parse_map_yaml, then the image, with nav2_map_server loadMapFromFile semantics:
/// shade = mean(R,G,B)/255 (trinary also averages in alpha when the image has it);
/// occ = negate ? shade : 1 - shade;
/// trinary: occ > occupied_thresh -> p = 1, occ < free_thresh -> p = 0, otherwise unknown;
/// scale: as trinary, but in between p = rint((occ - free) / (occupied - free) * 100) / 100, and a
///        pixel that is not fully opaque is unknown;
/// raw: v = round(shade * 255); 0 <= v <= 100 -> p = v / 100, otherwise unknown.
/// p is stored with OccupancyGrid::set_probability (which clamps 0 and 1). Image row 0 is the top,
/// so image row r is cell row height - 1 - r; the origin is yaml.origin's x, y.
[[nodiscard]] Result<OccupancyGrid> read_map_yaml(const std::filesystem::path& yaml_path);

/// How write_map_yaml classifies cells (nav2 map_saver defaults).
struct MapSaveOptions {
  double occupied_thresh = 0.65;  // p >= this (in percent, rounded) -> black
  double free_thresh = 0.25;      // p <= this (in percent, rounded) -> white
};
/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const MapSaveOptions& o);

/// The trinary map_saver picture of a map (nav2 map_io.cpp tryWriteMapToFile): with
/// v = rint(p * 100), unknown -> 205, v <= rint(free_thresh * 100) -> 254,
/// v >= rint(occupied_thresh * 100) -> 0, in between -> 205. Precondition: validate(options) empty.
[[nodiscard]] GrayImage map_saver_image(const OccupancyGrid& map, const MapSaveOptions& options);

/// Writes `yaml_path` and "<stem>.pgm" beside it (the YAML names the image relative to itself),
/// both atomically: nothing new is left behind if either fails. The YAML carries the load
/// thresholds occupied_thresh 0.65 and free_thresh 0.196 (ROS 1 map_saver), not the save thresholds
/// as nav2 writes them: with nav2's 0.25 the 205 "unknown" grey would load back as free. So
/// read_map_yaml(write_map_yaml(m)) gives free, occupied and unknown cells where map_saver_image
/// shows them. Errors: kInput for invalid options or an empty map, kRuntime when writing fails.
[[nodiscard]] Status write_map_yaml(const OccupancyGrid& map,
                                    const std::filesystem::path& yaml_path,
                                    const MapSaveOptions& options = {});

}  // namespace tessera
