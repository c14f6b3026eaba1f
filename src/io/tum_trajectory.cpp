#include "tessera/io/tum_trajectory.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "internal/decoders.hpp"
#include "internal/file_util.hpp"
#include "internal/text_fields.hpp"
#include "tessera/io/atomic_file.hpp"

namespace tessera {
namespace {

constexpr std::array<const char*, 8> kFieldNames = {"t", "x", "y", "z", "qx", "qy", "qz", "qw"};

/// How far a quaternion's norm may be from 1: TUM files print 4 decimals (norm off by < 1e-3).
constexpr double kUnitQuaternionTolerance = 0.01;

/// Splits at spaces, tabs and commas (the TUM tools replace ',' and '\\t' by ' ').
std::vector<std::string_view> split_tum_fields(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t i = 0;
  while (i < line.size()) {
    const std::size_t begin = line.find_first_not_of(" \t,\r", i);
    if (begin == std::string_view::npos) break;
    std::size_t end = line.find_first_of(" \t,\r", begin);
    if (end == std::string_view::npos) end = line.size();
    fields.push_back(line.substr(begin, end - begin));
    i = end;
  }
  return fields;
}

std::optional<double> parse_number(std::string_view text) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

}  // namespace

std::string encode_tum_trajectory(const std::vector<StampedPose2>& poses) {
  std::string out = "# timestamp tx ty tz qx qy qz qw\n";
  char line[256];
  for (const StampedPose2& p : poses) {
    const double half = 0.5 * p.pose.theta;
    std::snprintf(line, sizeof(line), "%.6f %.6f %.6f 0 0 0 %.9f %.9f\n", p.t_s, p.pose.x, p.pose.y,
                  std::sin(half), std::cos(half));
    out += line;
  }
  return out;
}

Status write_tum_trajectory(const std::filesystem::path& path,
                            const std::vector<StampedPose2>& poses) {
  return write_file_atomic(path, encode_tum_trajectory(poses));
}

Result<std::vector<StampedPose3>> read_tum_trajectory3(const std::filesystem::path& path) {
  Result<std::string> text = io_internal::read_file_bytes(path);
  if (!text) return text.error();
  return io_internal::decode_tum_trajectory3(*text, path.string());
}

namespace io_internal {

Result<std::vector<StampedPose3>> decode_tum_trajectory3(std::string_view text,
                                                         const std::string& name) {
  std::vector<StampedPose3> poses;
  LineCursor cursor(text);
  std::string_view line;
  int line_no = 0;
  while (cursor.next(line, line_no)) {
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string_view::npos || line[first] == '#') continue;
    const std::string where = name + ":" + std::to_string(line_no) + ": ";
    const std::vector<std::string_view> fields = split_tum_fields(line);
    if (fields.size() != kFieldNames.size()) {
      return input_error(where + "expected 8 fields 't x y z qx qy qz qw', got " +
                         std::to_string(fields.size()));
    }
    std::array<double, 8> v{};
    for (std::size_t k = 0; k < fields.size(); ++k) {
      const std::optional<double> value = parse_number(fields[k]);
      if (!value || !std::isfinite(*value)) {
        return input_error(where + "field " + kFieldNames[k] + " must be a finite number, got '" +
                           std::string(fields[k]) + "'");
      }
      v[k] = *value;
    }
    const Eigen::Quaterniond q(v[7], v[4], v[5], v[6]);  // Eigen's constructor takes w first
    const double norm = q.norm();
    if (std::abs(norm - 1.0) > kUnitQuaternionTolerance) {
      return input_error(where + "quaternion (qx qy qz qw) must have norm 1, got " +
                         std::to_string(norm));
    }
    poses.push_back({v[0], Eigen::Vector3d(v[1], v[2], v[3]), q.normalized()});
  }
  return poses;
}

}  // namespace io_internal

Result<std::vector<StampedPose2>> read_tum_trajectory(const std::filesystem::path& path) {
  Result<std::vector<StampedPose3>> poses3 = read_tum_trajectory3(path);
  if (!poses3) return poses3.error();
  std::vector<StampedPose2> poses;
  poses.reserve(poses3->size());
  for (const StampedPose3& p : *poses3) {
    const Eigen::Quaterniond& q = p.orientation;
    // Heading = rotation about z (yaw) of the quaternion.
    const double yaw = std::atan2(2.0 * (q.w() * q.z() + q.x() * q.y()),
                                  1.0 - 2.0 * (q.y() * q.y() + q.z() * q.z()));
    poses.push_back({p.t_s, {p.position_m.x(), p.position_m.y(), normalize_angle(yaw)}});
  }
  return poses;
}

}  // namespace tessera
