// Fuzz target: CARMEN logs (io/carmen_log.hpp, read_carmen_log) with the default options.
#include "fuzz_target.hpp"
#include "internal/decoders.hpp"

namespace {

tessera::Status read(std::string_view bytes, const std::filesystem::path& path) {
  return tessera::fuzz::status_of(
      tessera::io_internal::decode_carmen_log(bytes, path.string(), tessera::CarmenReadOptions{}));
}

TESSERA_FUZZ_TARGET("carmen", ".log", &read);

}  // namespace
