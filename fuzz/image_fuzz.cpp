// Fuzz target: image maps (io/image_map.hpp, read_image_map): PNG and any other image OpenCV
// decodes, through the PNG chunk check and the ROS map_server pixel rules.
#include "fuzz_target.hpp"
#include "internal/raw_image.hpp"

namespace {

tessera::Status read(std::string_view bytes, const std::filesystem::path& path) {
  tessera::Result<tessera::io_internal::RawImage> image =
      tessera::io_internal::decode_raw_image(std::string(bytes), path.string());
  if (!image) return image.error();
  static_cast<void>(tessera::io_internal::grid_from_image(*image, {0.0, 0.0}, 0.05, {}));
  return tessera::Ok{};
}

TESSERA_FUZZ_TARGET("image", ".png", &read);

}  // namespace
