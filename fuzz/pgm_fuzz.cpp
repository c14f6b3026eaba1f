// Fuzz target: PGM images, P2 and P5 (io/pgm.hpp, decode_pgm).
#include "fuzz_target.hpp"
#include "tessera/io/pgm.hpp"

namespace {

tessera::Status read(std::string_view bytes, const std::filesystem::path& path) {
  return tessera::fuzz::status_of(tessera::decode_pgm(bytes, path.string()));
}

TESSERA_FUZZ_TARGET("pgm", ".pgm", &read);

}  // namespace
