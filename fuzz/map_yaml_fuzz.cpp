// Fuzz target: ROS map_server map YAML (io/map_yaml.hpp, parse_map_yaml). The image it names is
// never found (fuzz/libfuzzer_main.cpp), so every input ends in an error; the keys are what is
// under test.
#include "fuzz_target.hpp"
#include "internal/decoders.hpp"

namespace {

tessera::Status read(std::string_view bytes, const std::filesystem::path& path) {
  return tessera::fuzz::status_of(tessera::io_internal::decode_map_yaml(bytes, path));
}

TESSERA_FUZZ_TARGET("map_yaml", ".yaml", &read);

}  // namespace
