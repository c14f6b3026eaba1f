#pragma once
// The beam layout CARMEN assumes for its old-format laser messages (FLASER, RLASER), which state
// only the beam count: shared by the reader and the writer so that what one writes the other reads
// back (docs/decisions/0006-carmen-beam-geometry.md).
#include <numbers>

namespace tessera::io_internal {

/// The first beam of an old-format scan points at the robot's right.
inline constexpr double kCarmenFirstBeamRad = -std::numbers::pi / 2.0;

/// CARMEN's carmen_laser_guess_angle_increment (readlog.c) for old-format messages, which do not
/// say: a SICK LMS at 1, 0.5 or 0.25 degrees, otherwise 180 degrees spread over the beams.
inline double guess_angle_increment_rad(int beams) {
  constexpr double kPi = std::numbers::pi;
  if (beams == 180 || beams == 181) return kPi / 180.0;
  if (beams == 360 || beams == 361) return kPi / 360.0;
  if (beams == 400 || beams == 401) return kPi / 720.0;
  return beams > 1 ? kPi / (beams - 1) : 0.0;
}

}  // namespace tessera::io_internal
