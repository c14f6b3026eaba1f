#pragma once
// A test room for the simulated RGB-D camera: 7 m x 4.5 m at 5 cm with one-cell walls, so the
// free space is x in [0.05, 6.95], y in [0.05, 4.45]. The east wall (x = 6.95, facing west) can
// carry a poster; the north wall (y = 4.45) stays blank.
#include <cstdint>
#include <vector>

#include "tessera/sim/rgbd_camera.hpp"

namespace tessera::support {

inline World rgbd_room() {
  const int w = 140, h = 90;
  std::vector<std::uint8_t> solid(static_cast<std::size_t>(w * h), 0);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (x == 0 || y == 0 || x == w - 1 || y == h - 1) solid[static_cast<std::size_t>(y * w + x)] = 1;
    }
  }
  return World(GridGeometry({0.0, 0.0}, 0.05, w, h), solid, "rgbd_room");
}

inline constexpr double kEastWallX = 6.95;
inline constexpr double kNorthWallY = 4.45;

/// A photo-like texture: smooth colour gradients plus a deterministic pattern of blobs and edges
/// (no real photo needed in sim tests).
inline WallTexture test_photo(int width = 256, int height = 192) {
  WallTexture t;
  t.width = width;
  t.height = height;
  t.name = "test_photo";
  t.rgb.resize(static_cast<std::size_t>(3 * width * height));
  std::uint32_t state = 12345;
  std::vector<std::uint8_t> blocks(64);
  for (auto& b : blocks) {
    state = state * 1664525u + 1013904223u;
    b = static_cast<std::uint8_t>(state >> 24);
  }
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const std::size_t i = static_cast<std::size_t>(3 * (y * width + x));
      const std::uint8_t block = blocks[static_cast<std::size_t>((y * 8 / height) * 8 + x * 8 / width)];
      t.rgb[i] = static_cast<std::uint8_t>((block + x) & 0xff);
      t.rgb[i + 1] = static_cast<std::uint8_t>((block * 3 + y) & 0xff);
      t.rgb[i + 2] = block;
    }
  }
  return t;
}

/// The east wall's face and a poster 1.2 m x 0.9 m centred on it at camera height.
inline Poster east_poster(const std::vector<WallFace>& faces, int texture = 0) {
  Poster p;
  p.face = nearest_wall_face(faces, {kEastWallX, 2.25});
  p.texture = texture;
  p.width_m = 1.2;
  p.height_m = 0.9;
  p.center_m = 0.5 * faces[static_cast<std::size_t>(p.face)].length_m();
  p.bottom_m = 1.03 - 0.45;
  return p;
}

/// The room with the east poster, noise off unless asked.
inline RgbdCamera room_camera(RgbdCameraOptions o = {}, bool noise = false) {
  if (!noise) o.depth_noise_coefficient_1_per_m = 0.0;
  const World world = rgbd_room();
  const std::vector<WallFace> faces = find_wall_faces(world).faces;
  Result<RgbdCamera> camera =
      RgbdCamera::create(world, o, {test_photo()}, {east_poster(faces)});
  return std::move(camera).value();
}

}  // namespace tessera::support
