#include "tessera/sensors/thesis_odometry.hpp"

namespace tessera {

OdometryErrorOptions thesis_fusion_odometry() {
  OdometryErrorOptions o;
  // Systematic part (Borenstein & Feng 1996 types A and B), fitted to the signs and sizes of
  // Table 5.4 and Tables A.2, A.4, A.6 (x short, y long) over the route of
  // tests/sensors/thesis_odometry_test.cpp: mostly a leftward heading drift (unequal wheels),
  // turns under-read by 4 %, distance under-read by 0.5 %.
  o.distance_scale_error = -0.005;
  o.rotation_scale_error = -0.04;
  o.heading_drift_rad_per_m = 0.029;
  // Random part, for the run-to-run spread of Table 5.4 (0.26 m in x, 0.41 m in y): a heading
  // random walk of 0.035 rad per sqrt(m), a distance random walk of 0.039 m per sqrt(m).
  o.rot_var_rad2_per_rad = 1e-4;
  o.rot_var_rad2_per_m = 1.2e-3;
  o.trans_var_m2_per_m = 1.5e-3;
  o.trans_var_m2_per_rad = 1e-4;
  return o;
}

}  // namespace tessera
