#include "tessera/sensors/beacon_trilateration.hpp"

#include <algorithm>
#include <cmath>

namespace tessera {
namespace {

Point3 sub(Point3 a, Point3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Point3 add(Point3 a, Point3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Point3 scale(Point3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double dot(Point3 a, Point3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Point3 cross(Point3 a, Point3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
double norm(Point3 a) { return std::sqrt(dot(a, a)); }

// Relative size below which the beacon triangle counts as degenerate.
constexpr double kMinSine = 1e-6;

}  // namespace

std::optional<std::string> validate(const BeaconOptions& o) {
  const Point3 a = sub(o.beacons[1], o.beacons[0]);
  const Point3 b = sub(o.beacons[2], o.beacons[0]);
  if (norm(cross(a, b)) <= kMinSine * norm(a) * norm(b) || norm(a) == 0.0 || norm(b) == 0.0) {
    return "beacons: must not be collinear or coincide";
  }
  for (const Point3& p : o.beacons) {
    if (!(p.z > o.receiver_height_m)) return "beacons: must be above the receiver";
  }
  if (!(o.range_noise_stddev_m >= 0.0)) return "range_noise_stddev_m: must be >= 0";
  return std::nullopt;
}

std::array<double, 3> measure_beacon_ranges(Point3 receiver, const BeaconOptions& o, Rng& rng) {
  std::array<double, 3> r{};
  const double s = o.range_noise_stddev_m;
  for (std::size_t i = 0; i < 3; ++i) {
    const double e = s > 0.0 ? std::clamp(rng.gaussian(s), -3.0 * s, 3.0 * s) : 0.0;
    r[i] = std::max(0.0, norm(sub(o.beacons[i], receiver)) + e);
  }
  return r;
}

TrilaterationResult trilaterate(const std::array<Point3, 3>& beacons,
                                const std::array<double, 3>& ranges_m, double touch_tolerance_m2) {
  TrilaterationResult out;
  const Point3 p0 = beacons[0];
  const Point3 a = sub(beacons[1], p0);
  const Point3 b = sub(beacons[2], p0);
  const double d = norm(a);
  const double nb = norm(b);
  if (d == 0.0 || nb == 0.0 || norm(cross(a, b)) <= kMinSine * d * nb) {
    out.status = TrilaterationStatus::kDegenerateBeacons;
    return out;
  }
  const Point3 ex = scale(a, 1.0 / d);
  const double i = dot(ex, b);
  const Point3 b_perp = sub(b, scale(ex, i));
  const double j = norm(b_perp);
  const Point3 ey = scale(b_perp, 1.0 / j);
  const Point3 ez = cross(ex, ey);

  const double r0 = ranges_m[0], r1 = ranges_m[1], r2 = ranges_m[2];
  const double x = (r0 * r0 - r1 * r1 + d * d) / (2.0 * d);
  const double y = (r0 * r0 - r2 * r2 + i * i + j * j) / (2.0 * j) - (i / j) * x;
  double z2 = r0 * r0 - x * x - y * y;
  if (z2 < -touch_tolerance_m2) {
    out.status = TrilaterationStatus::kNoIntersection;
    return out;
  }
  const double z = std::sqrt(std::max(0.0, z2));
  const Point3 in_plane = add(p0, add(scale(ex, x), scale(ey, y)));
  Point3 c0 = add(in_plane, scale(ez, z));
  Point3 c1 = sub(in_plane, scale(ez, z));
  if (c1.z < c0.z) std::swap(c0, c1);
  out.candidates = {c0, c1};
  out.position = c0;
  return out;
}

}  // namespace tessera
