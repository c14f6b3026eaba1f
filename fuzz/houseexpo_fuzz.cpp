// Fuzz target: HouseExpo JSON floor plans (io/houseexpo.hpp, read_houseexpo_map at 0.5 m).
#include <cmath>

#include "fuzz_target.hpp"
#include "internal/decoders.hpp"
#include "internal/file_util.hpp"

namespace {

constexpr double kResolutionM = 0.5;
// Plans whose grid would be larger than this are only parsed: rasterising up to kMaxCells cells
// (2^28) is legitimate but would take the fuzzer seconds and gigabytes per input.
constexpr double kMaxFuzzCells = 1e6;
// The same for the scanline work, the rows each edge spans summed over the edges: a zigzag of a
// thousand edges each crossing a million rows is a legitimate plan that takes seconds to fill.
constexpr double kMaxFuzzEdgeRows = 2e7;

double edge_rows(const tessera::PolygonMap& plan) {
  double rows = 0.0;
  for (const tessera::Polygon& polygon : plan.polygons()) {
    const std::vector<tessera::Vec2>& v = polygon.vertices;
    for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
      rows += std::fabs(v[i].y - v[j].y) / kResolutionM + 1.0;
    }
  }
  return rows;
}

tessera::Status read(std::string_view bytes, const std::filesystem::path& path) {
  tessera::Result<tessera::PolygonMap> plan =
      tessera::io_internal::decode_houseexpo_json(bytes, path.string());
  if (!plan) return plan.error();
  // The decoder's own grid size, so that "too large" means exactly what the decoder refuses
  // (an estimate with other margins let a 247-million-cell grid through as "refused quickly").
  const auto [width, height] = tessera::io_internal::houseexpo_grid_size(*plan, kResolutionM);
  const double cells = width * height;
  const bool too_large = !(cells <= static_cast<double>(tessera::io_internal::kMaxCells));
  if (!too_large && (cells > kMaxFuzzCells || edge_rows(*plan) > kMaxFuzzEdgeRows)) {
    return tessera::Ok{};
  }
  return tessera::fuzz::status_of(
      tessera::io_internal::decode_houseexpo_map(bytes, path.string(), kResolutionM));
}

TESSERA_FUZZ_TARGET("houseexpo", ".json", &read);

}  // namespace
