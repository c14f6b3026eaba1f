#pragma once
// RGB-D frames from image files, as the TUM RGB-D benchmark stores them (Sturm et al. 2012):
// 8-bit colour PNGs and 16-bit depth PNGs whose value / 5000 is the depth in metres (0 = no
// reading), registered to the colour camera. And a frame pair folder, the layout of
// ../shared/data/rgbd/tum_fr1_xyz_pairs/case_*:
//   img_prev.png img_curr.png   colour
//   dep_prev.png dep_curr.png   16-bit depth
//   pose_prev.txt pose_curr.txt optional ground truth, one line "tx ty tz qx qy qz qw" (world <-
//                               camera, TUM convention, quaternion w last); both or neither
//   intrinsics.txt              optional, one line "fx fy cx cy" in pixels; default TUM fr1
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <filesystem>

#include "tessera/core/result.hpp"
#include "tessera/sensors/pinhole_camera.hpp"
#include "tessera/sensors/rgbd_frame.hpp"
#include "tessera/trajectory/stamped_pose3.hpp"

namespace tessera {

/// TUM RGB-D depth PNGs: raw value / 5000 = metres.
inline constexpr double kTumDepthUnitsPerM = 5000.0;

/// Reads one colour + depth image pair into a frame (t_s = 0). The colour image must be 8-bit grey,
/// RGB or RGBA (alpha dropped), the depth image 16-bit single-channel, both of the same size, and
/// `intrinsics` for that size. kInput errors name the offending file: "<file>: no such file",
/// "<file>: depth must be a 16-bit single-channel PNG (value / 5000 = metres), got 8-bit with 3
/// channels", "<depth>: depth image is 320 x 240 but colour image <colour> is 640 x 480".
[[nodiscard]] Result<RgbdFrame> read_rgbd_frame(const std::filesystem::path& colour,
                                                const std::filesystem::path& depth,
                                                const PinholeIntrinsics& intrinsics,
                                                double depth_units_per_m = kTumDepthUnitsPerM);

struct RgbdPair {
  RgbdFrame prev;
  RgbdFrame curr;
  /// True when the folder holds pose_prev.txt and pose_curr.txt; the poses are then T_world_camera
  /// of each frame (t_s = 0).
  bool has_ground_truth = false;
  StampedPose3 T_world_prev;
  StampedPose3 T_world_curr;
  bool has_intrinsics_file = false;

  /// inv(T_world_prev) * T_world_curr: maps points in the current camera frame into the previous
  /// one. Precondition: has_ground_truth.
  [[nodiscard]] Eigen::Isometry3d T_prev_curr_truth() const;
};

/// Reads a pair folder (layout above). kInput errors name the file and, for text files, the line:
/// "<dir>/pose_prev.txt:1: expected 7 numbers 'tx ty tz qx qy qz qw', got 3".
[[nodiscard]] Result<RgbdPair> read_rgbd_pair_folder(const std::filesystem::path& dir);

}  // namespace tessera
