#pragma once
// TUM RGB-D sequence folders (Sturm et al. 2012, "A Benchmark for the Evaluation of RGB-D SLAM
// Systems", IROS; file formats at cvg.cit.tum.de/data/datasets/rgbd-dataset/file_formats):
//   rgb.txt, depth.txt   "t filename" per line, '#' comments; images relative to the folder
//   rgb/*.png            8-bit colour
//   depth/*.png          16-bit, value / 5000 = metres along the optical axis, 0 = no reading
//   groundtruth.txt      optional, "t tx ty tz qx qy qz qw": T_world_camera of the colour camera's
//                        optical frame (x right, y down, z forward)
// and tessera's additions, all optional:
//   intrinsics.txt       one line "fx fy cx cy" or "fx fy cx cy width height" (pixels), as in
//                        io/rgbd_pair_folder.hpp
//   odometry.txt         TUM trajectory of the robot base as wheel odometry reports it (z = 0)
//   neck.txt             "t neck_pan_rad" per line: the camera's pan on the robot (sim/rgbd_camera)
//
// Reading is lazy (sequences hold thousands of frames): open() reads the lists and associates
// them; load(i) decodes one frame. The simulator's runs are written in the same layout
// (render/simulated_rgbd_sequence.hpp), so every experiment runs the same way on simulated and
// real data.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "tessera/core/pose2.hpp"
#include "tessera/core/result.hpp"
#include "tessera/core/stamped_pose2.hpp"
#include "tessera/trajectory/stamped_pose3.hpp"
#include "tessera/sensors/pinhole_camera.hpp"
#include "tessera/sensors/rgbd_frame.hpp"

namespace tessera {

/// TUM's associate.py default: colour and depth stamps further apart than this are no pair.
inline constexpr double kTumMaxStampDifferenceS = 0.02;

/// Where a sequence's intrinsics came from.
enum class IntrinsicsSource { kFile, kFreiburg1, kFreiburg2, kFreiburg3 };

/// One associated colour/depth pair and what is known about it.
struct TumRgbdEntry {
  double t_s = 0.0;        // the colour image's stamp: the frame's stamp
  double depth_t_s = 0.0;  // the depth image's stamp
  std::filesystem::path rgb_path;    // folder / the listed name
  std::filesystem::path depth_path;
  /// Ground truth at t_s: interpolated (linear position, slerp) between the two samples around
  /// t_s when both are within kTumMaxStampDifferenceS, else the nearest sample within it.
  bool has_truth = false;
  StampedPose3 T_world_camera;
  /// tessera's additions, the nearest sample within kTumMaxStampDifferenceS.
  bool has_odometry = false;
  Pose2 odometry;  // T_odom_robot
  bool has_neck = false;
  double neck_pan_rad = 0.0;
};

class TumRgbdSequence {
 public:
  /// Reads rgb.txt and depth.txt and associates them as TUM's associate.py does: every pair of a
  /// colour and a depth stamp at most 0.02 s apart is a candidate, candidates are taken greedily
  /// by smallest difference, each stamp is used once; the pairs are sorted by colour stamp.
  /// Checks that every associated image exists (not its content: load() decodes).
  /// Intrinsics: intrinsics.txt when present; else the folder's name names the TUM camera
  /// ("freiburg1", "freiburg2", "freiburg3", as rgbd_dataset_freiburg1_xyz; TUM's published
  /// calibration, sensors/pinhole_camera.hpp); else an input error asking for intrinsics.txt
  /// (a guess would silently bias every 3D point).
  /// Input errors, each one line naming the file (and line): not a folder, no rgb.txt or
  /// depth.txt, a malformed line ("<dir>/rgb.txt:7: expected 't filename', got 3 fields"), a
  /// missing image ("<dir>/depth.txt:12: depth/1.5.png: no such file"), no colour and depth stamp
  /// within 0.02 s, a bad intrinsics, groundtruth, odometry or neck file.
  /// Cost: O(n log n) in the lines, one stat per image.
  [[nodiscard]] static Result<TumRgbdSequence> open(const std::filesystem::path& folder);

  [[nodiscard]] const std::filesystem::path& folder() const { return folder_; }
  [[nodiscard]] std::size_t size() const { return entries_.size(); }
  [[nodiscard]] const std::vector<TumRgbdEntry>& entries() const { return entries_; }
  [[nodiscard]] const TumRgbdEntry& entry(std::size_t i) const { return entries_[i]; }
  [[nodiscard]] const PinholeIntrinsics& intrinsics() const { return intrinsics_; }
  [[nodiscard]] IntrinsicsSource intrinsics_source() const { return intrinsics_source_; }
  /// True when the folder has groundtruth.txt (frames outside its time span have no truth).
  [[nodiscard]] bool has_ground_truth_file() const { return has_ground_truth_file_; }

  /// Decodes frame i (t_s = the colour stamp). Input errors name the image: "<file>: depth must
  /// be a 16-bit single-channel PNG ...", "<depth>: depth image is 320 x 240 but colour image ...
  /// is 640 x 480" (io/rgbd_pair_folder.hpp read_rgbd_frame). Precondition: i < size().
  [[nodiscard]] Result<RgbdFrame> load(std::size_t i) const;

 private:
  std::filesystem::path folder_;
  std::vector<TumRgbdEntry> entries_;
  PinholeIntrinsics intrinsics_;
  IntrinsicsSource intrinsics_source_ = IntrinsicsSource::kFile;
  bool has_ground_truth_file_ = false;
};

/// What write_tum_rgbd_sequence writes: frame_count frames produced one at a time by frame_at
/// (never all in memory), and optional per-frame data (empty, or one per frame).
struct TumRgbdSequenceContent {
  std::size_t frame_count = 0;
  std::function<RgbdFrame(std::size_t)> frame_at;
  std::vector<StampedPose3> ground_truth;  // T_world_camera (optical frame)
  std::vector<StampedPose2> odometry;      // T_odom_robot
  std::vector<double> neck_pan_rad;
};

/// Writes a TUM sequence folder (layout above, intrinsics.txt with the size): rgb/<t>.png and
/// depth/<t>.png named by the stamp with 6 decimals; depth as round(z * 5000), 0 for no reading
/// and for depths beyond 65535 / 5000 = 13.1 m. Atomic: everything goes into the sibling folder
/// "<folder>.tmp-<pid>", which is then renamed to `folder` (an existing `folder` is replaced; a
/// file in the way is an error). On failure nothing is left behind. Runtime errors: frames whose
/// stamps do not increase or whose buffers are inconsistent, a per-frame list of the wrong length,
/// a file that cannot be written. Cost: one PNG encode per image.
[[nodiscard]] Status write_tum_rgbd_sequence(const std::filesystem::path& folder,
                                             const TumRgbdSequenceContent& content);

/// The robot's T_world_robot from a level camera's optical-frame pose (z forward, x right, y down)
/// and the neck angle: the camera's heading minus the pan; height and tilt dropped. The inverse of
/// render/simulated_rgbd_sequence.hpp's optical_frame_pose.
[[nodiscard]] Pose2 robot_pose_from_optical_frame(const StampedPose3& T_world_camera,
                                                  double neck_pan_rad);

}  // namespace tessera
