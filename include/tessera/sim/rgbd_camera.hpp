#pragma once
// A simulated RGB-D camera (Kinect v1) on the thesis' pan "neck": it renders an RgbdFrame of a
// World whose solid cells are walls extruded from the floor to wall_height_m, with a plain floor
// and ceiling, plain walls, and real photographs hung on some walls as posters (sim/poster.hpp).
//
// Geometry. The camera sits on the neck's pan axis above the robot's centre, mount_height_m above
// the floor (thesis section 3.1.3: 1.030 m), its optical axis horizontal; T_world_camera (in the
// plane) = T_world_robot * Pose2{0, 0, neck_pan_rad}, pan 0 = robot forward, counter-clockwise
// positive. The image follows sensors/pinhole_camera.hpp (x right, y down, z forward).
//
// Rendering (a ray caster, as in Wolfenstein-style renderers): per image column one 2D ray along
// the column's azimuth, cast exactly through the grid (Amanatides & Woo 1987, as World::cast_ray);
// the ray's parameter is scaled so that it equals the depth along the optical axis. Per row, the
// pixel is on the wall when its viewing ray meets the wall's vertical line between 0 and
// wall_height_m, else on the floor (depth mount_height_m / y) or the ceiling. Depth is z along the
// optical axis, as RgbdFrame requires. Posters are sampled bilinearly from a mip-map pyramid
// (box-filtered halvings), blending two levels chosen by the pixel's footprint on the wall
// (trilinear filtering, Williams 1983, "Pyramidal parametrics"), so that a photo seen from 1-4 m
// stays sharp and does not alias.
//
// Depth noise. The Kinect v1's random depth error grows with the square of the range (Khoshelham &
// Elberink 2012, "Accuracy and Resolution of Kinect Depth Data for Indoor Mapping Applications",
// Sensors 12(2), 1437: "from a few millimeters up to about 4 cm at the maximum range"; the model
// sigma_z = 1.425e-3 * z^2 m, z in m, gives 3.6 cm at 5 m). Optional quantisation of the measured
// disparity: the depth resolution falls off as z^2, to about 7 cm at the maximum range of 5 m
// (ibid., conclusions), i.e. steps of 1/z of 0.07 / 5^2 = 2.8e-3 1/m. Outside [min_depth_m,
// max_depth_m] (of the true depth) the pixel reads 0, no reading.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tessera/core/pose2.hpp"
#include "tessera/core/result.hpp"
#include "tessera/core/rng.hpp"
#include "tessera/sensors/pinhole_camera.hpp"
#include "tessera/sensors/rgbd_frame.hpp"
#include "tessera/sim/poster.hpp"
#include "tessera/sim/wall_faces.hpp"
#include "tessera/sim/wall_texture.hpp"
#include "tessera/sim/world.hpp"

namespace tessera {

/// Defaults: a Kinect v1 (640 x 480, 57 x 43 degrees, depth 0.5 to 4.5 m) on the thesis' neck.
struct RgbdCameraOptions {
  PinholeIntrinsics intrinsics = PinholeIntrinsics::kinect_v1();
  /// Height of the optical centre above the floor (thesis section 3.1.3).
  double mount_height_m = 1.03;
  /// Walls are the solid cells extruded to this height; the ceiling lies on top.
  double wall_height_m = 2.5;
  /// The Kinect v1's operating range (Khoshelham & Elberink 2012: 0.5 to 5 m; the thesis' 4.5 m
  /// is the range OpenNI reports reliably). Depths outside read 0.
  double min_depth_m = 0.5;
  double max_depth_m = 4.5;
  /// sigma_z = depth_noise_coefficient_1_per_m * z^2 (Khoshelham & Elberink 2012); 0: exact depth.
  double depth_noise_coefficient_1_per_m = 1.425e-3;
  /// Steps of 1/z (disparity quantisation); 0: none. The Kinect v1: 2.8e-3 (see above).
  double inverse_depth_step_1_per_m = 0.0;
  /// Plain surfaces (sRGB). A wall's brightness depends on which way it faces (a light from
  /// above one corner), so that corners stay visible; every face of one orientation is one colour.
  std::array<std::uint8_t, 3> wall_rgb = {236, 234, 228};
  std::array<std::uint8_t, 3> floor_rgb = {128, 116, 100};
  std::array<std::uint8_t, 3> ceiling_rgb = {246, 246, 246};
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const RgbdCameraOptions& o);

/// The camera and the scene it looks at (the world, its wall faces, the textures and the posters),
/// prepared once (faces found, texture pyramids built) and rendered many times. Immutable after
/// creation; render() is const and thread-safe for distinct Rng and frames.
class RgbdCamera {
 public:
  /// Input errors: invalid options ("rgbd camera: <what>"), an inconsistent texture ("texture k:
  /// buffer does not match width x height"), a poster that does not fit ("poster k: <what>").
  [[nodiscard]] static Result<RgbdCamera> create(World world, const RgbdCameraOptions& options,
                                                 std::vector<WallTexture> textures,
                                                 std::vector<Poster> posters);

  [[nodiscard]] const World& world() const { return world_; }
  [[nodiscard]] const RgbdCameraOptions& options() const { return options_; }
  [[nodiscard]] const std::vector<WallFace>& faces() const { return faces_.faces; }
  [[nodiscard]] const std::vector<Poster>& posters() const { return posters_; }
  [[nodiscard]] std::size_t texture_count() const { return pyramids_.size(); }
  /// True when texture k hangs on a wall (only those are kept, as mip-map pyramids).
  [[nodiscard]] bool texture_used(std::size_t k) const { return !pyramids_[k].empty(); }

  /// T_world_camera in the plane: the robot pose turned by the neck's pan angle.
  [[nodiscard]] static Pose2 camera_pose(const Pose2& T_world_robot, double neck_pan_rad) {
    return T_world_robot * Pose2{0.0, 0.0, normalize_angle(neck_pan_rad)};
  }

  /// The frame seen from T_world_robot with the neck at neck_pan_rad, stamped t_s. Draws one
  /// Gaussian per valid depth pixel from rng when depth noise is on (none otherwise). A camera
  /// inside a solid cell sees black and reads no depth. Cost: O(columns * cells crossed + pixels).
  [[nodiscard]] RgbdFrame render(const Pose2& T_world_robot, double neck_pan_rad, double t_s,
                                 Rng& rng) const;
  /// As render(), reusing `frame`'s buffers (no allocation once they have the right size).
  void render_into(const Pose2& T_world_robot, double neck_pan_rad, double t_s, Rng& rng,
                   RgbdFrame& frame) const;

  /// One level of a texture's mip-map pyramid: level 0 is the picture, each next level half the
  /// size (a 2 x 2 box filter).
  struct MipLevel {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgb;  // 3 bytes per pixel, top row first
  };

 private:
  RgbdCamera() = default;

  World world_;
  RgbdCameraOptions options_;
  WallFaces faces_;
  std::vector<Poster> posters_;
  std::vector<std::vector<int>> posters_of_face_;
  /// One pyramid per texture; empty for a texture no poster uses (photo folders are large).
  std::vector<std::vector<MipLevel>> pyramids_;
  std::vector<int> texture_width_, texture_height_;
};

}  // namespace tessera
