#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "tessera/core/pose2.hpp"
#include "tessera/core/result.hpp"

namespace tessera {

/// A planar pose with its time stamp, seconds.
struct StampedPose2 {
  double t_s = 0.0;
  Pose2 pose;
};

/// TUM trajectory text (one line per pose: "t x y z qx qy qz qw"), z = 0 and the rotation about z
/// as a unit quaternion (TUM RGB-D benchmark file format).
[[nodiscard]] std::string encode_tum_trajectory(const std::vector<StampedPose2>& poses);

/// Writes encode_tum_trajectory(poses) to `path` atomically.
[[nodiscard]] Status write_tum_trajectory(const std::filesystem::path& path,
                                          const std::vector<StampedPose2>& poses);

/// Reads a TUM trajectory file; the heading is the rotation about z of each quaternion. Comment
/// lines start with '#'. Input error naming the file and line for a malformed line.
[[nodiscard]] Result<std::vector<StampedPose2>> read_tum_trajectory(
    const std::filesystem::path& path);

}  // namespace tessera
