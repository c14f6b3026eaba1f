#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "tessera/core/result.hpp"
#include "tessera/core/stamped_pose2.hpp"
#include "tessera/trajectory/stamped_pose3.hpp"

namespace tessera {

/// TUM trajectory text (one line per pose: "t x y z qx qy qz qw"), z = 0 and the rotation about z
/// as a unit quaternion (TUM RGB-D benchmark file format).
[[nodiscard]] std::string encode_tum_trajectory(const std::vector<StampedPose2>& poses);

/// Writes encode_tum_trajectory(poses) to `path` atomically.
[[nodiscard]] Status write_tum_trajectory(const std::filesystem::path& path,
                                          const std::vector<StampedPose2>& poses);

/// Reads a TUM trajectory file as read_tum_trajectory3 does and keeps x, y and the heading (the
/// rotation about z, yaw) of each pose.
[[nodiscard]] Result<std::vector<StampedPose2>> read_tum_trajectory(
    const std::filesystem::path& path);

/// Reads a TUM trajectory file (Sturm et al. 2012): one pose a line, "t x y z qx qy qz qw" (s, m,
/// unit quaternion), fields separated by spaces, tabs or commas as the TUM tools accept; blank
/// lines and lines starting with '#' are skipped. Poses are kept in file order. Quaternions are
/// normalised; one whose norm is off 1 by more than 0.01 is an error. Input error naming the file
/// and line for a missing file, a wrong field count, a field that is not a finite number, or a
/// non-unit quaternion.
[[nodiscard]] Result<std::vector<StampedPose3>> read_tum_trajectory3(
    const std::filesystem::path& path);

}  // namespace tessera
