#include "tessera/sensors/ir_sensor.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "tessera/core/assert.hpp"

namespace tessera {
namespace {

// Linear interpolation of voltage over the table, clamped at both ends.
double interpolate_voltage(double d_m, const std::vector<IrCurvePoint>& curve) {
  if (d_m <= curve.front().distance_m) return curve.front().voltage_v;
  if (d_m >= curve.back().distance_m) return curve.back().voltage_v;
  const auto hi =
      std::upper_bound(curve.begin(), curve.end(), d_m,
                       [](double d, const IrCurvePoint& p) { return d < p.distance_m; });
  const auto lo = hi - 1;
  const double t = (d_m - lo->distance_m) / (hi->distance_m - lo->distance_m);
  return lo->voltage_v + t * (hi->voltage_v - lo->voltage_v);
}

}  // namespace

IrSensorOptions lateral_ir_options() {
  IrSensorOptions o;
  o.min_range_m = 0.03;
  o.max_range_m = 0.35;
  // Sharp GP2D120 datasheet, Fig. "Analog output voltage vs. distance to reflective object",
  // read off the white-reflector curve; the first two points are the rising part below 3 cm.
  o.curve = {{0.000, 0.20}, {0.015, 2.00}, {0.030, 3.00}, {0.040, 2.75}, {0.050, 2.30},
             {0.060, 1.98}, {0.070, 1.72}, {0.080, 1.53}, {0.100, 1.25}, {0.120, 1.05},
             {0.140, 0.92}, {0.160, 0.81}, {0.180, 0.73}, {0.200, 0.66}, {0.250, 0.54},
             {0.300, 0.45}, {0.350, 0.40}, {0.400, 0.36}, {0.600, 0.30}};
  o.noise_base_m = 0.001;
  o.noise_per_m = 0.030;  // sigma 0.9 cm at 25 cm
  return o;
}

IrSensorOptions front_ir_options() {
  IrSensorOptions o;  // the struct's defaults are the front sensor's
  // Sharp GP2Y0A21YK datasheet, Fig. "Analog output voltage vs. distance to reflective object",
  // white-reflector curve; the first three points are the rising part below the 6.5 cm peak.
  o.curve = {{0.000, 0.30}, {0.030, 1.60}, {0.050, 2.80}, {0.065, 3.15}, {0.080, 2.85},
             {0.100, 2.30}, {0.150, 1.65}, {0.200, 1.30}, {0.250, 1.08}, {0.300, 0.92},
             {0.350, 0.80}, {0.400, 0.72}, {0.450, 0.65}, {0.500, 0.60}, {0.600, 0.50},
             {0.700, 0.44}, {0.800, 0.40}, {0.900, 0.37}, {1.500, 0.30}};
  return o;
}

IrSensorOptions without_noise(IrSensorOptions o) {
  o.noise_base_m = 0.0;
  o.noise_per_m = 0.0;
  o.adc_step_v = 0.0;
  return o;
}

std::optional<std::string> validate(const IrSensorOptions& o) {
  if (o.curve.size() < 2) return "curve: needs at least two points";
  for (std::size_t i = 1; i < o.curve.size(); ++i) {
    if (!(o.curve[i].distance_m > o.curve[i - 1].distance_m)) {
      return "curve: distance_m must increase strictly";
    }
  }
  if (!(o.min_range_m > 0.0)) return "min_range_m: must be > 0";
  if (!(o.max_range_m > o.min_range_m)) return "max_range_m: must be > min_range_m";
  if (o.min_range_m < o.curve.front().distance_m || o.max_range_m > o.curve.back().distance_m) {
    return "curve: must cover [min_range_m, max_range_m]";
  }
  // The falling part must fall strictly so that distance_from_voltage has one answer.
  double prev = interpolate_voltage(o.min_range_m, o.curve);
  for (const IrCurvePoint& p : o.curve) {
    if (p.distance_m <= o.min_range_m) continue;
    const double d = std::min(p.distance_m, o.max_range_m);
    const double v = interpolate_voltage(d, o.curve);
    if (!(v < prev)) return "curve: voltage must fall strictly from min_range_m to max_range_m";
    prev = v;
    if (d >= o.max_range_m) break;
  }
  if (o.noise_base_m < 0.0 || o.noise_per_m < 0.0) return "noise: must be >= 0";
  if (o.adc_step_v < 0.0) return "adc_step_v: must be >= 0";
  return std::nullopt;
}

double voltage_at(double distance_m, const IrSensorOptions& o) {
  TESSERA_ASSERT(o.curve.size() >= 2);
  return interpolate_voltage(distance_m, o.curve);
}

std::optional<double> distance_from_voltage(double voltage_v, const IrSensorOptions& o) {
  TESSERA_ASSERT(o.curve.size() >= 2);
  const double v_near = interpolate_voltage(o.min_range_m, o.curve);
  const double v_far = interpolate_voltage(o.max_range_m, o.curve);
  if (voltage_v > v_near || voltage_v < v_far) return std::nullopt;
  // Walk the falling segments between min_range_m and max_range_m (tables are a few dozen points:
  // the robot's lookup table, not a search structure).
  double d0 = o.min_range_m;
  double v0 = v_near;
  for (const IrCurvePoint& p : o.curve) {
    if (p.distance_m <= o.min_range_m) continue;
    const double d1 = std::min(p.distance_m, o.max_range_m);
    const double v1 = interpolate_voltage(d1, o.curve);
    if (voltage_v >= v1) {
      if (voltage_v == v0) return d0;
      return d0 + (d1 - d0) * (v0 - voltage_v) / (v0 - v1);
    }
    d0 = d1;
    v0 = v1;
    if (d1 >= o.max_range_m) break;
  }
  return o.max_range_m;  // only reached through rounding at v_far
}

double noise_stddev_m(double distance_m, const IrSensorOptions& o) {
  return o.noise_base_m + o.noise_per_m * distance_m;
}

IrReading read(double true_distance_m, const IrSensorOptions& o, Rng& rng) {
  TESSERA_ASSERT(true_distance_m >= 0.0);
  double seen_m = true_distance_m;
  const double sigma = noise_stddev_m(true_distance_m, o);
  if (sigma > 0.0) {
    const double e = std::clamp(rng.gaussian(sigma), -3.0 * sigma, 3.0 * sigma);
    seen_m = std::max(0.0, true_distance_m + e);
  }
  double v = voltage_at(seen_m, o);
  if (o.adc_step_v > 0.0) v = std::round(v / o.adc_step_v) * o.adc_step_v;
  return {v, distance_from_voltage(v, o)};
}

}  // namespace tessera
