#include "tessera/slam/scan_agreement.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace tessera::slam {
namespace {

constexpr double kPi = std::numbers::pi;

/// A scan in a 6 m x 4 m room ([0, 6] x [0, 4]) with a 1 m square pillar at [4, 5] x [1, 2],
/// taken from T_room_robot by a sensor at the robot's origin: `beams` beams over `fov_rad`,
/// centred on the robot's heading, as scan_to_points gives them (robot frame).
ScanPoints room_scan(const Pose2& T_room_robot, int beams, double fov_rad) {
  ScanPoints s;
  const auto box_exit = [](Vec2 o, Vec2 d, Vec2 lo, Vec2 hi, bool inside) {
    // inside: distance to leave the box; otherwise distance to enter it (inf if never).
    double t0 = 0.0, t1 = std::numeric_limits<double>::infinity();
    const double os[2] = {o.x, o.y}, ds[2] = {d.x, d.y}, ls[2] = {lo.x, lo.y}, hs[2] = {hi.x, hi.y};
    for (int a = 0; a < 2; ++a) {
      if (std::abs(ds[a]) < 1e-12) {
        if (os[a] < ls[a] || os[a] > hs[a]) return std::numeric_limits<double>::infinity();
        continue;
      }
      double ta = (ls[a] - os[a]) / ds[a], tb = (hs[a] - os[a]) / ds[a];
      if (ta > tb) std::swap(ta, tb);
      t0 = std::max(t0, ta);
      t1 = std::min(t1, tb);
    }
    if (inside) return t1;
    return t0 <= t1 && t0 > 0.0 ? t0 : std::numeric_limits<double>::infinity();
  };
  for (int i = 0; i < beams; ++i) {
    const double a = -0.5 * fov_rad + fov_rad * i / std::max(beams - 1, 1);
    const Vec2 d{std::cos(T_room_robot.theta + a), std::sin(T_room_robot.theta + a)};
    const Vec2 o = T_room_robot.translation();
    const double r =
        std::min(box_exit(o, d, {0, 0}, {6, 4}, true), box_exit(o, d, {4, 1}, {5, 2}, false));
    s.returns_m.push_back({r * std::cos(a), r * std::sin(a)});
    s.return_beams.push_back(i);
  }
  return s;
}

TEST(ScanAgreement, ConsecutiveScansOfOnePlaceAgree) {
  const Pose2 a{1.5, 2.0, 0.1};
  const Pose2 b{1.6, 2.02, 0.15};  // a tenth of a second later
  const ScanPoints earlier = room_scan(a, 181, kPi);
  const ScanAgreement g = scan_agreement(earlier, room_scan(b, 181, kPi), between(a, b), kPi / 180);
  EXPECT_GT(g.compared, 150);
  EXPECT_GT(g.share(), 0.95);
}

TEST(ScanAgreement, ScansOfAnotherPlaceDisagreeHoweverTheyAreShifted) {
  // The robot was carried from one end of the room to the other and turned; its odometry (and so
  // the tracker's prior) says it barely moved.
  const ScanPoints earlier = room_scan({1.0, 1.0, 0.3}, 181, kPi);
  const ScanPoints later = room_scan({4.5, 3.0, 2.5}, 181, kPi);
  double best = 0.0;
  for (double dx : {-0.2, 0.0, 0.2}) {
    for (double dth : {-0.2, 0.0, 0.2}) {
      best = std::max(best, scan_agreement(earlier, later, {dx, 0.0, dth}, kPi / 180).share());
    }
  }
  EXPECT_LT(best, 0.5);
}

TEST(ScanAgreement, A360DegreeScanIsComparedAcrossItsSeam) {
  // 360 beams all round; the later robot turned by half a beam, so every bearing near +-pi falls
  // between the first and the last beam.
  const Pose2 a{3.0, 2.0, 0.0};
  const Pose2 b{3.0, 2.0, 0.5 * 2 * kPi / 360};
  const ScanPoints earlier = room_scan(a, 360, 2 * kPi * 359 / 360);
  const ScanPoints later = room_scan(b, 360, 2 * kPi * 359 / 360);
  const ScanAgreement g = scan_agreement(earlier, later, between(a, b), 2 * kPi / 360);
  EXPECT_EQ(g.compared, 360);
  EXPECT_GT(g.share(), 0.97);
}

TEST(ScanAgreement, NothingToCompareIsNoEvidenceOfAJump) {
  const ScanPoints later = room_scan({1.0, 1.0, 0.0}, 181, kPi);
  const ScanAgreement g = scan_agreement(ScanPoints{}, later, Pose2{}, kPi / 180);
  EXPECT_EQ(g.compared, 0);
  EXPECT_EQ(g.share(), 1.0);
  // Behind the earlier sensor (beyond its 180-degree field) nothing is compared either.
  const ScanPoints ahead = room_scan({3.0, 2.0, 0.0}, 181, kPi);
  const ScanPoints behind = room_scan({3.0, 2.0, kPi}, 181, 0.5 * kPi);
  EXPECT_EQ(scan_agreement(ahead, behind, {0.0, 0.0, kPi}, kPi / 180).compared, 0);
}

}  // namespace
}  // namespace tessera::slam
