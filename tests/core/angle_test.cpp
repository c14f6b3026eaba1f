#include "tessera/core/angle.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

namespace tessera {
namespace {

TEST(NormalizeAngle, PiAndMinusPiBothMapToMinusPi) {
  // The range is [-pi, pi): the two ends of the circle meet at -pi, exactly.
  EXPECT_EQ(normalize_angle(std::numbers::pi), -std::numbers::pi);
  EXPECT_EQ(normalize_angle(-std::numbers::pi), -std::numbers::pi);
}

TEST(NormalizeAngle, AnglesInsideTheRangeAreUnchanged) {
  EXPECT_EQ(normalize_angle(0.0), 0.0);
  EXPECT_DOUBLE_EQ(normalize_angle(1.0), 1.0);
  EXPECT_DOUBLE_EQ(normalize_angle(-1.0), -1.0);
  EXPECT_DOUBLE_EQ(normalize_angle(std::numbers::pi / 2), std::numbers::pi / 2);
  EXPECT_DOUBLE_EQ(normalize_angle(-3.0), -3.0);
}

TEST(NormalizeAngle, MultiplesOfTwoPiMapToZero) {
  EXPECT_EQ(normalize_angle(2.0 * std::numbers::pi), 0.0);
  EXPECT_EQ(normalize_angle(-2.0 * std::numbers::pi), 0.0);
  EXPECT_EQ(normalize_angle(4.0 * std::numbers::pi), 0.0);
  // 100 pi carries the rounding of 100 * pi (a few ulps of 314).
  EXPECT_NEAR(normalize_angle(100.0 * std::numbers::pi), 0.0, 1e-14);
}

TEST(NormalizeAngle, OddMultiplesOfPiMapToMinusPi) {
  EXPECT_EQ(normalize_angle(3.0 * std::numbers::pi), -std::numbers::pi);
  EXPECT_EQ(normalize_angle(-3.0 * std::numbers::pi), -std::numbers::pi);
}

TEST(NormalizeAngle, WrapsByWholeTurns) {
  // 7 - 2 pi = 0.7168146928204138.
  EXPECT_NEAR(normalize_angle(7.0), 0.7168146928204138, 1e-15);
  EXPECT_NEAR(normalize_angle(-7.0), -0.7168146928204138, 1e-15);
  // pi/2 + three turns, both ways.
  EXPECT_NEAR(normalize_angle(std::numbers::pi / 2 + 6.0 * std::numbers::pi), std::numbers::pi / 2,
              1e-14);
  EXPECT_NEAR(normalize_angle(-std::numbers::pi / 2 - 6.0 * std::numbers::pi),
              -std::numbers::pi / 2, 1e-14);
}

TEST(NormalizeAngle, JustBelowMinusPiStaysInsideTheRange) {
  // -pi - 1 ulp: fmod gives -2^-51, and -2^-51 + 2 pi rounds up to exactly 2 pi. Without the
  // second correction the result would be +pi, outside [-pi, pi).
  const double a = std::nextafter(-std::numbers::pi, -std::numeric_limits<double>::infinity());
  const double r = normalize_angle(a);
  EXPECT_LT(r, std::numbers::pi);
  EXPECT_EQ(r, -std::numbers::pi);
}

TEST(NormalizeAngle, ResultIsAlwaysInsideMinusPiToPi) {
  // Neighbours of every boundary the formula has, at one ulp either side.
  const double inf = std::numeric_limits<double>::infinity();
  for (const double base :
       {-4.0 * std::numbers::pi, -3.0 * std::numbers::pi, -2.0 * std::numbers::pi,
        -std::numbers::pi, 0.0, std::numbers::pi, 2.0 * std::numbers::pi, 3.0 * std::numbers::pi,
        4.0 * std::numbers::pi}) {
    for (const double a : {std::nextafter(base, -inf), base, std::nextafter(base, inf)}) {
      const double r = normalize_angle(a);
      EXPECT_GE(r, -std::numbers::pi) << "a = " << a;
      EXPECT_LT(r, std::numbers::pi) << "a = " << a;
    }
  }
}

TEST(DegreesRadians, ConvertTheCardinalAngles) {
  EXPECT_DOUBLE_EQ(deg_to_rad(180.0), std::numbers::pi);
  EXPECT_DOUBLE_EQ(deg_to_rad(90.0), std::numbers::pi / 2);
  EXPECT_DOUBLE_EQ(deg_to_rad(-45.0), -std::numbers::pi / 4);
  EXPECT_EQ(deg_to_rad(0.0), 0.0);
  EXPECT_DOUBLE_EQ(rad_to_deg(std::numbers::pi), 180.0);
  EXPECT_DOUBLE_EQ(rad_to_deg(-std::numbers::pi / 2), -90.0);
  EXPECT_DOUBLE_EQ(rad_to_deg(1.0), 57.29577951308232);
}

TEST(DegreesRadians, RoundTripAndUsableAtCompileTime) {
  static_assert(deg_to_rad(0.0) == 0.0);
  for (const double deg : {-720.0, -33.3, 1.0, 57.0, 359.9}) {
    EXPECT_DOUBLE_EQ(rad_to_deg(deg_to_rad(deg)), deg);
  }
}

}  // namespace
}  // namespace tessera
