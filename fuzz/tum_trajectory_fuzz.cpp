// Fuzz target: TUM trajectories (io/tum_trajectory.hpp, read_tum_trajectory3).
#include "fuzz_target.hpp"
#include "internal/decoders.hpp"

namespace {

tessera::Status read(std::string_view bytes, const std::filesystem::path& path) {
  return tessera::fuzz::status_of(
      tessera::io_internal::decode_tum_trajectory3(bytes, path.string()));
}

TESSERA_FUZZ_TARGET("tum_trajectory", ".txt", &read);

}  // namespace
