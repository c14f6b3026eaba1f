#pragma once
// Real photographs as wall textures for the simulated RGB-D camera (sim/rgbd_camera.hpp,
// sim/wall_texture.hpp): RTAB-Map's loop-closure images (../shared/data/rgbd/rtabmap_loop_samples/
// images, 84 JPEGs of 512 x 384) and the TUM frames (../shared/data/rgbd/tum_fr1_xyz_pairs/case_*/
// img_*.png). Decoded with OpenCV's imgcodecs, here in io only.
#include <filesystem>
#include <string_view>
#include <vector>

#include "tessera/core/result.hpp"
#include "tessera/sim/wall_texture.hpp"

namespace tessera {

/// The .jpg, .jpeg and .png files in `folder` (and its sub-folders when `recursive`) whose names
/// start with `name_prefix`, in natural order ("2.jpg" before "10.jpg"; paths compared folder by
/// folder). Input error when `folder` is not a folder or holds no such file.
[[nodiscard]] Result<std::vector<std::filesystem::path>> list_texture_images(
    const std::filesystem::path& folder, bool recursive = false, std::string_view name_prefix = "");

/// One photo as a texture (name = the file name). Grey images become grey RGB, alpha is dropped.
/// Input errors name the file: "<file>: no such file", "<file>: cannot decode image", "<file>: a
/// wall texture must be an 8-bit grey, RGB or RGBA image, got 16-bit with 1 channel" (a depth
/// image, say).
[[nodiscard]] Result<WallTexture> read_wall_texture(const std::filesystem::path& path);

/// read_wall_texture of each file, in order; the first error stops.
[[nodiscard]] Result<std::vector<WallTexture>> read_wall_textures(
    const std::vector<std::filesystem::path>& paths);

}  // namespace tessera
