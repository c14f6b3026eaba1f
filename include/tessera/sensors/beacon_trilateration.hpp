#pragma once
#include <array>
#include <optional>
#include <string>

#include "tessera/core/rng.hpp"

namespace tessera {

/// A point in the room, metres: x and y as in the map frame, z up from the floor.
struct Point3 {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;
};

/// The ultrasonic localisation of BOBMapping 3.3 (the method of its refs. 16 and 17): three
/// emitters on the ceiling, time-of-flight ranges to a receiver on top of the robot, RF for
/// synchronisation. Defaults: a 3 x 3 m room with a 2.5 m ceiling, emitters near three corners,
/// the receiver 0.18 m above the floor (the robot's height), range noise that gives the paper's
/// "mean error below 3.5 cm" with the robot standing still.
struct BeaconOptions {
  std::array<Point3, 3> beacons{{{0.2, 0.2, 2.5}, {2.8, 0.2, 2.5}, {0.2, 2.8, 2.5}}};
  double receiver_height_m = 0.18;
  double range_noise_stddev_m = 0.01;  // per range, Gaussian clipped at 3 sigma
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const BeaconOptions& o);

/// Ranges from the receiver at `receiver` to the three beacons, with noise. Draws three Gaussians.
[[nodiscard]] std::array<double, 3> measure_beacon_ranges(Point3 receiver, const BeaconOptions& o,
                                                          Rng& rng);

enum class TrilaterationStatus {
  kOk,
  kDegenerateBeacons,  // two beacons coincide or all three are (nearly) collinear
  kNoIntersection,     // the three spheres do not meet (ranges inconsistent with the geometry)
};

struct TrilaterationResult {
  TrilaterationStatus status = TrilaterationStatus::kOk;
  Point3 position;                     // the lower candidate: the other lies above the ceiling
  std::array<Point3, 2> candidates{};  // lower first; both equal when the spheres touch
};

/// Closed-form intersection of three spheres (centre beacons[i], radius ranges_m[i]): a frame
/// with x along beacon 0 -> 1 and y in the beacons' plane gives x and y linearly and z up to sign;
/// the two mirror solutions lie on either side of the beacons' plane and the one with the larger
/// world z (above the ceiling) is discarded (BOBMapping 3.3). A small negative z^2 from noise, up
/// to `touch_tolerance_m2`, is read as touching spheres; more is kNoIntersection. Cost: O(1).
[[nodiscard]] TrilaterationResult trilaterate(const std::array<Point3, 3>& beacons,
                                              const std::array<double, 3>& ranges_m,
                                              double touch_tolerance_m2 = 1e-4);

}  // namespace tessera
