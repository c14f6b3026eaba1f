#include "tessera/io/map_yaml.hpp"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <exception>
#include <string>

#include "internal/decoders.hpp"
#include "internal/file_util.hpp"
#include "internal/raw_image.hpp"
#include "tessera/core/angle.hpp"
#include "tessera/io/atomic_file.hpp"
#include "tessera/io/pgm.hpp"

namespace tessera {
namespace {

using io_internal::format_double;
using io_internal::parse_double;

// Reads the keys of one map YAML, building "<file>:<line>: ..." messages (yaml-cpp marks are
// 0-based).
class YamlKeys {
 public:
  YamlKeys(const YAML::Node& doc, std::string name) : doc_(doc), name_(std::move(name)) {}

  [[nodiscard]] YAML::Node get(const char* key) const { return doc_[key]; }

  [[nodiscard]] Error at(const YAML::Node& node, const std::string& what) const {
    return input_error(name_ + ":" + std::to_string(node.Mark().line + 1) + ": " + what);
  }
  [[nodiscard]] Error missing(const std::string& what) const {
    return input_error(name_ + ": " + what);
  }

  // A finite number from a scalar node, or an error naming the key.
  bool number(const YAML::Node& node, const std::string& key, double& out, Error& error) const {
    if (!node.IsScalar()) {
      error = at(node, key + " must be a number, got " + kind(node));
      return false;
    }
    if (!parse_double(node.Scalar(), out)) {
      error = at(node, key + " must be a number, got '" + node.Scalar() + "'");
      return false;
    }
    return true;
  }

  static std::string kind(const YAML::Node& node) {
    if (node.IsSequence()) return "a list";
    if (node.IsMap()) return "a mapping";
    if (node.IsNull()) return "nothing";
    return "'" + node.Scalar() + "'";
  }

 private:
  const YAML::Node& doc_;
  std::string name_;
};

// Plain YAML scalar when safe, else double-quoted.
std::string yaml_string(const std::string& s) {
  bool plain = !s.empty();
  for (const char c : s) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '.' || c == '_' || c == '-';
    if (!ok) plain = false;
  }
  if (plain && s.front() != '-' && s.front() != '.') return s;
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

// The keys of a loaded document (decode_map_yaml). May throw YAML::Exception from yaml-cpp's
// accessors; decode_map_yaml turns those into input errors.
Result<MapYaml> map_yaml_from(const YAML::Node& doc, const std::filesystem::path& yaml_path) {
  const std::string name = yaml_path.string();
  if (!doc.IsMap()) {
    return input_error(name +
                       ": expected a YAML mapping with the keys image, resolution and origin"
                       " (ROS map_server map format)");
  }
  const YamlKeys keys(doc, name);
  MapYaml map;
  Error error;

  // image: required (nav2 loadMapYaml); the file's existence is checked last.
  const YAML::Node image = keys.get("image");
  if (!image) return keys.missing("missing 'image' (the map image's file name)");
  if (!image.IsScalar() || image.Scalar().empty()) {
    return keys.at(image, "image must be a file name, got " + YamlKeys::kind(image));
  }

  const YAML::Node resolution = keys.get("resolution");
  if (!resolution) return keys.missing("missing 'resolution' (metres per pixel)");
  if (!keys.number(resolution, "resolution", map.resolution_m, error)) return error;
  if (!(map.resolution_m > 0.0)) {
    return keys.at(resolution, "resolution must be > 0, got " + resolution.Scalar());
  }

  const YAML::Node origin = keys.get("origin");
  if (!origin) return keys.missing("missing 'origin' ([x, y, yaw] of the lower-left pixel)");
  if (!origin.IsSequence() || origin.size() != 3) {
    return keys.at(origin, "origin must be [x, y, yaw] (3 numbers), got " +
                               (origin.IsSequence() ? std::to_string(origin.size()) + " elements"
                                                    : YamlKeys::kind(origin)));
  }
  double xyz[3] = {0.0, 0.0, 0.0};
  for (std::size_t i = 0; i < 3; ++i) {
    if (!keys.number(origin[i], "origin[" + std::to_string(i) + "]", xyz[i], error)) return error;
  }
  map.origin = {xyz[0], xyz[1], normalize_angle(xyz[2])};

  // negate: nav2 reads an int, then falls back to a bool.
  if (const YAML::Node negate = keys.get("negate")) {
    double v = 0.0;
    bool b = false;
    if (negate.IsScalar() && parse_double(negate.Scalar(), v) && v == std::floor(v)) {
      map.negate = v != 0.0;
    } else if (negate.IsScalar() && YAML::convert<bool>::decode(negate, b)) {
      map.negate = b;
    } else {
      return keys.at(negate, "negate must be 0, 1, true or false, got " + YamlKeys::kind(negate));
    }
  }

  const YAML::Node occupied = keys.get("occupied_thresh");
  const YAML::Node free = keys.get("free_thresh");
  if (occupied && !keys.number(occupied, "occupied_thresh", map.occupied_thresh, error)) {
    return error;
  }
  if (free && !keys.number(free, "free_thresh", map.free_thresh, error)) return error;
  if (const std::string problem =
          io_internal::threshold_problem(map.occupied_thresh, map.free_thresh);
      !problem.empty()) {
    const bool occupied_bad = !(0.0 <= map.occupied_thresh && map.occupied_thresh <= 1.0);
    const YAML::Node& where = occupied_bad ? occupied : (free ? free : occupied);
    return where ? keys.at(where, problem) : keys.missing(problem);
  }

  const YAML::Node mode = keys.get("mode");
  if (mode) {
    const std::string m = mode.IsScalar() ? mode.Scalar() : std::string();
    if (m == "trinary") {
      map.mode = MapYaml::Mode::kTrinary;
    } else if (m == "scale") {
      map.mode = MapYaml::Mode::kScale;
    } else if (m == "raw") {
      map.mode = MapYaml::Mode::kRaw;
    } else {
      return keys.at(mode, "mode must be trinary, scale or raw, got " + YamlKeys::kind(mode));
    }
  }
  if (map.mode == MapYaml::Mode::kScale && !(map.free_thresh < map.occupied_thresh)) {
    return keys.at(mode, "mode scale needs free_thresh < occupied_thresh, got " +
                             format_double(map.free_thresh) + " and " +
                             format_double(map.occupied_thresh));
  }

  // nav2: a relative image name is relative to the YAML's folder.
  const std::filesystem::path image_name = image.Scalar();
  map.image = image_name.is_absolute() ? image_name : yaml_path.parent_path() / image_name;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(map.image, ec)) {
    return keys.at(image, "image file '" + image.Scalar() + "' not found (looked for " +
                              map.image.string() + ")");
  }
  return map;
}

// yaml-cpp's mark of an exception, "<file>:<line>: " when it has one (marks are 0-based; -1 when
// the exception has no position).
std::string yaml_where(const std::string& name, const YAML::Mark& mark) {
  return mark.is_null() || mark.line < 0 ? name + ": "
                                         : name + ":" + std::to_string(mark.line + 1) + ": ";
}

}  // namespace

Result<MapYaml> parse_map_yaml(const std::filesystem::path& yaml_path) {
  Result<std::string> text = io_internal::read_file_bytes(yaml_path);
  if (!text) return text.error();
  return io_internal::decode_map_yaml(*text, yaml_path);
}

Result<MapYaml> io_internal::decode_map_yaml(std::string_view text,
                                             const std::filesystem::path& yaml_path) {
  const std::string name = yaml_path.string();
  YAML::Node doc;
  try {
    doc = YAML::Load(std::string(text));
  } catch (const YAML::Exception& e) {
    return input_error(yaml_where(name, e.mark) + "YAML syntax error: " + e.msg);
  }
  try {
    return map_yaml_from(doc, yaml_path);
  } catch (const YAML::Exception& e) {
    return input_error(yaml_where(name, e.mark) + "unexpected YAML structure: " + e.msg);
  }
}

Result<OccupancyGrid> read_map_yaml(const std::filesystem::path& yaml_path) {
  Result<MapYaml> yaml = parse_map_yaml(yaml_path);
  if (!yaml) return yaml.error();
  Result<io_internal::RawImage> image = io_internal::read_raw_image(yaml->image);
  if (!image) return image.error();
  io_internal::PixelRules rules;
  rules.mode = yaml->mode == MapYaml::Mode::kScale ? io_internal::PixelMode::kScale
               : yaml->mode == MapYaml::Mode::kRaw ? io_internal::PixelMode::kRaw
                                                   : io_internal::PixelMode::kTrinary;
  rules.negate = yaml->negate;
  rules.occupied_thresh = yaml->occupied_thresh;
  rules.free_thresh = yaml->free_thresh;
  return io_internal::grid_from_image(*image, {yaml->origin.x, yaml->origin.y}, yaml->resolution_m,
                                      rules);
}

std::optional<std::string> validate(const MapSaveOptions& o) {
  // nav2 map_io.cpp checkSaveParameters.
  if (!(0.0 < o.occupied_thresh && o.occupied_thresh <= 1.0)) {
    return "occupied_thresh must be in (0, 1], got " + format_double(o.occupied_thresh);
  }
  if (!(0.0 <= o.free_thresh && o.free_thresh < 1.0)) {
    return "free_thresh must be in [0, 1), got " + format_double(o.free_thresh);
  }
  if (!(o.free_thresh < o.occupied_thresh)) {
    return "free_thresh (" + format_double(o.free_thresh) + ") must be below occupied_thresh (" +
           format_double(o.occupied_thresh) + ")";
  }
  return std::nullopt;
}

GrayImage map_saver_image(const OccupancyGrid& map, const MapSaveOptions& options) {
  // nav2 map_io.cpp tryWriteMapToFile, MapMode::Trinary.
  const GridGeometry& g = map.geometry();
  const int free_int = static_cast<int>(std::rint(options.free_thresh * 100.0));
  const int occupied_int = static_cast<int>(std::rint(options.occupied_thresh * 100.0));
  GrayImage image(g.width(), g.height(), 205);
  for (int y = 0; y < g.height(); ++y) {
    const int row = g.height() - 1 - y;
    for (int x = 0; x < g.width(); ++x) {
      const std::optional<double> p = map.probability_at({x, y});
      if (!p) continue;
      const int v = static_cast<int>(std::rint(*p * 100.0));
      if (v <= free_int) {
        image.set(x, row, 254);
      } else if (occupied_int <= v) {
        image.set(x, row, 0);
      }
    }
  }
  return image;
}

Status write_map_yaml(const OccupancyGrid& map, const std::filesystem::path& yaml_path,
                      const MapSaveOptions& options) {
  if (auto problem = validate(options)) {
    return input_error(yaml_path.string() + ": cannot save map: " + *problem);
  }
  const GridGeometry& g = map.geometry();
  if (g.width() == 0 || g.height() == 0) {
    return input_error(yaml_path.string() + ": cannot save an empty map (" +
                       std::to_string(g.width()) + " x " + std::to_string(g.height()) + " cells)");
  }
  const std::string image_name = yaml_path.stem().string() + ".pgm";
  const std::filesystem::path image_path = yaml_path.parent_path() / image_name;
  if (image_path == yaml_path) {
    return input_error(yaml_path.string() + ": the map YAML must not be named *.pgm");
  }
  const std::string pgm = encode_pgm(map_saver_image(map, options));
  // ROS 1 map_saver's YAML: load thresholds under which 254 is free, 0 occupied, 205 unknown.
  const std::string yaml = "image: " + yaml_string(image_name) +
                           "\nmode: trinary\nresolution: " + format_double(g.resolution_m()) +
                           "\norigin: [" + format_double(g.origin().x) + ", " +
                           format_double(g.origin().y) +
                           ", 0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n";
  const PendingFile files[] = {{image_path, pgm}, {yaml_path, yaml}};
  return write_files_atomic(files);
}

}  // namespace tessera
