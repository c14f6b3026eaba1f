// Fuzz target: Kummerle relations files (io/relations_file.hpp, read_relations).
#include "fuzz_target.hpp"
#include "internal/decoders.hpp"

namespace {

tessera::Status read(std::string_view bytes, const std::filesystem::path& path) {
  return tessera::fuzz::status_of(tessera::io_internal::decode_relations(bytes, path.string()));
}

TESSERA_FUZZ_TARGET("relations", ".relations", &read);

}  // namespace
