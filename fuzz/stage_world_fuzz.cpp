// Fuzz target: Stage world files (io/stage_world.hpp, parse_stage_world). The bitmap it names is
// never found (fuzz/libfuzzer_main.cpp); the world syntax is what is under test.
#include "fuzz_target.hpp"
#include "internal/decoders.hpp"

namespace {

tessera::Status read(std::string_view bytes, const std::filesystem::path& path) {
  return tessera::fuzz::status_of(tessera::io_internal::decode_stage_world(bytes, path));
}

TESSERA_FUZZ_TARGET("stage_world", ".world", &read);

}  // namespace
