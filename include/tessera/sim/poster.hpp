#pragma once
// Posters: real photographs hung on the walls of a simulated world, so that the simulated RGB-D
// camera sees feature-rich views where a poster hangs and a blank white wall elsewhere (the
// thesis' stationary test faces a cluttered desk, a cabinet and a blank wall, section 5.2.3).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tessera/sim/wall_faces.hpp"
#include "tessera/sim/wall_texture.hpp"

namespace tessera {

/// A picture on one wall face. The poster spans [center_m - width_m / 2, center_m + width_m / 2]
/// along the face from its start (its left end seen from the room) and [bottom_m, bottom_m +
/// height_m] above the floor; the texture fills it, column 0 at the left, row 0 at the top.
struct Poster {
  int face = 0;
  double center_m = 0.0;
  double width_m = 0.8;
  double bottom_m = 0.7;
  double height_m = 0.6;
  int texture = 0;
};

/// Empty when the poster fits: a valid face and texture index, positive size, inside the face
/// along it and between floor and wall_height_m.
[[nodiscard]] std::optional<std::string> validate(const Poster& p, const std::vector<WallFace>& faces,
                                                  std::size_t texture_count, double wall_height_m);

/// Random placement: every face at least min_face_length_m long gets a poster with probability
/// `probability`; its width is uniform in [min_width_m, max_width_m] (shrunk to fit the face with
/// margin_m on each side), its height follows the texture's aspect ratio (clamped to
/// max_height_m), its centre height is eye_height_m plus uniform jitter in +-eye_height_jitter_m,
/// its place along the face uniform, its texture uniform among the textures.
struct PosterPlacementOptions {
  double probability = 0.6;
  double min_face_length_m = 1.0;
  double min_width_m = 0.6;
  double max_width_m = 1.2;
  double max_height_m = 1.2;
  double margin_m = 0.1;
  /// Around the camera's height on the thesis' neck (section 3.1.3: 1.03 m).
  double eye_height_m = 1.03;
  double eye_height_jitter_m = 0.15;
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const PosterPlacementOptions& o);

/// Posters for `faces`, a deterministic function of the faces, the textures' sizes, the options and
/// the seed (one Rng stream per face, so a face's poster does not depend on the others). No
/// posters when `textures` is empty. Precondition: validate(o) is empty and every texture is
/// consistent(). Cost: O(faces).
[[nodiscard]] std::vector<Poster> place_posters(const std::vector<WallFace>& faces,
                                                const std::vector<WallTexture>& textures,
                                                const PosterPlacementOptions& o,
                                                std::uint64_t seed);

}  // namespace tessera
