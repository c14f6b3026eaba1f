#pragma once
#include <optional>
#include <string>
#include <vector>

#include "tessera/core/rng.hpp"

namespace tessera {

/// One point of a Sharp IR sensor's output curve: the analog output at a reflector distance.
struct IrCurvePoint {
  double distance_m = 0.0;
  double voltage_v = 0.0;
};

/// A Sharp-type triangulating IR range sensor (BOBMapping 3.2): its analog output falls with
/// distance along an experimentally measured curve, which the robot inverts with a lookup table
/// instead of an arctangent fit. The curve rises from 0 to a peak near min_range_m and falls
/// monotonically after it; only the falling part is invertible, so a reflector closer than the
/// peak reads as a farther one (the Sharp sensors' known ambiguity).
///
/// Noise (Figure 6): the sensor behaves as if the reflector stood at true + e, with e Gaussian of
/// standard deviation noise_base_m + noise_per_m * true distance, clipped at 3 sigma; then the
/// voltage is quantised by the ADC (adc_step_v, 0 = no quantisation).
struct IrSensorOptions {
  double min_range_m = 0.10;
  double max_range_m = 0.80;
  std::vector<IrCurvePoint> curve;  // distance strictly increasing; see the two factories below
  double noise_base_m = 0.003;
  double noise_per_m = 0.025;        // sigma grows 2.5 cm per metre
  double adc_step_v = 3.3 / 1024.0;  // 10-bit ADC on a 3.3 V reference
};

/// Lateral sensors i and j: Sharp GP2D120 (2D120X), 3 to 35 cm (BOBMapping 4.1). The curve follows
/// the shape of the datasheet's "analog output voltage vs distance to reflective object" figure
/// (white paper, 90 % reflectance): peak about 3.0 V at 3 cm, 1.25 V at 10 cm, 0.4 V at 35 cm.
/// Noise gives sigma 0.9 cm at 25 cm, the farthest a lateral cell needs (Figure 6b reports an
/// average error within 2 cm from 4 to 25 cm).
[[nodiscard]] IrSensorOptions lateral_ir_options();

/// Front sensors k, l and m: Sharp GP2Y0A21YK (2Y0A21), 10 to 80 cm (BOBMapping 4.1). The curve
/// follows the datasheet figure's shape: peak about 3.15 V at 6-7 cm, 2.3 V at 10 cm, 0.4 V at
/// 80 cm. Noise gives sigma 1.5 cm at 48 cm, the farthest beams k and m need (Figure 6a reports an
/// average error below 3 cm from 10 to 48 cm). Note: BOBMapping 4.3 swaps the two part names
/// when it quotes minimum ranges; 4.1 (front 2Y0A21, lateral 2D120X) is followed here.
[[nodiscard]] IrSensorOptions front_ir_options();

/// The same sensor with noise and ADC quantisation off (exact readings inside the range).
[[nodiscard]] IrSensorOptions without_noise(IrSensorOptions o);

/// Empty when usable; otherwise names the field and the rule it breaks. Requires at least two
/// curve points with strictly increasing distance, a curve that falls strictly from min_range_m
/// to max_range_m (both inside the table), 0 < min_range_m < max_range_m and non-negative noise.
[[nodiscard]] std::optional<std::string> validate(const IrSensorOptions& o);

/// Output voltage for a reflector at distance_m, linear between table points and clamped to the
/// first and last point outside the table. No noise. Cost: O(log table size).
/// Precondition: validate(o) is empty.
[[nodiscard]] double voltage_at(double distance_m, const IrSensorOptions& o);

/// Distance the robot infers from a voltage: the inverse of the table's falling part between
/// min_range_m and max_range_m; nullopt for a voltage above the value at min_range_m or below the
/// value at max_range_m (out of range, or nothing in front). Precondition: validate(o) is empty.
[[nodiscard]] std::optional<double> distance_from_voltage(double voltage_v,
                                                          const IrSensorOptions& o);

/// Standard deviation of the range error at a reflector distance (Figure 6), metres.
[[nodiscard]] double noise_stddev_m(double distance_m, const IrSensorOptions& o);

struct IrReading {
  double voltage_v = 0.0;            // after noise and ADC quantisation
  std::optional<double> distance_m;  // what the robot infers; nullopt: out of range
};

/// One reading of a reflector at true_distance_m (pass max_range_m or more for "nothing in the
/// beam"). Draws one Gaussian from rng when noise is on. Precondition: validate(o) is empty,
/// true_distance_m >= 0.
[[nodiscard]] IrReading read(double true_distance_m, const IrSensorOptions& o, Rng& rng);

}  // namespace tessera
