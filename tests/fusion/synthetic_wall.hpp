#pragma once
// Synthetic RGB-D frames of a flat wall for the fusion tests: a pinhole camera looking at the plane
// z = wall_z_m of the reference camera frame, rendered by casting each pixel's ray onto the plane.
// The wall's grey value comes from a texture function of the wall coordinates (metres), so a
// textured poster, a small patch or a blank wall are all a few lines.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>

#include "tessera/core/rng.hpp"
#include "tessera/sensors/rgbd_frame.hpp"

namespace tessera::fusion::testing {

/// Grey value (0..255) of the wall at (x_m, y_m).
using WallTexture = std::function<double(double x_m, double y_m)>;

inline double lattice_value(std::int64_t i, std::int64_t j, std::uint64_t seed) {
  std::uint64_t z = seed + 0x9E3779B97F4A7C15ull * static_cast<std::uint64_t>(i) +
                    0xC2B2AE3D27D4EB4Full * static_cast<std::uint64_t>(j);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) / static_cast<double>(1ull << 53);
}

/// Random blobs: values on a lattice of `cell_m`, bilinearly interpolated (a poster-like texture
/// with corners at every scale the features look at).
inline WallTexture blob_texture(double cell_m, std::uint64_t seed) {
  return [cell_m, seed](double x_m, double y_m) {
    const double gx = x_m / cell_m, gy = y_m / cell_m;
    const auto i = static_cast<std::int64_t>(std::floor(gx));
    const auto j = static_cast<std::int64_t>(std::floor(gy));
    const double fx = gx - std::floor(gx), fy = gy - std::floor(gy);
    const double v = (1 - fx) * (1 - fy) * lattice_value(i, j, seed) +
                     fx * (1 - fy) * lattice_value(i + 1, j, seed) +
                     (1 - fx) * fy * lattice_value(i, j + 1, seed) +
                     fx * fy * lattice_value(i + 1, j + 1, seed);
    return 255.0 * v;
  };
}

/// A white wall with a textured square poster of side `side_m` centred at (cx_m, cy_m).
inline WallTexture poster_on_blank_wall(double cx_m, double cy_m, double side_m) {
  const WallTexture poster = blob_texture(0.015, 77);
  return [=](double x_m, double y_m) {
    if (std::abs(x_m - cx_m) <= 0.5 * side_m && std::abs(y_m - cy_m) <= 0.5 * side_m) {
      return poster(x_m, y_m);
    }
    return 235.0;
  };
}

/// The frame seen by a camera at T_ref_cam looking at the wall z = wall_z_m of the reference
/// frame. Depth is exact; `pixel_noise` adds Gaussian noise to the grey values (seeded).
inline RgbdFrame render_wall(const Eigen::Isometry3d& T_ref_cam, double wall_z_m,
                             const WallTexture& texture, const PinholeIntrinsics& k,
                             double pixel_noise = 0.0, std::uint64_t noise_seed = 1) {
  RgbdFrame f;
  f.width = k.width_px;
  f.height = k.height_px;
  f.intrinsics = k;
  f.rgb.resize(3 * f.pixel_count());
  f.depth_m.resize(f.pixel_count());
  Rng rng(noise_seed);
  const Eigen::Matrix3d R = T_ref_cam.linear();
  const Eigen::Vector3d t = T_ref_cam.translation();
  std::size_t i = 0;
  for (int v = 0; v < f.height; ++v) {
    for (int u = 0; u < f.width; ++u, ++i) {
      const Eigen::Vector3d d_cam((u - k.cx_px) / k.fx_px, (v - k.cy_px) / k.fy_px, 1.0);
      const Eigen::Vector3d d_ref = R * d_cam;
      const double s = (wall_z_m - t.z()) / d_ref.z();  // ray parameter; depth along z_cam = s
      const Eigen::Vector3d p = t + s * d_ref;
      double g = texture(p.x(), p.y());
      if (pixel_noise > 0.0) g += rng.gaussian(pixel_noise);
      const auto byte = static_cast<std::uint8_t>(std::lround(std::clamp(g, 0.0, 255.0)));
      f.rgb[3 * i] = f.rgb[3 * i + 1] = f.rgb[3 * i + 2] = byte;
      f.depth_m[i] = static_cast<float>(s);
    }
  }
  return f;
}

/// A small motion like the robot's between two nodes: 6 cm, 3 degrees.
inline Eigen::Isometry3d small_motion() {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() =
      Eigen::AngleAxisd(0.05, Eigen::Vector3d(0.1, 1.0, 0.05).normalized()).toRotationMatrix();
  T.translation() = Eigen::Vector3d(0.05, -0.02, 0.03);
  return T;
}

}  // namespace tessera::fusion::testing
