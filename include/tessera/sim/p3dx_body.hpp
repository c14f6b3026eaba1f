#pragma once
// The simulated body of the Fusion SLAM thesis' robot, a Pioneer 3-DX (thesis section 3.1.1): a
// round body that stops against what it drives into, the 8 forward sonars (thesis Figure 3.3, at
// -90, -50, -30, -10, 10, 30, 50 and 90 degrees) and the 5 front and 5 rear bumpers (Figure 3.4),
// sensed in a World for nav/reactive_avoidance.hpp. Sonar beams are cones: a reading is the
// nearest echo within the cone, so a wall beside the beam's axis reads as an obstacle on it, as a
// real sonar's does. Deterministic for the Rng. No I/O.
#include <optional>
#include <string>
#include <vector>

#include "tessera/core/pose2.hpp"
#include "tessera/core/rng.hpp"
#include "tessera/nav/reactive_avoidance.hpp"
#include "tessera/sim/world.hpp"

namespace tessera {

struct P3dxBodyOptions {
  /// The body as a disc: the P3DX's swing radius is 0.267 m (the manufacturer's figure); a disc
  /// of 0.25 m fits its 0.455 x 0.381 m footprint's width and keeps clear of a 0.3 m route
  /// clearance.
  double body_radius_m = 0.25;
  /// Sonar bearings, robot frame, counter-clockwise from straight ahead (thesis Figure 3.3).
  std::vector<double> sonar_bearings_rad = {1.5708,  0.8727,  0.5236,  0.1745,
                                            -0.1745, -0.5236, -0.8727, -1.5708};
  /// The sonars sit on the body's edge this far from the centre; ranges are measured from there.
  double sonar_radius_m = 0.2;
  /// Half the beam's cone (a Polaroid 6500's main lobe is about 15 degrees wide) and rays per cone.
  double sonar_half_cone_rad = 0.13;
  int sonar_rays = 5;
  double sonar_max_range_m = 5.0;
  /// Gaussian range noise, standard deviation.
  double sonar_noise_m = 0.01;
  /// A bumper is pressed when a solid cell is within body_radius_m + this of the centre, inside
  /// its sector: the front ring's five equal sectors span +-bumper_half_arc_rad about straight
  /// ahead (index 0 left-most), the rear ring's the same about straight behind (index 0 left-most
  /// seen from above with the robot facing forward). The P3DX's bumpers wrap its front and rear
  /// corners, not its flanks (thesis Figure 3.4): a wall brushing its side presses none.
  double bumper_contact_m = 0.02;
  double bumper_half_arc_rad = 1.2566;  // 72 degrees
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const P3dxBodyOptions& o);

/// The sonars and bumpers of a robot at T_world_robot in `world` (no depth readings: the caller
/// adds the camera's if it has them). Sonar without an echo within range reads +infinity.
/// Precondition: !validate(o). Cost: O(sonars x rays x range / resolution).
[[nodiscard]] ObstacleSensing sense_p3dx(const World& world, const Pose2& T_world_robot,
                                         const P3dxBodyOptions& o, Rng& rng);

/// True when the body at position p_m overlaps a solid cell.
[[nodiscard]] bool body_overlaps(const World& world, Vec2 p_m, double body_radius_m);

/// The motion a body can make from `from` towards `to` (a short step): `to` when the body there is
/// clear of solid cells or no deeper in them than at `from` (so a robot touching a wall can still
/// back away or turn), otherwise `from` with `to`'s heading (the wheels stall but a disc can
/// always turn in place).
[[nodiscard]] Pose2 blocked_motion(const World& world, const Pose2& from, const Pose2& to,
                                   double body_radius_m);

}  // namespace tessera
