// Fuzz target: a TUM RGB-D folder's intrinsics.txt (io/tum_rgbd_sequence.hpp).
#include "fuzz_target.hpp"
#include "internal/tum_rgbd_lists.hpp"

namespace {

tessera::Status read(std::string_view bytes, const std::filesystem::path& path) {
  bool has_size = false;
  return tessera::fuzz::status_of(
      tessera::io_internal::decode_tum_intrinsics(bytes, path.string(), has_size));
}

TESSERA_FUZZ_TARGET("tum_rgbd_intrinsics", ".txt", &read);

}  // namespace
