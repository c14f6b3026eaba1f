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

tessera::Status read(std::string_view bytes, const std::filesystem::path& path) {
  tessera::Result<tessera::PolygonMap> plan =
      tessera::io_internal::decode_houseexpo_json(bytes, path.string());
  if (!plan) return plan.error();
  const auto [lo, hi] = plan->bounds();
  const double cells = ((hi.x - lo.x) / kResolutionM + 3.0) * ((hi.y - lo.y) / kResolutionM + 3.0);
  if (cells > kMaxFuzzCells &&
      cells <= static_cast<double>(tessera::io_internal::kMaxCells) * 1.01) {
    return tessera::Ok{};
  }
  return tessera::fuzz::status_of(
      tessera::io_internal::decode_houseexpo_map(bytes, path.string(), kResolutionM));
}

TESSERA_FUZZ_TARGET("houseexpo", ".json", &read);

}  // namespace
