#pragma once
// The thesis' stationary test scene (section 5.1.3, Figures 5.2 to 5.4; results in Table 5.5) in
// the simulator: a robot that does not drive faces "a desk that was moderately cluttered", "a
// cabinet that was cluttered" and "an uncluttered blank white wall", and captures frame after
// frame, sometimes turning its neck a little. Here the cluttered views are real photographs hung
// as posters (sim/poster.hpp) at 1.5 to 3 m, and the blank views are plain walls: one filling the
// view at 1.5 m, one at 3 m with the floor in view, and a blank corner at 2 m.
//
// The room is 8 m x 6 m at 5 cm with one-cell walls (free space x in [0.05, 7.95], y in [0.05,
// 5.95]); the camera is the default Kinect v1 on the thesis' neck (sim/rgbd_camera.hpp).
// fusion/stationary_matching.hpp measures what the matcher makes of the captures.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tessera/core/pose2.hpp"
#include "tessera/core/result.hpp"
#include "tessera/sensors/rgbd_frame.hpp"
#include "tessera/sim/rgbd_camera.hpp"
#include "tessera/sim/wall_texture.hpp"

namespace tessera {

/// One view of the test: where the robot stands (facing the view, neck at 0) and what it sees.
struct StationaryView {
  std::string name;       // "desk (1.5 m)", "blank wall (1.5 m)", ...
  Pose2 T_world_robot;
  double distance_m = 0.0;  // from the camera to the wall it faces, along the optical axis
  bool textured = false;    // a poster is in view (false: blank walls only)
};

/// The room, its posters and the views.
struct StationaryScene {
  RgbdCamera camera;
  std::vector<StationaryView> views;
};

/// Builds the scene. `photos` hang as posters: photos[0] as the desk (1.6 m x 1.2 m on the east
/// wall, seen from 1.5 m), photos[1] as the cabinet (2.0 m x 1.5 m on the north wall, from 2.5 m),
/// photos[2] and photos[3] side by side (1.2 m x 0.9 m each on the west wall, from 3 m); the south
/// wall stays blank. Each poster is stretched to its size. Input errors: fewer than 4 photos
/// ("stationary scene: need 4 photos, got 2"), an inconsistent photo, invalid camera options
/// (RgbdCamera::create's errors). Cost: building the textures' mip-map pyramids.
[[nodiscard]] Result<StationaryScene> make_stationary_scene(std::vector<WallTexture> photos,
                                                            const RgbdCameraOptions& camera = {});

struct StationaryCaptureOptions {
  int frames = 10;
  /// 0: the neck stays still (true motion between captures: identity). Otherwise the neck turns
  /// between pan 0 and this angle on alternate captures (a pure rotation about the pan axis, which
  /// runs through the optical centre).
  double neck_turn_rad = 0.0;
  /// Colour noise of the sensor: zero-mean Gaussian, in grey levels, added to each channel of each
  /// pixel and rounded (the renderer's images are noise-free). 2 levels is a modest assumption
  /// for the Kinect v1's colour camera; it also gives a blank wall its specks.
  double rgb_noise_sigma = 2.0;
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const StationaryCaptureOptions& o);

/// One capture: the frame and the neck angle it was taken with (the robot is at view.T_world_robot).
struct StationaryCapture {
  RgbdFrame frame;
  double neck_pan_rad = 0.0;
};

/// Renders o.frames captures of `view`, stamped 0, 1, 2, ... s. Capture k draws its depth noise
/// and colour noise from Rng(seed).fork(k), so captures differ in noise only. Precondition:
/// validate(o) is empty. Cost: o.frames renders plus O(pixels) per frame for the colour noise.
[[nodiscard]] std::vector<StationaryCapture> capture_stationary_view(
    const RgbdCamera& camera, const StationaryView& view, const StationaryCaptureOptions& o,
    std::uint64_t seed);

}  // namespace tessera
