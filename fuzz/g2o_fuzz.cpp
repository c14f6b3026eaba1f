// Fuzz target: g2o 2D pose graphs (io/g2o_file.hpp, read_g2o).
#include "fuzz_target.hpp"
#include "internal/decoders.hpp"

namespace {

tessera::Status read(std::string_view bytes, const std::filesystem::path& path) {
  return tessera::fuzz::status_of(tessera::io_internal::decode_g2o(bytes, path.string()));
}

TESSERA_FUZZ_TARGET("g2o", ".g2o", &read);

}  // namespace
