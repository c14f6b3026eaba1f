#include "tessera/sim/rgbd_camera.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "tessera/core/assert.hpp"

namespace tessera {
namespace {

bool positive(double v) { return v > 0.0 && std::isfinite(v); }
bool non_negative(double v) { return v >= 0.0 && std::isfinite(v); }

/// Brightness of a plain wall by the side it faces (index: FaceSide of the free cell, i.e. the
/// face's normal -x, +x, -y, +y): a soft light from one corner, so that two walls meeting in a
/// corner differ and the corner stays visible, while one face is one uniform colour.
constexpr double kFaceShade[4] = {1.0, 0.86, 0.93, 0.80};

/// What a column's ray hit.
struct ColumnHit {
  double z_m = 0.0;  // depth of the wall along the optical axis (0: camera inside a solid cell)
  int face = -1;
  Vec2 point_m;
  int side = 0;
};

/// What a column shows on its wall: the plain colour, or a poster's texture coordinates.
struct Column {
  double z_m = 0.0;
  bool inside_solid = false;
  std::array<std::uint8_t, 3> wall_rgb{};
  int poster = -1;            // index into posters_, -1: none
  double tex_x0 = 0.0;        // column's x in level-0 texels of the poster's texture
  double poster_top_m = 0.0;  // height of the poster's top edge
  double poster_bottom_m = 0.0;
  double texels_per_m_v = 0.0;  // level-0 texels per metre of height
  /// The one or two mip levels the column samples (trilinear: fine and coarse), with their
  /// weights and the column's bilinear x taps, which are the same for every row.
  struct Tap {
    const RgbdCamera::MipLevel* level = nullptr;
    float weight = 0.0F;
    int x0 = 0, x1 = 0;
    float wx = 0.0F;
    double y_scale = 1.0;  // level texels per level-0 texel, vertically
  };
  Tap taps[2];
  int tap_count = 0;
};

/// Two standard Gaussians (Marsaglia's polar method, 1964: no sine or cosine, one logarithm per
/// pair), each candidate point from one 64-bit draw. The camera needs one Gaussian per pixel; this
/// is about twice as fast as Rng::gaussian while staying seeded and portable.
void gaussian_pair(Rng& rng, double& a, double& b) {
  for (;;) {
    const std::uint64_t bits = rng.next_u64();
    const double u = static_cast<double>(bits >> 32) * 0x1.0p-31 - 1.0;  // [-1, 1)
    const double v = static_cast<double>(bits & 0xffffffffULL) * 0x1.0p-31 - 1.0;
    const double s = u * u + v * v;
    if (s >= 1.0 || s == 0.0) continue;  // accepted with probability pi / 4
    const double f = std::sqrt(-2.0 * std::log(s) / s);
    a = u * f;
    b = v * f;
    return;
  }
}

/// A tap on `level` with the bilinear x taps for x in level-0 texels of a picture level0_width
/// wide (texel centres at +0.5, edges clamped).
Column::Tap make_tap(const RgbdCamera::MipLevel& level, int level0_width, int level0_height,
                     double x_level0, float weight) {
  Column::Tap tap;
  tap.level = &level;
  tap.weight = weight;
  const double fx = x_level0 * level.width / level0_width - 0.5;
  const double x0f = std::floor(fx);
  tap.wx = static_cast<float>(fx - x0f);
  tap.x0 = std::clamp(static_cast<int>(x0f), 0, level.width - 1);
  tap.x1 = std::clamp(static_cast<int>(x0f) + 1, 0, level.width - 1);
  tap.y_scale = static_cast<double>(level.height) / level0_height;
  return tap;
}

/// Adds tap.weight times the bilinear sample at (the tap's column, y in level-0 texels) to out.
inline void add_sample(const Column::Tap& tap, double y_level0, float out[3]) {
  const RgbdCamera::MipLevel& m = *tap.level;
  const double fy = y_level0 * tap.y_scale - 0.5;
  const double y0f = std::floor(fy);
  const float wy = static_cast<float>(fy - y0f);
  const int y0 = std::clamp(static_cast<int>(y0f), 0, m.height - 1);
  const int y1 = std::clamp(static_cast<int>(y0f) + 1, 0, m.height - 1);
  const std::size_t w3 = 3 * static_cast<std::size_t>(m.width);
  const std::uint8_t* r0 = m.rgb.data() + static_cast<std::size_t>(y0) * w3;
  const std::uint8_t* r1 = m.rgb.data() + static_cast<std::size_t>(y1) * w3;
  const std::size_t a = 3 * static_cast<std::size_t>(tap.x0), b = 3 * static_cast<std::size_t>(tap.x1);
  const float wx = tap.wx;
  for (int c = 0; c < 3; ++c) {
    const float top = r0[a + c] + wx * (static_cast<float>(r0[b + c]) - r0[a + c]);
    const float bottom = r1[a + c] + wx * (static_cast<float>(r1[b + c]) - r1[a + c]);
    out[c] += tap.weight * (top + wy * (bottom - top));
  }
}

/// The mip-map pyramid of a picture: halvings with a 2 x 2 box filter (an odd last row or column
/// folds into the previous pair) down to 1 x 1.
std::vector<RgbdCamera::MipLevel> build_pyramid(const WallTexture& t) {
  std::vector<RgbdCamera::MipLevel> levels;
  levels.push_back({t.width, t.height, t.rgb});
  while (levels.back().width > 1 || levels.back().height > 1) {
    const RgbdCamera::MipLevel& src = levels.back();
    RgbdCamera::MipLevel dst;
    dst.width = std::max(1, src.width / 2);
    dst.height = std::max(1, src.height / 2);
    dst.rgb.resize(3 * static_cast<std::size_t>(dst.width) * static_cast<std::size_t>(dst.height));
    for (int y = 0; y < dst.height; ++y) {
      const int sy0 = std::min(2 * y, src.height - 1);
      const int sy1 = (y == dst.height - 1) ? src.height - 1 : std::min(2 * y + 1, src.height - 1);
      for (int x = 0; x < dst.width; ++x) {
        const int sx0 = std::min(2 * x, src.width - 1);
        const int sx1 = (x == dst.width - 1) ? src.width - 1 : std::min(2 * x + 1, src.width - 1);
        for (int c = 0; c < 3; ++c) {
          unsigned sum = 0, n = 0;
          for (int sy = sy0; sy <= sy1; ++sy) {
            for (int sx = sx0; sx <= sx1; ++sx) {
              sum += src.rgb[3 * (static_cast<std::size_t>(sy) * src.width + sx) + c];
              ++n;
            }
          }
          dst.rgb[3 * (static_cast<std::size_t>(y) * dst.width + x) + c] =
              static_cast<std::uint8_t>((sum + n / 2) / n);
        }
      }
    }
    levels.push_back(std::move(dst));
  }
  return levels;
}

/// Exact grid traversal (Amanatides & Woo 1987) from p_m along d (not normalised): the parameter t
/// of the first solid cell boundary, so that the hit is p_m + t * d, and the face it belongs to.
/// On a tie (an exact cell corner) the x step goes first, as World::cast_ray does. Ends at the
/// grid's edge at the latest, since everything outside the grid is solid.
ColumnHit cast(const World& world, const WallFaces& faces, Vec2 p_m, Vec2 d) {
  const GridGeometry& g = world.geometry();
  const double r = g.resolution_m();
  const Vec2 o = g.origin();
  Cell c = g.cell_at_unchecked(p_m);
  ColumnHit hit;
  if (world.solid(c)) return hit;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const int step_x = d.x > 0.0 ? 1 : (d.x < 0.0 ? -1 : 0);
  const int step_y = d.y > 0.0 ? 1 : (d.y < 0.0 ? -1 : 0);
  double t_max_x = step_x != 0 ? (o.x + (c.x + (step_x > 0 ? 1 : 0)) * r - p_m.x) / d.x : kInf;
  double t_max_y = step_y != 0 ? (o.y + (c.y + (step_y > 0 ? 1 : 0)) * r - p_m.y) / d.y : kInf;
  const double t_delta_x = step_x != 0 ? r / std::abs(d.x) : kInf;
  const double t_delta_y = step_y != 0 ? r / std::abs(d.y) : kInf;
  const int max_steps = g.width() + g.height() + 4;
  for (int k = 0; k < max_steps; ++k) {
    const bool x_step = t_max_x <= t_max_y;
    const Cell next = x_step ? Cell{c.x + step_x, c.y} : Cell{c.x, c.y + step_y};
    const double t = x_step ? t_max_x : t_max_y;
    if (world.solid(next)) {
      const FaceSide side = x_step ? (step_x > 0 ? FaceSide::kPlusX : FaceSide::kMinusX)
                                   : (step_y > 0 ? FaceSide::kPlusY : FaceSide::kMinusY);
      hit.z_m = std::max(t, 0.0);
      hit.side = static_cast<int>(side);
      hit.face = faces.face_of_side[4 * g.index_of(c) + static_cast<std::size_t>(side)];
      hit.point_m = p_m + d * hit.z_m;
      return hit;
    }
    c = next;
    if (x_step) {
      t_max_x += t_delta_x;
    } else {
      t_max_y += t_delta_y;
    }
  }
  return hit;  // unreachable for a consistent grid; reads as no depth
}

}  // namespace

std::optional<std::string> validate(const RgbdCameraOptions& o) {
  const PinholeIntrinsics& k = o.intrinsics;
  if (k.width_px < 2 || k.height_px < 2 || k.width_px > 8192 || k.height_px > 8192) {
    return "intrinsics: image size must be in [2, 8192] pixels, got " +
           std::to_string(k.width_px) + " x " + std::to_string(k.height_px);
  }
  if (!positive(k.fx_px) || !positive(k.fy_px)) return "intrinsics: fx_px and fy_px must be > 0";
  if (!std::isfinite(k.cx_px) || !std::isfinite(k.cy_px)) {
    return "intrinsics: cx_px and cy_px must be finite";
  }
  if (!positive(o.wall_height_m)) {
    return "wall_height_m must be > 0, got " + std::to_string(o.wall_height_m);
  }
  if (!(positive(o.mount_height_m) && o.mount_height_m < o.wall_height_m)) {
    return "mount_height_m must be in (0, wall_height_m), got " + std::to_string(o.mount_height_m);
  }
  if (!non_negative(o.min_depth_m) || !positive(o.max_depth_m) || !(o.min_depth_m < o.max_depth_m)) {
    return "need 0 <= min_depth_m < max_depth_m, got " + std::to_string(o.min_depth_m) + " and " +
           std::to_string(o.max_depth_m);
  }
  if (!non_negative(o.depth_noise_coefficient_1_per_m)) {
    return "depth_noise_coefficient_1_per_m must be >= 0";
  }
  if (!non_negative(o.inverse_depth_step_1_per_m)) return "inverse_depth_step_1_per_m must be >= 0";
  return std::nullopt;
}

Result<RgbdCamera> RgbdCamera::create(World world, const RgbdCameraOptions& options,
                                      std::vector<WallTexture> textures,
                                      std::vector<Poster> posters) {
  if (auto problem = validate(options)) return input_error("rgbd camera: " + *problem);
  for (std::size_t k = 0; k < textures.size(); ++k) {
    if (!textures[k].consistent()) {
      return input_error("texture " + std::to_string(k) + " (" + textures[k].name +
                         "): buffer does not match width x height, or the picture is empty");
    }
  }
  RgbdCamera camera;
  camera.faces_ = find_wall_faces(world);
  for (std::size_t k = 0; k < posters.size(); ++k) {
    if (auto problem = validate(posters[k], camera.faces_.faces, textures.size(),
                                options.wall_height_m)) {
      return input_error("poster " + std::to_string(k) + ": " + *problem);
    }
  }
  camera.world_ = std::move(world);
  camera.options_ = options;
  camera.posters_of_face_.resize(camera.faces_.faces.size());
  for (std::size_t k = 0; k < posters.size(); ++k) {
    camera.posters_of_face_[static_cast<std::size_t>(posters[k].face)].push_back(
        static_cast<int>(k));
  }
  std::vector<bool> used(textures.size(), false);
  for (const Poster& p : posters) used[static_cast<std::size_t>(p.texture)] = true;
  camera.pyramids_.resize(textures.size());
  for (std::size_t k = 0; k < textures.size(); ++k) {
    camera.texture_width_.push_back(textures[k].width);
    camera.texture_height_.push_back(textures[k].height);
    if (used[k]) camera.pyramids_[k] = build_pyramid(textures[k]);
  }
  camera.posters_ = std::move(posters);
  return camera;
}

RgbdFrame RgbdCamera::render(const Pose2& T_world_robot, double neck_pan_rad, double t_s,
                             Rng& rng) const {
  RgbdFrame frame;
  render_into(T_world_robot, neck_pan_rad, t_s, rng, frame);
  return frame;
}

void RgbdCamera::render_into(const Pose2& T_world_robot, double neck_pan_rad, double t_s,
                             Rng& rng, RgbdFrame& frame) const {
  const RgbdCameraOptions& o = options_;
  const PinholeIntrinsics& k = o.intrinsics;
  const int width = k.width_px, height = k.height_px;
  frame.t_s = t_s;
  frame.width = width;
  frame.height = height;
  frame.intrinsics = k;
  frame.rgb.resize(3 * frame.pixel_count());
  frame.depth_m.resize(frame.pixel_count());

  const Pose2 cam = camera_pose(T_world_robot, neck_pan_rad);
  const Vec2 forward{std::cos(cam.theta), std::sin(cam.theta)};
  const Vec2 right{forward.y, -forward.x};  // image x points right: clockwise from forward
  const Vec2 eye = cam.translation();

  // Per column: one ray, the wall it hits and what the wall shows there.
  std::vector<Column> columns(static_cast<std::size_t>(width));
  for (int u = 0; u < width; ++u) {
    Column& col = columns[static_cast<std::size_t>(u)];
    const double tan_u = (u - k.cx_px) / k.fx_px;
    const Vec2 d = forward + right * tan_u;  // unit forward component: t is the depth z
    const ColumnHit hit = cast(world_, faces_, eye, d);
    if (hit.face < 0) {
      col.inside_solid = true;
      continue;
    }
    col.z_m = hit.z_m;
    const double shade = kFaceShade[hit.side];
    for (int c = 0; c < 3; ++c) {
      col.wall_rgb[static_cast<std::size_t>(c)] = static_cast<std::uint8_t>(
          std::lround(o.wall_rgb[static_cast<std::size_t>(c)] * shade));
    }
    const WallFace& face = faces_.faces[static_cast<std::size_t>(hit.face)];
    const double s_m = (hit.point_m - face.start_m).dot(face.along());
    for (const int pi : posters_of_face_[static_cast<std::size_t>(hit.face)]) {
      const Poster& p = posters_[static_cast<std::size_t>(pi)];
      const double left_m = p.center_m - 0.5 * p.width_m;
      if (s_m < left_m || s_m >= left_m + p.width_m) continue;
      const auto t = static_cast<std::size_t>(p.texture);
      const double tex_w = texture_width_[t], tex_h = texture_height_[t];
      col.poster = pi;
      col.tex_x0 = (s_m - left_m) / p.width_m * tex_w;
      col.poster_bottom_m = p.bottom_m;
      col.poster_top_m = p.bottom_m + p.height_m;
      col.texels_per_m_v = tex_h / p.height_m;
      // Pixel footprint on the wall: z / (fx |n . d|) across, z / fy up (see header).
      const double across_m = hit.z_m / (k.fx_px * std::max(1e-6, std::abs(face.normal.dot(d))));
      const double up_m = hit.z_m / k.fy_px;
      const double rho = std::max(across_m * tex_w / p.width_m, up_m * col.texels_per_m_v);
      const double lambda = rho > 1.0 ? std::log2(rho) : 0.0;
      const std::vector<MipLevel>& pyramid = pyramids_[t];
      const int last = static_cast<int>(pyramid.size()) - 1;
      const int level = std::min(static_cast<int>(lambda), last);
      const double blend = level < last ? lambda - level : 0.0;
      const int w0 = pyramid[0].width, h0 = pyramid[0].height;
      col.taps[0] = make_tap(pyramid[static_cast<std::size_t>(level)], w0, h0, col.tex_x0,
                             static_cast<float>(1.0 - blend));
      col.tap_count = 1;
      if (blend > 0.0) {
        col.taps[1] = make_tap(pyramid[static_cast<std::size_t>(level) + 1], w0, h0, col.tex_x0,
                               static_cast<float>(blend));
        col.tap_count = 2;
      }
      break;
    }
  }

  const double mount = o.mount_height_m, top = o.wall_height_m;
  const double noise_k = o.depth_noise_coefficient_1_per_m;
  const double step = o.inverse_depth_step_1_per_m;
  double spare_gaussian = 0.0;
  bool have_spare = false;
  const auto measure = [&](double z) -> float {
    if (!(z >= o.min_depth_m && z <= o.max_depth_m)) return 0.0F;
    double zm = z;
    if (noise_k > 0.0) {
      double g = 0.0;
      if (have_spare) {
        g = spare_gaussian;
        have_spare = false;
      } else {
        gaussian_pair(rng, g, spare_gaussian);
        have_spare = true;
      }
      zm += g * noise_k * z * z;
    }
    if (step > 0.0) zm = 1.0 / (std::max(1.0, std::round(1.0 / (zm * step))) * step);
    return zm > 0.0 ? static_cast<float>(zm) : 0.0F;
  };

  for (int v = 0; v < height; ++v) {
    const double y_c = (v - k.cy_px) / k.fy_px;  // image y points down
    const double floor_z = y_c > 0.0 ? mount / y_c : 0.0;
    const double ceiling_z = y_c < 0.0 ? (mount - top) / y_c : 0.0;
    std::uint8_t* rgb = &frame.rgb[3 * static_cast<std::size_t>(v) * width];
    float* depth = &frame.depth_m[static_cast<std::size_t>(v) * width];
    for (int u = 0; u < width; ++u, rgb += 3) {
      const Column& col = columns[static_cast<std::size_t>(u)];
      if (col.inside_solid) {
        rgb[0] = rgb[1] = rgb[2] = 0;
        depth[u] = 0.0F;
        continue;
      }
      const double h = mount - y_c * col.z_m;  // height where this pixel's ray meets the wall
      if (h < 0.0) {
        std::copy(o.floor_rgb.begin(), o.floor_rgb.end(), rgb);
        depth[u] = measure(floor_z);
        continue;
      }
      if (h > top) {
        std::copy(o.ceiling_rgb.begin(), o.ceiling_rgb.end(), rgb);
        depth[u] = measure(ceiling_z);
        continue;
      }
      depth[u] = measure(col.z_m);
      if (col.poster < 0 || h < col.poster_bottom_m || h >= col.poster_top_m) {
        std::copy(col.wall_rgb.begin(), col.wall_rgb.end(), rgb);
        continue;
      }
      const double tex_y0 = (col.poster_top_m - h) * col.texels_per_m_v;
      float sum[3] = {0.0F, 0.0F, 0.0F};
      for (int j = 0; j < col.tap_count; ++j) add_sample(col.taps[j], tex_y0, sum);
      for (int c = 0; c < 3; ++c) {
        rgb[c] = static_cast<std::uint8_t>(std::clamp(sum[c] + 0.5F, 0.0F, 255.0F));
      }
    }
  }
}

}  // namespace tessera
