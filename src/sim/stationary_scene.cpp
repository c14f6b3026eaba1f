#include "tessera/sim/stationary_scene.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "tessera/core/assert.hpp"
#include "tessera/sim/builtin_world.hpp"
#include "tessera/sim/wall_faces.hpp"

namespace tessera {
namespace {

constexpr double kResolutionM = 0.05;
constexpr int kWidthCells = 160;   // 8 m
constexpr int kHeightCells = 120;  // 6 m
constexpr double kEastX = 7.95, kNorthY = 5.95, kWestX = 0.05, kSouthY = 0.05;

World stationary_room() {
  return walled_room(kWidthCells, kHeightCells, kResolutionM, "stationary_room");
}

/// A poster of the given size centred at `center` (a point on the wall) at camera height (1.03 m,
/// thesis section 3.1.3).
Poster poster_at(const std::vector<WallFace>& faces, Vec2 center, double width_m, double height_m,
                 int texture) {
  Poster p;
  p.face = nearest_wall_face(faces, center);
  const WallFace& f = faces[static_cast<std::size_t>(p.face)];
  p.center_m = (center - f.start_m).dot(f.along());
  p.width_m = width_m;
  p.height_m = height_m;
  p.bottom_m = 1.03 - 0.5 * height_m;
  p.texture = texture;
  return p;
}

}  // namespace

Result<StationaryScene> make_stationary_scene(std::vector<WallTexture> photos,
                                              const RgbdCameraOptions& camera) {
  if (photos.size() < 4) {
    return input_error("stationary scene: need 4 photos, got " + std::to_string(photos.size()));
  }
  photos.resize(4);
  const World world = stationary_room();
  const std::vector<WallFace> faces = find_wall_faces(world).faces;
  const std::vector<Poster> posters = {
      poster_at(faces, {kEastX, 3.0}, 1.6, 1.2, 0),   // desk
      poster_at(faces, {4.0, kNorthY}, 2.0, 1.5, 1),  // cabinet
      poster_at(faces, {kWestX, 3.7}, 1.2, 0.9, 2),   // two posters side by side
      poster_at(faces, {kWestX, 2.3}, 1.2, 0.9, 3),
  };
  Result<RgbdCamera> cam = RgbdCamera::create(world, camera, std::move(photos), posters);
  if (!cam) return cam.error();
  constexpr double kPi = std::numbers::pi;
  std::vector<StationaryView> views = {
      {"desk (1.5 m)", {kEastX - 1.5, 3.0, 0.0}, 1.5, true},
      {"cabinet (2.5 m)", {4.0, kNorthY - 2.5, 0.5 * kPi}, 2.5, true},
      {"two posters (3 m)", {kWestX + 3.0, 3.0, -kPi}, 3.0, true},
      {"blank wall (1.5 m)", {2.0, kSouthY + 1.5, -0.5 * kPi}, 1.5, false},
      {"blank wall and floor (3 m)", {6.0, kSouthY + 3.0, -0.5 * kPi}, 3.0, false},
      // Facing the south-west corner along the diagonal, 2 m away (1.41 m from each wall).
      {"blank corner (2 m)", {kWestX + std::sqrt(2.0), kSouthY + std::sqrt(2.0), -0.75 * kPi},
       2.0, false},
  };
  return StationaryScene{std::move(cam).value(), std::move(views)};
}

std::optional<std::string> validate(const StationaryCaptureOptions& o) {
  if (o.frames < 1) return "frames must be >= 1";
  if (!(std::abs(o.neck_turn_rad) <= 0.5 * std::numbers::pi)) {
    return "neck_turn_rad must be within +-pi/2 (the thesis' 180-degree servo)";
  }
  if (!(o.rgb_noise_sigma >= 0.0)) return "rgb_noise_sigma must be >= 0";
  return std::nullopt;
}

std::vector<StationaryCapture> capture_stationary_view(const RgbdCamera& camera,
                                                       const StationaryView& view,
                                                       const StationaryCaptureOptions& o,
                                                       std::uint64_t seed) {
  TESSERA_ASSERT(!validate(o));
  const Rng base(seed);
  std::vector<StationaryCapture> out;
  out.reserve(static_cast<std::size_t>(o.frames));
  for (int k = 0; k < o.frames; ++k) {
    Rng rng = base.fork(static_cast<std::uint64_t>(k));
    StationaryCapture c;
    c.neck_pan_rad = (k % 2 == 1) ? o.neck_turn_rad : 0.0;
    c.frame = camera.render(view.T_world_robot, c.neck_pan_rad, static_cast<double>(k), rng);
    if (o.rgb_noise_sigma > 0.0) {
      for (std::uint8_t& v : c.frame.rgb) {
        const double noisy = std::round(v + rng.gaussian(o.rgb_noise_sigma));
        v = static_cast<std::uint8_t>(std::clamp(noisy, 0.0, 255.0));
      }
    }
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace tessera
