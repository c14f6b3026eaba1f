// Fuzz target: MCAP files (io/ros_bag.hpp; chunks none, zstd, lz4; ros1 or cdr messages), then the
// robot bag made from them (bag_target.hpp).
#include "bag_target.hpp"
#include "fuzz_target.hpp"

namespace {

tessera::Status read(std::string_view bytes, const std::filesystem::path& path) {
  return tessera::fuzz::read_bag(&tessera::io_internal::decode_mcap, bytes, path);
}

TESSERA_FUZZ_TARGET("mcap", ".mcap", &read);

}  // namespace
