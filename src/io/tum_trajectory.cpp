#include "tessera/io/tum_trajectory.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "tessera/io/atomic_file.hpp"

namespace tessera {

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

Result<std::vector<StampedPose2>> read_tum_trajectory(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) return input_error(path.string() + ": cannot open trajectory file");
  std::vector<StampedPose2> poses;
  std::string line;
  for (int line_no = 1; std::getline(in, line); ++line_no) {
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    std::istringstream fields(line);
    double t, x, y, z, qx, qy, qz, qw;
    if (!(fields >> t >> x >> y >> z >> qx >> qy >> qz >> qw)) {
      return input_error(path.string() + ":" + std::to_string(line_no) +
                         ": expected 8 numbers 't x y z qx qy qz qw'");
    }
    // Heading = rotation about z (yaw) of the quaternion.
    const double yaw = std::atan2(2.0 * (qw * qz + qx * qy), 1.0 - 2.0 * (qy * qy + qz * qz));
    poses.push_back({t, {x, y, normalize_angle(yaw)}});
  }
  return poses;
}

}  // namespace tessera
