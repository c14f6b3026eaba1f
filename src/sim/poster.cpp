#include "tessera/sim/poster.hpp"

#include <algorithm>
#include <cmath>

#include "tessera/core/assert.hpp"
#include "tessera/core/rng.hpp"

namespace tessera {
namespace {

bool positive(double v) { return v > 0.0 && std::isfinite(v); }
bool non_negative(double v) { return v >= 0.0 && std::isfinite(v); }

/// Posters never touch a face's ends or the floor and ceiling closer than this: a picture frame.
constexpr double kEdgeTolerance_m = 1e-9;

}  // namespace

std::optional<std::string> validate(const Poster& p, const std::vector<WallFace>& faces,
                                    std::size_t texture_count, double wall_height_m) {
  if (p.face < 0 || static_cast<std::size_t>(p.face) >= faces.size()) {
    return "face " + std::to_string(p.face) + " does not exist (the world has " +
           std::to_string(faces.size()) + " wall faces)";
  }
  if (p.texture < 0 || static_cast<std::size_t>(p.texture) >= texture_count) {
    return "texture " + std::to_string(p.texture) + " does not exist (" +
           std::to_string(texture_count) + " textures given)";
  }
  if (!positive(p.width_m) || !positive(p.height_m)) {
    return "width_m and height_m must be > 0, got " + std::to_string(p.width_m) + " and " +
           std::to_string(p.height_m);
  }
  if (!std::isfinite(p.center_m) || !std::isfinite(p.bottom_m)) {
    return "center_m and bottom_m must be finite";
  }
  const double length_m = faces[static_cast<std::size_t>(p.face)].length_m();
  if (p.center_m - 0.5 * p.width_m < -kEdgeTolerance_m ||
      p.center_m + 0.5 * p.width_m > length_m + kEdgeTolerance_m) {
    return "poster [" + std::to_string(p.center_m - 0.5 * p.width_m) + ", " +
           std::to_string(p.center_m + 0.5 * p.width_m) + "] m does not fit on face " +
           std::to_string(p.face) + " of length " + std::to_string(length_m) + " m";
  }
  if (p.bottom_m < -kEdgeTolerance_m || p.bottom_m + p.height_m > wall_height_m + kEdgeTolerance_m) {
    return "poster from " + std::to_string(p.bottom_m) + " to " +
           std::to_string(p.bottom_m + p.height_m) + " m does not fit between floor and wall top " +
           std::to_string(wall_height_m) + " m";
  }
  return std::nullopt;
}

std::optional<std::string> validate(const PosterPlacementOptions& o) {
  if (!(o.probability >= 0.0 && o.probability <= 1.0)) {
    return "probability must be in [0, 1], got " + std::to_string(o.probability);
  }
  if (!non_negative(o.min_face_length_m)) return "min_face_length_m must be >= 0";
  if (!positive(o.min_width_m) || !(o.max_width_m >= o.min_width_m) || !std::isfinite(o.max_width_m)) {
    return "need 0 < min_width_m <= max_width_m, got " + std::to_string(o.min_width_m) + " and " +
           std::to_string(o.max_width_m);
  }
  if (!positive(o.max_height_m)) return "max_height_m must be > 0";
  if (!non_negative(o.margin_m)) return "margin_m must be >= 0";
  if (!positive(o.eye_height_m)) return "eye_height_m must be > 0";
  if (!non_negative(o.eye_height_jitter_m)) return "eye_height_jitter_m must be >= 0";
  return std::nullopt;
}

std::vector<Poster> place_posters(const std::vector<WallFace>& faces,
                                  const std::vector<WallTexture>& textures,
                                  const PosterPlacementOptions& o, std::uint64_t seed) {
  TESSERA_ASSERT(!validate(o).has_value());
  std::vector<Poster> posters;
  if (textures.empty()) return posters;
  const Rng root(seed);
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const double length_m = faces[i].length_m();
    if (length_m < o.min_face_length_m) continue;
    Rng rng = root.fork(i);
    // Every draw is made whatever the outcome, so the sequence is fixed per face.
    const double coin = rng.uniform(0.0, 1.0);
    const double width_draw = rng.uniform(o.min_width_m, o.max_width_m);
    const double place_draw = rng.uniform(0.0, 1.0);
    const double height_draw = rng.uniform(-o.eye_height_jitter_m, o.eye_height_jitter_m);
    const int texture = rng.uniform_int(0, static_cast<int>(textures.size()) - 1);
    if (coin >= o.probability) continue;
    const double room_m = length_m - 2.0 * o.margin_m;
    if (room_m <= 0.0) continue;
    const WallTexture& t = textures[static_cast<std::size_t>(texture)];
    TESSERA_ASSERT(t.consistent());
    Poster p;
    p.face = static_cast<int>(i);
    p.texture = texture;
    p.width_m = std::min(width_draw, room_m);
    p.height_m = std::min(o.max_height_m, p.width_m * t.height / t.width);
    p.center_m = o.margin_m + 0.5 * p.width_m + place_draw * (room_m - p.width_m);
    p.bottom_m = std::max(0.0, o.eye_height_m + height_draw - 0.5 * p.height_m);
    posters.push_back(p);
  }
  return posters;
}

}  // namespace tessera
