// Fuzz target: a TUM RGB-D folder's image lists (rgb.txt, depth.txt) and their association, and
// its neck.txt (io/tum_rgbd_sequence.hpp). The list is associated with itself, which makes every
// stamp a candidate pair at least once.
#include "fuzz_target.hpp"
#include "internal/tum_rgbd_lists.hpp"
#include "tessera/io/tum_rgbd_sequence.hpp"

namespace {

tessera::Status read(std::string_view bytes, const std::filesystem::path& path) {
  const auto list = tessera::io_internal::decode_tum_image_list(bytes, path.string());
  if (!list) return list.error();
  static_cast<void>(
      tessera::io_internal::associate(*list, *list, tessera::kTumMaxStampDifferenceS));
  return tessera::fuzz::status_of(tessera::io_internal::decode_tum_neck(bytes, path.string()));
}

TESSERA_FUZZ_TARGET("tum_rgbd_lists", ".txt", &read);

}  // namespace
