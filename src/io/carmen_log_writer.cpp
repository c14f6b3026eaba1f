// CARMEN log writer: the line layouts read_carmen_log parses (CARMEN's src/global/readlog.c).
#include "tessera/io/carmen_log_writer.hpp"

#include <cmath>
#include <cstdarg>
#include <cstddef>
#include <cstdio>
#include <limits>
#include <string>

#include "internal/carmen_beams.hpp"
#include "tessera/io/atomic_file.hpp"

namespace tessera {
namespace {

constexpr double kAngleToleranceRad = 1e-9;

/// printf-style append (the io module formats as the other writers do, without fmt); a value too
/// long for the stack buffer (a finite 1e300 is 300 digits) is formatted again at its length.
[[gnu::format(printf, 2, 3)]] void appendf(std::string& out, const char* format, ...) {
  char buffer[160];
  va_list args;
  va_start(args, format);
  va_list again;
  va_copy(again, args);
  const int n = std::vsnprintf(buffer, sizeof(buffer), format, args);
  va_end(args);
  if (n >= 0 && static_cast<std::size_t>(n) < sizeof(buffer)) {
    out.append(buffer, static_cast<std::size_t>(n));
  } else if (n > 0) {
    const std::size_t at = out.size();
    out.resize(at + static_cast<std::size_t>(n) + 1);
    std::vsnprintf(out.data() + at, static_cast<std::size_t>(n) + 1, format, again);
    out.resize(at + static_cast<std::size_t>(n));
  }
  va_end(again);
}

bool finite(const Pose2& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.theta);
}

/// True when the old format's guess (from the beam count alone) gives this scan's beams.
bool old_format_fits(const RangeScan& scan) {
  const int n = static_cast<int>(scan.ranges_m.size());
  return std::abs(scan.angle_min_rad - io_internal::kCarmenFirstBeamRad) <= kAngleToleranceRad &&
         std::abs(scan.angle_increment_rad - io_internal::guess_angle_increment_rad(n)) <=
             kAngleToleranceRad;
}

void append_pose(std::string& out, const Pose2& p) {
  appendf(out, " %.6f %.6f %.6f", p.x, p.y, p.theta);
}

void append_stamps(std::string& out, double t_s) { appendf(out, " %.6f tessera %.6f\n", t_s, t_s); }

void append_scan(std::string& out, const StampedScan& s) {
  const std::size_t n = s.scan.ranges_m.size();
  const bool old_format = old_format_fits(s.scan);
  if (old_format) {
    appendf(out, "FLASER %zu", n);
  } else {
    // ROBOTLASER1 type start_angle fov resolution max_range accuracy remission_mode n
    const double fov_rad = s.scan.angle_increment_rad * static_cast<double>(n > 0 ? n - 1 : 0);
    appendf(out, "ROBOTLASER1 0 %.9f %.9f %.9f %.6f 0 0 %zu", s.scan.angle_min_rad, fov_rad,
            s.scan.angle_increment_rad, s.scan.max_range_m, n);
  }
  for (double r : s.scan.ranges_m) appendf(out, " %.6f", r);
  if (!old_format) out += " 0";  // no remission values
  append_pose(out, s.odometry * s.laser_in_robot);
  append_pose(out, s.odometry);
  if (!old_format) out += " 0 0 0 0 0";  // tv rv forward_safety side_safety turn_axis
  append_stamps(out, s.t_s);
}

/// Appends an ODOM line; false (nothing appended) when the reading is not finite.
bool append_odometry(std::string& out, const OdometryReading& o) {
  if (!finite(o.pose) || !std::isfinite(o.t_s)) return false;
  out += "ODOM";
  append_pose(out, o.pose);
  out += " 0 0 0";  // tv rv accel
  append_stamps(out, o.t_s);
  return true;
}

std::string scan_problem(const StampedScan& s, std::size_t index) {
  if (s.scan.ranges_m.empty()) return "scan " + std::to_string(index) + " has no beams";
  for (double r : s.scan.ranges_m) {
    if (!std::isfinite(r))
      return "scan " + std::to_string(index) + " has a range that is not finite";
  }
  if (!finite(s.odometry) || !finite(s.laser_in_robot) || !std::isfinite(s.t_s) ||
      !std::isfinite(s.scan.angle_min_rad) || !std::isfinite(s.scan.angle_increment_rad) ||
      !std::isfinite(s.scan.max_range_m)) {
    return "scan " + std::to_string(index) + " has a pose, stamp or beam layout that is not finite";
  }
  return {};
}

}  // namespace

Status write_carmen_log(const std::filesystem::path& path, const LaserLog& log) {
  std::string out = "# CARMEN laser log written by tessera\n";
  std::size_t next_odometry = 0;
  // ODOM lines up to `t_s` (all of them when t_s is infinite).
  auto odometry_until = [&](double t_s) -> Status {
    for (; next_odometry < log.odometry.size() && log.odometry[next_odometry].t_s <= t_s;
         ++next_odometry) {
      if (!append_odometry(out, log.odometry[next_odometry])) {
        return usage_error(path.string() + ": odometry reading " + std::to_string(next_odometry) +
                           " is not finite");
      }
    }
    return Ok{};
  };
  for (std::size_t i = 0; i < log.scans.size(); ++i) {
    const StampedScan& s = log.scans[i];
    if (std::string problem = scan_problem(s, i); !problem.empty()) {
      return usage_error(path.string() + ": " + problem);
    }
    if (Status st = odometry_until(s.t_s); !st) return st;
    append_scan(out, s);
  }
  if (Status st = odometry_until(std::numeric_limits<double>::infinity()); !st) return st;
  return write_file_atomic(path, out);
}

}  // namespace tessera
