#pragma once

namespace tessera {

/// A command for a differential-drive robot: forward speed and turn rate (counter-clockwise
/// positive), in the robot frame.
struct VelocityCommand {
  double v_m_per_s = 0.0;
  double omega_rad_per_s = 0.0;
};

}  // namespace tessera
