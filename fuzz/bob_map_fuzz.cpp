// Fuzz target: BOB map files (io/bob_map_file.hpp, decode_bob_map).
#include "fuzz_target.hpp"
#include "tessera/io/bob_map_file.hpp"

namespace {

tessera::Status read(std::string_view bytes, const std::filesystem::path& path) {
  return tessera::fuzz::status_of(tessera::decode_bob_map(bytes, path.string()));
}

TESSERA_FUZZ_TARGET("bob_map", ".bobmap", &read);

}  // namespace
