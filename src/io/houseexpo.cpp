#include "tessera/io/houseexpo.hpp"

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "internal/decoders.hpp"
#include "internal/file_util.hpp"
#include "internal/json_parse.hpp"

namespace tessera {

Result<PolygonMap> read_houseexpo_json(const std::filesystem::path& path) {
  Result<std::string> text = io_internal::read_file_bytes(path);
  if (!text) return text.error();
  return io_internal::decode_houseexpo_json(*text, path.string());
}

namespace io_internal {

Result<PolygonMap> decode_houseexpo_json(std::string_view text, const std::string& name) {
  Result<nlohmann::json> parsed = parse_json(text, name);
  if (!parsed) return parsed.error();
  const nlohmann::json& doc = *parsed;
  if (!doc.is_object()) {
    return input_error(name + ": expected a HouseExpo JSON object with 'verts'");
  }
  const auto verts = doc.find("verts");
  if (verts == doc.end()) {
    return input_error(name + ": missing 'verts' (the outer contour, [[x, y], ...] in metres)");
  }
  if (!verts->is_array()) return input_error(name + ": 'verts' must be a list of [x, y] points");
  Polygon polygon;
  polygon.vertices.reserve(verts->size());
  for (std::size_t i = 0; i < verts->size(); ++i) {
    const nlohmann::json& v = (*verts)[i];
    if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number() ||
        !std::isfinite(v[0].get<double>()) || !std::isfinite(v[1].get<double>())) {
      return input_error(
          name + ": verts[" + std::to_string(i) + "] must be [x, y] (two numbers), got " +
          v.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace).substr(0, 40));
    }
    polygon.vertices.push_back({v[0].get<double>(), v[1].get<double>()});
  }
  if (polygon.vertices.size() < 3) {
    return input_error(name + ": 'verts' has " + std::to_string(polygon.vertices.size()) +
                       " vertices, a contour needs at least 3");
  }
  PolygonMap map(PolygonMap::Meaning::kFreeSpace);
  map.add(std::move(polygon));
  return map;
}

}  // namespace io_internal

Result<OccupancyGrid> read_houseexpo_map(const std::filesystem::path& path, double resolution_m) {
  if (!(resolution_m > 0.0)) {
    return input_error(path.string() + ": resolution must be > 0, got " +
                       io_internal::format_double(resolution_m));
  }
  Result<std::string> text = io_internal::read_file_bytes(path);
  if (!text) return text.error();
  return io_internal::decode_houseexpo_map(*text, path.string(), resolution_m);
}

namespace io_internal {

HouseExpoGridSize houseexpo_grid_size(const PolygonMap& plan, double resolution_m) {
  const auto [lo, hi] = plan.bounds();
  return {std::ceil((hi.x - lo.x) / resolution_m - 1e-9) + 2.0,
          std::ceil((hi.y - lo.y) / resolution_m - 1e-9) + 2.0};
}

Result<OccupancyGrid> decode_houseexpo_map(std::string_view text, const std::string& name,
                                           double resolution_m) {
  Result<PolygonMap> plan = decode_houseexpo_json(text, name);
  if (!plan) return plan.error();
  const Vec2 lo = plan->bounds().first;
  // One cell of margin on every side of the contour's bounding box.
  const Vec2 origin{lo.x - resolution_m, lo.y - resolution_m};
  // Sizes in double first: far-apart vertices would overflow an int (undefined behaviour).
  const auto [width, height] = houseexpo_grid_size(*plan, resolution_m);
  if (!(width * height <= static_cast<double>(kMaxCells))) {
    return input_error(name + ": a " + format_double(width) + " x " + format_double(height) +
                       " grid at resolution " + format_double(resolution_m) + " m is too large");
  }
  return plan->rasterize(
      GridGeometry(origin, resolution_m, static_cast<int>(width), static_cast<int>(height)));
}

}  // namespace io_internal

}  // namespace tessera
