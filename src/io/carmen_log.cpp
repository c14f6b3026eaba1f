// CARMEN log reader: one pass over the bytes, fields split in place and parsed with from_chars.
// Field layouts follow CARMEN's src/global/readlog.c (carmen_string_to_robot_laser_message_orig
// for FLASER/RLASER, carmen_string_to_robot_laser_message for ROBOTLASER1,
// carmen_string_to_laser_laser_message for RAWLASER1); the choices it leaves open are in
// docs/decisions/0006-carmen-beam-geometry.md.
#include "tessera/io/carmen_log.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>
#include <string_view>
#include <vector>

#include "internal/carmen_beams.hpp"
#include "internal/decoders.hpp"
#include "internal/file_util.hpp"
#include "internal/text_fields.hpp"
#include "tessera/core/pose_interpolation.hpp"

namespace tessera {
namespace {

using io_internal::guess_angle_increment_rad;
using io_internal::parse_double;

/// Automatic no-return threshold of FLASER/RLASER: this far below the file's largest reading, so
/// that logs with two sentinel values (FHW's 51.05 and 51.1 m) lose both.
constexpr double kNoReturnBandM = 0.1;

constexpr std::string_view kOdomLayout =
    "ODOM x y theta tv rv accel ipc_timestamp ipc_hostname logger_timestamp";
constexpr std::string_view kOldLaserLayout =
    "n r_0..r_{n-1} x y theta odom_x odom_y odom_theta ipc_timestamp ipc_hostname "
    "logger_timestamp";
constexpr std::string_view kRobotLaserLayout =
    "ROBOTLASER1 type start_angle fov resolution max_range accuracy remission_mode n r.. n_rem "
    "rem.. laser_x laser_y laser_theta robot_x robot_y robot_theta tv rv forward_safety "
    "side_safety turn_axis ipc_timestamp ipc_hostname logger_timestamp";
constexpr std::string_view kRawLaserLayout =
    "RAWLASER1 type start_angle fov resolution max_range accuracy remission_mode n r.. n_rem "
    "rem.. ipc_timestamp ipc_hostname logger_timestamp";

/// The fields of one message line and where it is, so that every problem names file and line.
/// Getters record the first problem and return 0; check ok() once after reading.
class MessageLine {
 public:
  MessageLine(const std::string& file, int line_no, std::span<const std::string_view> fields)
      : file_(file), line_no_(line_no), fields_(fields), tag_(fields.front()) {}

  [[nodiscard]] std::size_t size() const { return fields_.size(); }
  [[nodiscard]] bool ok() const { return !failed_; }
  [[nodiscard]] const Error& failure() const { return error_; }

  [[nodiscard]] Error error(const std::string& what) const {
    return input_error(file_ + ":" + std::to_string(line_no_) + ": " + what);
  }
  void fail(const std::string& what) {
    if (failed_) return;
    failed_ = true;
    error_ = error(what);
  }

  /// Fails unless the line has at least `min` fields; `layout` describes them.
  void expect_at_least(std::size_t min, std::string_view layout) {
    if (size() >= min) return;
    fail("truncated " + std::string(tag_) + " line: " + std::to_string(size()) +
         " fields, expected at least " + std::to_string(min) + " (" + std::string(layout) + ")");
  }

  /// Fails unless the line has exactly `expected` fields; `layout` describes them.
  void expect_fields(std::size_t expected, std::string_view layout) {
    if (size() == expected) return;
    const std::string head = size() < expected ? "truncated " + std::string(tag_) + " line: "
                                               : std::string(tag_) + " line has ";
    fail(head + std::to_string(size()) + " fields, expected " + std::to_string(expected) + " (" +
         std::string(layout) + ")");
  }

  double number(std::size_t i, std::string_view name) {
    double v = 0.0;
    if (!failed_ && !parse_double(fields_[i], v)) {
      fail(std::string(tag_) + " " + std::string(name) + " is '" + std::string(fields_[i]) +
           "', expected a number");
    }
    return v;
  }

  /// A count field (beams, remissions): an integer >= `min`.
  int count(std::size_t i, std::string_view name, int min) {
    int v = 0;
    if (!failed_ && (!io_internal::parse_int(fields_[i], v) || v < min)) {
      fail(std::string(tag_) + " " + std::string(name) + " is '" + std::string(fields_[i]) +
           "', expected an integer >= " + std::to_string(min));
      return 0;
    }
    return v;
  }

  /// Three fields x y theta named <prefix>x ..., the angle wrapped into [-pi, pi).
  Pose2 pose(std::size_t i, std::string_view prefix) {
    const std::string p(prefix);
    const double x = number(i, p + "x");
    const double y = number(i + 1, p + "y");
    const double theta = number(i + 2, p + "theta");
    return {x, y, io_internal::wrap_angle(theta)};
  }

  /// The trailing `ipc_timestamp ipc_hostname logger_timestamp` starting at field i; returns the
  /// ipc stamp.
  double stamps(std::size_t i) {
    const double ipc_s = number(i, "ipc_timestamp");
    number(i + 2, "logger_timestamp");
    return ipc_s;
  }

  /// `n` ranges starting at field i: finite and >= 0.
  std::vector<double> ranges(std::size_t i, int n) {
    std::vector<double> out(static_cast<std::size_t>(n));
    for (std::size_t b = 0; b < out.size() && !failed_; ++b) {
      if (!parse_double(fields_[i + b], out[b]) || out[b] < 0.0) {
        fail(std::string(tag_) + " range of beam " + std::to_string(b) + " is '" +
             std::string(fields_[i + b]) + "', expected a finite number >= 0");
      }
    }
    return out;
  }

  /// Checks `n` numeric fields from field i (values the reader does not keep).
  void numbers(std::size_t i, int n, std::string_view name) {
    for (std::size_t k = 0; k < static_cast<std::size_t>(n) && !failed_; ++k) {
      number(i + k, name);
    }
  }

 private:
  const std::string& file_;
  int line_no_;
  std::span<const std::string_view> fields_;
  std::string_view tag_;
  bool failed_ = false;
  Error error_;
};

/// laser_in_robot from the logged laser and robot poses; a rear laser looks backwards (CARMEN's
/// localize places it at robot theta + pi), so it is turned unless the logged pose already is.
Pose2 laser_in_robot(const Pose2& laser, const Pose2& robot, bool rear) {
  const Pose2 T_robot_laser = between(robot, laser);
  if (rear && std::abs(T_robot_laser.theta) < std::numbers::pi / 2.0) {
    return T_robot_laser * Pose2{0.0, 0.0, std::numbers::pi};
  }
  return T_robot_laser;
}

Result<OdometryReading> parse_odom(MessageLine& line) {
  line.expect_fields(10, kOdomLayout);
  if (!line.ok()) return line.failure();
  OdometryReading odom;
  odom.pose = line.pose(1, "");
  line.number(4, "tv");
  line.number(5, "rv");
  line.number(6, "accel");
  odom.t_s = line.stamps(7);
  if (!line.ok()) return line.failure();
  return odom;
}

/// FLASER / RLASER: `n r.. x y theta odom_x odom_y odom_theta` + stamps.
Result<StampedScan> parse_old_laser(MessageLine& line, std::string_view tag) {
  constexpr std::size_t kFixedFields = 11;  // tag, n, two poses, three stamp fields
  const std::string layout = std::string(tag) + " " + std::string(kOldLaserLayout);
  line.expect_at_least(kFixedFields, layout);
  if (!line.ok()) return line.failure();
  const int n = line.count(1, "beam count", 1);
  if (!line.ok()) return line.failure();
  const std::size_t ranges = line.size() - kFixedFields;
  if (ranges != static_cast<std::size_t>(n)) {
    return line.error(std::string(tag) + " says " + std::to_string(n) + " beams but has " +
                      std::to_string(ranges) + " ranges");
  }
  const std::size_t pose_at = 2 + ranges;
  StampedScan s;
  s.scan.angle_min_rad = io_internal::kCarmenFirstBeamRad;
  s.scan.angle_increment_rad = guess_angle_increment_rad(n);
  s.scan.ranges_m = line.ranges(2, n);
  const Pose2 laser = line.pose(pose_at, "");
  s.odometry = line.pose(pose_at + 3, "odom_");
  s.laser_in_robot = laser_in_robot(laser, s.odometry, tag == "RLASER");
  s.t_s = line.stamps(pose_at + 6);
  if (!line.ok()) return line.failure();
  return s;
}

/// The head shared by ROBOTLASER1 and RAWLASER1: `type start_angle fov resolution max_range
/// accuracy remission_mode n r.. n_rem rem..`. `tail` is the number of fields after the
/// remissions; the line must have exactly that many. Returns the index of the first tail field.
std::size_t parse_new_laser_head(MessageLine& line, std::size_t tail, std::string_view layout,
                                 RangeScan& scan) {
  constexpr std::size_t kHead = 9;  // tag .. n
  line.expect_at_least(kHead + 1 + tail, layout);
  const int n = line.count(8, "beam count", 1);
  if (!line.ok()) return 0;
  const std::size_t rem_at = kHead + static_cast<std::size_t>(n);
  line.expect_at_least(rem_at + 1 + tail, layout);
  const int n_rem = line.count(rem_at, "remission count", 0);
  if (!line.ok()) return 0;
  const std::size_t tail_at = rem_at + 1 + static_cast<std::size_t>(n_rem);
  line.expect_fields(tail_at + tail, layout);
  if (!line.ok()) return 0;
  line.number(1, "laser_type");
  scan.angle_min_rad = line.number(2, "start_angle");
  line.number(3, "fov");
  scan.angle_increment_rad = line.number(4, "resolution");
  scan.max_range_m = line.number(5, "max_range");
  line.number(6, "accuracy");
  line.number(7, "remission_mode");
  if (line.ok() && !(scan.angle_increment_rad > 0.0)) line.fail("resolution must be > 0");
  if (line.ok() && !(scan.max_range_m > 0.0)) line.fail("max_range must be > 0");
  scan.ranges_m = line.ranges(kHead, n);
  line.numbers(rem_at + 1, n_rem, "remission");
  return tail_at;
}

Result<StampedScan> parse_robot_laser(MessageLine& line) {
  StampedScan s;
  const std::size_t at = parse_new_laser_head(line, 14, kRobotLaserLayout, s.scan);
  if (!line.ok()) return line.failure();
  const Pose2 laser = line.pose(at, "laser_");
  s.odometry = line.pose(at + 3, "robot_");
  s.laser_in_robot = laser_in_robot(laser, s.odometry, false);
  line.number(at + 6, "tv");
  line.number(at + 7, "rv");
  line.number(at + 8, "forward_safety");
  line.number(at + 9, "side_safety");
  line.number(at + 10, "turn_axis");
  s.t_s = line.stamps(at + 11);
  if (!line.ok()) return line.failure();
  return s;
}

Result<StampedScan> parse_raw_laser(MessageLine& line) {
  StampedScan s;
  const std::size_t at = parse_new_laser_head(line, 3, kRawLaserLayout, s.scan);
  if (!line.ok()) return line.failure();
  s.t_s = line.stamps(at);
  if (!line.ok()) return line.failure();
  return s;
}

/// Odometry at t_s from the ODOM readings just before (a) and just after (b) a scan in the file,
/// either of which may be missing (not both): linear in x, y and along the shortest arc in theta
/// when t_s lies between their stamps, otherwise the reading nearer in time.
Pose2 odometry_at(double t_s, const OdometryReading* a, const OdometryReading* b) {
  if (a == nullptr) return b->pose;
  if (b == nullptr) return a->pose;
  if (a->t_s < b->t_s && a->t_s <= t_s && t_s <= b->t_s) {
    return interpolate(a->pose, b->pose, (t_s - a->t_s) / (b->t_s - a->t_s));
  }
  return std::abs(t_s - a->t_s) <= std::abs(t_s - b->t_s) ? a->pose : b->pose;
}

/// A RAWLASER1 scan waiting for the ODOM readings around it.
struct PendingOdometry {
  std::size_t scan = 0;
  std::size_t odometry_before = 0;  // ODOM readings read before the scan's line
  int line_no = 0;
};

}  // namespace

std::optional<std::string> validate(const CarmenReadOptions& options) {
  if (!std::isfinite(options.no_return_m) || options.no_return_m < 0.0) {
    return "no_return_m must be a finite number >= 0 (0: automatic), got " +
           std::to_string(options.no_return_m);
  }
  return std::nullopt;
}

Result<LaserLog> read_carmen_log(const std::filesystem::path& path,
                                 const CarmenReadOptions& options) {
  if (auto problem = validate(options)) return usage_error("CarmenReadOptions: " + *problem);
  Result<std::string> bytes = io_internal::read_file_bytes(path);
  if (!bytes) return bytes.error();
  return io_internal::decode_carmen_log(*bytes, path.string(), options);
}

namespace io_internal {

Result<LaserLog> decode_carmen_log(std::string_view text, const std::string& file,
                                   const CarmenReadOptions& options) {
  LaserLog log;
  std::vector<PendingOdometry> pending;
  std::vector<std::size_t> old_format;  // FLASER/RLASER scans, which get the automatic no-return
  double old_format_max_m = 0.0;
  int skipped_rear = 0;

  const Status read = io_internal::for_each_record(
      text, [&](int line_no, const std::vector<std::string_view>& fields) -> Status {
        const std::string_view tag = fields.front();
        MessageLine line(file, line_no, fields);
        if (tag == "ODOM") {
          Result<OdometryReading> odom = parse_odom(line);
          if (!odom) return odom.error();
          log.odometry.push_back(*odom);
          return Ok{};
        }
        const bool old = tag == "FLASER" || tag == "RLASER";
        if (!old && tag != "ROBOTLASER1" && tag != "RAWLASER1") {
          return Ok{};  // PARAM, NEFF, TRUEPOS, SYNC and messages this reader does not use
        }
        if (tag == "RLASER" && !options.rear_laser) {
          ++skipped_rear;
          return Ok{};
        }
        Result<StampedScan> scan = old                    ? parse_old_laser(line, tag)
                                   : tag == "ROBOTLASER1" ? parse_robot_laser(line)
                                                          : parse_raw_laser(line);
        if (!scan) return scan.error();
        if (old) {
          old_format.push_back(log.scans.size());
          for (double r : scan->scan.ranges_m) old_format_max_m = std::max(old_format_max_m, r);
        } else if (tag == "RAWLASER1") {
          pending.push_back({log.scans.size(), log.odometry.size(), line_no});
        }
        log.scans.push_back(std::move(scan).value());
        return Ok{};
      });
  if (!read) return read.error();

  if (log.scans.empty()) {
    std::string what = file + ": no laser scans (FLASER, RLASER, ROBOTLASER1 or RAWLASER1 lines)";
    if (skipped_rear > 0) {
      what += "; " + std::to_string(skipped_rear) +
              " RLASER lines were skipped (CarmenReadOptions::rear_laser reads them)";
    }
    return input_error(what);
  }
  for (const PendingOdometry& p : pending) {
    if (log.odometry.empty()) {
      return input_error(
          file + ":" + std::to_string(p.line_no) +
          ": RAWLASER1 carries no pose and the file has no ODOM line to take it from");
    }
    const OdometryReading* before =
        p.odometry_before > 0 ? &log.odometry[p.odometry_before - 1] : nullptr;
    const OdometryReading* after =
        p.odometry_before < log.odometry.size() ? &log.odometry[p.odometry_before] : nullptr;
    log.scans[p.scan].odometry = odometry_at(log.scans[p.scan].t_s, before, after);
  }
  if (options.no_return_m > 0.0) {
    for (StampedScan& s : log.scans) s.scan.max_range_m = options.no_return_m;
  } else {
    const double automatic_m = std::max(0.0, old_format_max_m - kNoReturnBandM);
    for (std::size_t i : old_format) log.scans[i].scan.max_range_m = automatic_m;
  }
  for (std::size_t i = 1; i < log.scans.size(); ++i) {
    if (log.scans[i].t_s < log.scans[i - 1].t_s) ++log.backward_stamps;
  }
  return log;
}

}  // namespace io_internal

}  // namespace tessera
