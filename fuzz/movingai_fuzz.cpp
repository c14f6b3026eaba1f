// Fuzz target: Moving AI grid maps (io/movingai_map.hpp, read_movingai_map).
#include "fuzz_target.hpp"
#include "internal/decoders.hpp"

namespace {

tessera::Status read(std::string_view bytes, const std::filesystem::path& path) {
  return tessera::fuzz::status_of(
      tessera::io_internal::decode_movingai_map(bytes, path.string(), 1.0));
}

TESSERA_FUZZ_TARGET("movingai", ".map", &read);

}  // namespace
