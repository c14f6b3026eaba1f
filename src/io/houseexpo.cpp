#include "tessera/io/houseexpo.hpp"

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "internal/file_util.hpp"

namespace tessera {

Result<PolygonMap> read_houseexpo_json(const std::filesystem::path& path) {
  const std::string name = path.string();
  Result<std::string> text = io_internal::read_file_bytes(path);
  if (!text) return text.error();
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(*text);
  } catch (const nlohmann::json::parse_error& e) {
    // e.what(): "[json.exception.parse_error.101] parse error at line 3, column 5: <reason>".
    std::string reason = e.what();
    if (const std::size_t colon = reason.find(": "); colon != std::string::npos) {
      reason = reason.substr(colon + 2);
    }
    const std::size_t byte = e.byte > 0 ? e.byte - 1 : 0;
    return input_error(name + ":" + std::to_string(io_internal::line_of_offset(*text, byte)) +
                       ": JSON syntax error: " + reason);
  }
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

Result<OccupancyGrid> read_houseexpo_map(const std::filesystem::path& path, double resolution_m) {
  if (!(resolution_m > 0.0)) {
    return input_error(path.string() + ": resolution must be > 0, got " +
                       io_internal::format_double(resolution_m));
  }
  Result<PolygonMap> plan = read_houseexpo_json(path);
  if (!plan) return plan.error();
  const auto [lo, hi] = plan->bounds();
  // One cell of margin on every side of the contour's bounding box.
  const Vec2 origin{lo.x - resolution_m, lo.y - resolution_m};
  const int width = static_cast<int>(std::ceil((hi.x - lo.x) / resolution_m - 1e-9)) + 2;
  const int height = static_cast<int>(std::ceil((hi.y - lo.y) / resolution_m - 1e-9)) + 2;
  if (static_cast<double>(width) * height > static_cast<double>(io_internal::kMaxCells)) {
    return input_error(path.string() + ": a " + std::to_string(width) + " x " +
                       std::to_string(height) + " grid at resolution " +
                       io_internal::format_double(resolution_m) + " m is too large");
  }
  return plan->rasterize(GridGeometry(origin, resolution_m, width, height));
}

}  // namespace tessera
