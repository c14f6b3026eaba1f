#include "tessera/sensors/ir_sensor.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tessera/core/rng.hpp"

namespace tessera {
namespace {

TEST(IrSensor, DefaultOptionSetsAreValid) {
  EXPECT_FALSE(validate(lateral_ir_options()).has_value());
  EXPECT_FALSE(validate(front_ir_options()).has_value());
  EXPECT_DOUBLE_EQ(lateral_ir_options().min_range_m, 0.03);
  EXPECT_DOUBLE_EQ(lateral_ir_options().max_range_m, 0.35);
  EXPECT_DOUBLE_EQ(front_ir_options().min_range_m, 0.10);
  EXPECT_DOUBLE_EQ(front_ir_options().max_range_m, 0.80);
}

TEST(IrSensor, ValidateRejectsACurveThatDoesNotFallOverTheRange) {
  IrSensorOptions o = front_ir_options();
  o.curve[8].voltage_v = 2.0;  // 0.25 m now above 0.20 m's 1.30 V
  EXPECT_TRUE(validate(o).has_value());
  o = front_ir_options();
  o.max_range_m = 2.0;  // beyond the table
  EXPECT_TRUE(validate(o).has_value());
}

TEST(IrSensor, VoltageInterpolatesBetweenTablePointsAndClampsOutside) {
  const IrSensorOptions o = front_ir_options();
  EXPECT_DOUBLE_EQ(voltage_at(0.10, o), 2.30);
  EXPECT_NEAR(voltage_at(0.125, o), 0.5 * (2.30 + 1.65), 1e-12);
  EXPECT_DOUBLE_EQ(voltage_at(5.0, o), o.curve.back().voltage_v);
}

TEST(IrSensor, DistanceFromVoltageInvertsTheFallingPart) {
  for (const IrSensorOptions& o : {lateral_ir_options(), front_ir_options()}) {
    for (double d = o.min_range_m; d <= o.max_range_m; d += 0.001) {
      const std::optional<double> back = distance_from_voltage(voltage_at(d, o), o);
      ASSERT_TRUE(back.has_value()) << d;
      EXPECT_NEAR(*back, d, 1e-9);
    }
  }
}

TEST(IrSensor, VoltageOutsideTheRangeGivesNoDistance) {
  const IrSensorOptions o = front_ir_options();
  EXPECT_FALSE(distance_from_voltage(3.0, o).has_value());   // above the 10 cm value: too close
  EXPECT_FALSE(distance_from_voltage(0.35, o).has_value());  // below the 80 cm value: nothing
  EXPECT_FALSE(distance_from_voltage(voltage_at(1.2, o), o).has_value());
}

TEST(IrSensor, AReflectorInsideTheDeadZoneReadsFartherThanItIs) {
  // The Sharp ambiguity: 3 cm in front of a GP2Y0A21 gives the voltage of about 15 cm.
  const IrSensorOptions o = front_ir_options();
  const std::optional<double> d = distance_from_voltage(voltage_at(0.03, o), o);
  ASSERT_TRUE(d.has_value());
  EXPECT_GT(*d, 0.14);
}

TEST(IrSensor, NoiselessReadingIsExactInsideTheRange) {
  const IrSensorOptions o = without_noise(lateral_ir_options());
  Rng rng(1);
  const IrReading r = read(0.2, o, rng);
  ASSERT_TRUE(r.distance_m.has_value());
  EXPECT_NEAR(*r.distance_m, 0.2, 1e-12);
  EXPECT_FALSE(read(2.0, o, rng).distance_m.has_value());
}

// Figure 6: the error grows with distance and stays under 3 cm up to 48 cm (front) and within
// 2 cm up to 25 cm (lateral). Measured here as mean absolute error over seeded trials.
double mean_abs_error(const IrSensorOptions& o, double d, Rng& rng, int trials) {
  double sum = 0.0;
  int n = 0;
  for (int t = 0; t < trials; ++t) {
    const IrReading r = read(d, o, rng);
    if (!r.distance_m) continue;
    sum += std::abs(*r.distance_m - d);
    ++n;
  }
  return n > 0 ? sum / n : 1e9;
}

TEST(IrSensor, FrontErrorGrowsWithDistanceAndStaysUnderThreeCentimetresTo48) {
  const IrSensorOptions o = front_ir_options();
  Rng rng(6);
  double prev = 0.0;
  for (double d = 0.12; d <= 0.481; d += 0.06) {
    const double e = mean_abs_error(o, d, rng, 4000);
    EXPECT_LT(e, 0.03) << d;
    EXPECT_GT(e, prev * 0.95) << d;  // grows (allowing for sampling scatter)
    prev = e;
  }
  EXPECT_LT(noise_stddev_m(0.48, o), 0.03);
  EXPECT_GT(noise_stddev_m(0.48, o), noise_stddev_m(0.10, o));
}

TEST(IrSensor, LateralErrorStaysWithinTwoCentimetresTo25) {
  const IrSensorOptions o = lateral_ir_options();
  Rng rng(7);
  for (double d = 0.04; d <= 0.251; d += 0.03) {
    EXPECT_LT(mean_abs_error(o, d, rng, 4000), 0.02) << d;
  }
}

TEST(IrSensor, ReadingErrorIsBoundedByThreeSigmaPlusQuantisation) {
  const IrSensorOptions o = front_ir_options();
  Rng rng(8);
  for (int t = 0; t < 20000; ++t) {
    const double d = rng.uniform(0.12, 0.6);
    const IrReading r = read(d, o, rng);
    if (!r.distance_m) continue;
    EXPECT_LE(std::abs(*r.distance_m - d), 3.5 * noise_stddev_m(d, o)) << d;
  }
}

TEST(IrSensor, SameSeedGivesSameReadings) {
  const IrSensorOptions o = front_ir_options();
  Rng a(11), b(11);
  for (int t = 0; t < 100; ++t) EXPECT_EQ(read(0.3, o, a).voltage_v, read(0.3, o, b).voltage_v);
}

}  // namespace
}  // namespace tessera
