#include "tessera/io/tum_rgbd_sequence.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string_view>
#include <utility>

#include "internal/cv_image.hpp"
#include "internal/file_util.hpp"
#include "internal/text_fields.hpp"
#include "internal/tum_rgbd_lists.hpp"
#include "tessera/core/angle.hpp"
#include "tessera/io/rgbd_pair_folder.hpp"
#include "tessera/io/tum_trajectory.hpp"

namespace tessera {
namespace {

using io_internal::associate;
using io_internal::ListedImage;

std::string where(const std::filesystem::path& file, int line) {
  return file.string() + ":" + std::to_string(line) + ": ";
}

/// Reads a TUM image list (decode_tum_image_list), saying which list is missing.
Result<std::vector<ListedImage>> read_image_list(const std::filesystem::path& path,
                                                 const std::string& what) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    return input_error(path.string() + ": no such file (a TUM RGB-D folder lists its " + what +
                       " images in it)");
  }
  Result<std::string> text = io_internal::read_file_bytes(path);
  if (!text) return text.error();
  return io_internal::decode_tum_image_list(*text, path.string());
}

Result<PinholeIntrinsics> read_intrinsics_file(const std::filesystem::path& path, bool& has_size) {
  Result<std::string> text = io_internal::read_file_bytes(path);
  if (!text) return text.error();
  return io_internal::decode_tum_intrinsics(*text, path.string(), has_size);
}

Result<std::vector<std::pair<double, double>>> read_neck_file(const std::filesystem::path& path) {
  Result<std::string> text = io_internal::read_file_bytes(path);
  if (!text) return text.error();
  return io_internal::decode_tum_neck(*text, path.string());
}

/// Index of the sample nearest to t within max_difference_s in a list sorted by stamp; -1 if none.
template <typename T, typename Stamp>
std::ptrdiff_t nearest(const std::vector<T>& samples, double t, double max_difference_s,
                       Stamp stamp) {
  const auto it = std::lower_bound(samples.begin(), samples.end(), t,
                                   [&](const T& s, double v) { return stamp(s) < v; });
  std::ptrdiff_t best = -1;
  double best_d = max_difference_s;
  const std::ptrdiff_t k = it - samples.begin();
  for (std::ptrdiff_t j = k - 1; j <= k; ++j) {
    if (j < 0 || j >= static_cast<std::ptrdiff_t>(samples.size())) continue;
    const double d = std::abs(stamp(samples[static_cast<std::size_t>(j)]) - t);
    if (d <= best_d) {
      best_d = d;
      best = j;
    }
  }
  return best;
}

/// Ground truth at t (see TumRgbdEntry). `truth` sorted by stamp.
bool truth_at(const std::vector<StampedPose3>& truth, double t, StampedPose3& out) {
  const auto it = std::lower_bound(truth.begin(), truth.end(), t,
                                   [](const StampedPose3& s, double v) { return s.t_s < v; });
  if (it != truth.end() && it != truth.begin()) {
    const StampedPose3& a = *(it - 1);
    const StampedPose3& b = *it;
    if (t - a.t_s <= kTumMaxStampDifferenceS && b.t_s - t <= kTumMaxStampDifferenceS &&
        b.t_s > a.t_s) {
      const double s = (t - a.t_s) / (b.t_s - a.t_s);
      out.t_s = t;
      out.position_m = (1.0 - s) * a.position_m + s * b.position_m;
      out.orientation = a.orientation.normalized().slerp(s, b.orientation.normalized());
      return true;
    }
  }
  const std::ptrdiff_t j =
      nearest(truth, t, kTumMaxStampDifferenceS, [](const StampedPose3& s) { return s.t_s; });
  if (j < 0) return false;
  out = truth[static_cast<std::size_t>(j)];
  out.t_s = t;
  return true;
}

/// The TUM camera a folder name names, if any.
bool freiburg_from_name(const std::filesystem::path& folder, PinholeIntrinsics& k,
                        IntrinsicsSource& source) {
  std::filesystem::path p = folder;
  if (!p.has_filename()) p = p.parent_path();  // "dir/" -> "dir"
  const std::string name = p.filename().string();
  if (name.find("freiburg1") != std::string::npos) {
    k = PinholeIntrinsics::tum_freiburg1();
    source = IntrinsicsSource::kFreiburg1;
  } else if (name.find("freiburg2") != std::string::npos) {
    k = PinholeIntrinsics::tum_freiburg2();
    source = IntrinsicsSource::kFreiburg2;
  } else if (name.find("freiburg3") != std::string::npos) {
    k = PinholeIntrinsics::tum_freiburg3();
    source = IntrinsicsSource::kFreiburg3;
  } else {
    return false;
  }
  return true;
}

// --- writing ---------------------------------------------------------------------------------

Status write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  out.close();
  if (!out) return runtime_error(path.string() + ": cannot write");
  return Ok{};
}

Status write_png(const std::filesystem::path& path, const cv::Mat& m) {
  Result<std::string> bytes = io_internal::encode_png_bytes(m);
  if (!bytes) return runtime_error(path.string() + ": " + bytes.error().message);
  return write_text(path, *bytes);
}

std::string stamp_text(double t_s) {
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.6f", t_s);
  return buffer;
}

/// Everything of the sequence into `dir` (a fresh folder).
Status write_contents(const std::filesystem::path& dir, const TumRgbdSequenceContent& c) {
  std::error_code ec;
  std::filesystem::create_directories(dir / "rgb", ec);
  if (!ec) std::filesystem::create_directories(dir / "depth", ec);
  if (ec) return runtime_error(dir.string() + ": cannot create folder: " + ec.message());
  std::string rgb_list = "# color images\n# timestamp filename\n";
  std::string depth_list = "# depth maps\n# timestamp filename\n";
  PinholeIntrinsics k;
  double last_t = -std::numeric_limits<double>::infinity();
  std::string last_stamp;
  std::vector<double> stamps;
  for (std::size_t i = 0; i < c.frame_count; ++i) {
    const RgbdFrame f = c.frame_at(i);
    if (!f.consistent()) {
      return runtime_error("frame " + std::to_string(i) +
                           ": buffers do not match its size and intrinsics");
    }
    const std::string stamp = stamp_text(f.t_s);
    if (i > 0 && (!(f.t_s > last_t) || stamp == last_stamp)) {
      return runtime_error("frame " + std::to_string(i) + ": stamp " + stamp +
                           " s does not increase (file names would clash)");
    }
    if (i == 0) k = f.intrinsics;
    last_t = f.t_s;
    last_stamp = stamp;
    stamps.push_back(f.t_s);
    cv::Mat bgr(f.height, f.width, CV_8UC3);
    cv::Mat depth(f.height, f.width, CV_16UC1);
    std::size_t p = 0;
    for (int row = 0; row < f.height; ++row) {
      auto* b = bgr.ptr<std::uint8_t>(row);
      auto* d = depth.ptr<std::uint16_t>(row);
      for (int x = 0; x < f.width; ++x, ++p) {
        b[3 * x] = f.rgb[3 * p + 2];
        b[3 * x + 1] = f.rgb[3 * p + 1];
        b[3 * x + 2] = f.rgb[3 * p];
        const double raw = std::round(static_cast<double>(f.depth_m[p]) * kTumDepthUnitsPerM);
        d[x] = raw > 0.0 && raw <= 65535.0 ? static_cast<std::uint16_t>(raw) : 0;
      }
    }
    const std::string rgb_name = "rgb/" + stamp + ".png";
    const std::string depth_name = "depth/" + stamp + ".png";
    if (Status s = write_png(dir / rgb_name, bgr); !s) return s;
    if (Status s = write_png(dir / depth_name, depth); !s) return s;
    rgb_list += stamp + " " + rgb_name + "\n";
    depth_list += stamp + " " + depth_name + "\n";
  }
  if (Status s = write_text(dir / "rgb.txt", rgb_list); !s) return s;
  if (Status s = write_text(dir / "depth.txt", depth_list); !s) return s;
  char line[256];
  std::snprintf(line, sizeof(line), "%.17g %.17g %.17g %.17g %d %d\n", k.fx_px, k.fy_px, k.cx_px,
                k.cy_px, k.width_px, k.height_px);
  if (Status s = write_text(dir / "intrinsics.txt",
                            std::string("# fx fy cx cy width height (pixels)\n") + line);
      !s) {
    return s;
  }
  if (!c.ground_truth.empty()) {
    std::string text =
        "# ground truth trajectory: T_world_camera of the optical frame\n"
        "# timestamp tx ty tz qx qy qz qw\n";
    for (const StampedPose3& p : c.ground_truth) {
      const Eigen::Quaterniond q = p.orientation.normalized();
      std::snprintf(line, sizeof(line), "%.6f %.6f %.6f %.6f %.9f %.9f %.9f %.9f\n", p.t_s,
                    p.position_m.x(), p.position_m.y(), p.position_m.z(), q.x(), q.y(), q.z(),
                    q.w());
      text += line;
    }
    if (Status s = write_text(dir / "groundtruth.txt", text); !s) return s;
  }
  if (!c.odometry.empty()) {
    if (Status s = write_text(dir / "odometry.txt", encode_tum_trajectory(c.odometry)); !s) {
      return s;
    }
  }
  if (!c.neck_pan_rad.empty()) {
    std::string text = "# timestamp neck_pan_rad\n";
    for (std::size_t i = 0; i < c.neck_pan_rad.size(); ++i) {
      std::snprintf(line, sizeof(line), "%.6f %.9f\n", stamps[i], c.neck_pan_rad[i]);
      text += line;
    }
    if (Status s = write_text(dir / "neck.txt", text); !s) return s;
  }
  return Ok{};
}

}  // namespace

Result<TumRgbdSequence> TumRgbdSequence::open(const std::filesystem::path& folder) {
  std::error_code ec;
  if (!std::filesystem::is_directory(folder, ec)) {
    return input_error(folder.string() + ": not a folder (expected a TUM RGB-D sequence with " +
                       "rgb.txt and depth.txt)");
  }
  TumRgbdSequence seq;
  seq.folder_ = folder;
  const std::filesystem::path rgb_txt = folder / "rgb.txt";
  const std::filesystem::path depth_txt = folder / "depth.txt";
  Result<std::vector<ListedImage>> rgb = read_image_list(rgb_txt, "colour");
  if (!rgb) return rgb.error();
  Result<std::vector<ListedImage>> depth = read_image_list(depth_txt, "depth");
  if (!depth) return depth.error();
  const auto pairs = associate(*rgb, *depth, kTumMaxStampDifferenceS);
  if (pairs.empty()) {
    return input_error(rgb_txt.string() + " and " + depth_txt.string() + ": no colour and depth " +
                       "stamps within 0.02 s of each other (" + std::to_string(rgb->size()) +
                       " colour, " + std::to_string(depth->size()) + " depth images)");
  }

  // Intrinsics.
  const std::filesystem::path intrinsics_txt = folder / "intrinsics.txt";
  bool size_known = true;
  if (std::filesystem::exists(intrinsics_txt, ec)) {
    Result<PinholeIntrinsics> k = read_intrinsics_file(intrinsics_txt, size_known);
    if (!k) return k.error();
    seq.intrinsics_ = *k;
    seq.intrinsics_source_ = IntrinsicsSource::kFile;
  } else if (!freiburg_from_name(folder, seq.intrinsics_, seq.intrinsics_source_)) {
    return input_error(intrinsics_txt.string() + ": no such file, and the folder's name names " +
                       "no TUM camera (freiburg1, freiburg2, freiburg3): write the camera's " +
                       "'fx fy cx cy width height' there");
  }

  for (const auto& [a, b] : pairs) {
    const ListedImage& r = (*rgb)[a];
    const ListedImage& d = (*depth)[b];
    TumRgbdEntry e;
    e.t_s = r.t_s;
    e.depth_t_s = d.t_s;
    e.rgb_path = folder / r.name;
    e.depth_path = folder / d.name;
    if (!std::filesystem::is_regular_file(e.rgb_path, ec)) {
      return input_error(where(rgb_txt, r.line) + r.name + ": no such file");
    }
    if (!std::filesystem::is_regular_file(e.depth_path, ec)) {
      return input_error(where(depth_txt, d.line) + d.name + ": no such file");
    }
    seq.entries_.push_back(std::move(e));
  }

  if (!size_known) {
    // "fx fy cx cy" only: the size is the first colour image's.
    Result<cv::Mat> m = io_internal::read_image_file(seq.entries_[0].rgb_path, cv::IMREAD_UNCHANGED,
                                                     io_internal::PngCheck::kNone);
    if (!m) return m.error();
    seq.intrinsics_.width_px = m->cols;
    seq.intrinsics_.height_px = m->rows;
  }

  const std::filesystem::path truth_txt = folder / "groundtruth.txt";
  if (std::filesystem::exists(truth_txt, ec)) {
    Result<std::vector<StampedPose3>> truth = read_tum_trajectory3(truth_txt);
    if (!truth) return truth.error();
    std::vector<StampedPose3> sorted = std::move(truth).value();
    std::stable_sort(sorted.begin(), sorted.end(),
                     [](const StampedPose3& x, const StampedPose3& y) { return x.t_s < y.t_s; });
    seq.has_ground_truth_file_ = true;
    for (TumRgbdEntry& e : seq.entries_) e.has_truth = truth_at(sorted, e.t_s, e.T_world_camera);
  }
  const std::filesystem::path odometry_txt = folder / "odometry.txt";
  if (std::filesystem::exists(odometry_txt, ec)) {
    Result<std::vector<StampedPose2>> odometry = read_tum_trajectory(odometry_txt);
    if (!odometry) return odometry.error();
    std::vector<StampedPose2> sorted = std::move(odometry).value();
    std::stable_sort(sorted.begin(), sorted.end(),
                     [](const StampedPose2& x, const StampedPose2& y) { return x.t_s < y.t_s; });
    for (TumRgbdEntry& e : seq.entries_) {
      const std::ptrdiff_t j = nearest(sorted, e.t_s, kTumMaxStampDifferenceS,
                                       [](const StampedPose2& s) { return s.t_s; });
      if (j >= 0) {
        e.has_odometry = true;
        e.odometry = sorted[static_cast<std::size_t>(j)].pose;
      }
    }
  }
  const std::filesystem::path neck_txt = folder / "neck.txt";
  if (std::filesystem::exists(neck_txt, ec)) {
    Result<std::vector<std::pair<double, double>>> neck = read_neck_file(neck_txt);
    if (!neck) return neck.error();
    for (TumRgbdEntry& e : seq.entries_) {
      const std::ptrdiff_t j = nearest(*neck, e.t_s, kTumMaxStampDifferenceS,
                                       [](const std::pair<double, double>& s) { return s.first; });
      if (j >= 0) {
        e.has_neck = true;
        e.neck_pan_rad = (*neck)[static_cast<std::size_t>(j)].second;
      }
    }
  }
  return seq;
}

Result<RgbdFrame> TumRgbdSequence::load(std::size_t i) const {
  TESSERA_ASSERT(i < entries_.size());
  const TumRgbdEntry& e = entries_[i];
  Result<RgbdFrame> frame = read_rgbd_frame(e.rgb_path, e.depth_path, intrinsics_);
  if (!frame) return frame.error();
  frame->t_s = e.t_s;
  return frame;
}

Status write_tum_rgbd_sequence(const std::filesystem::path& folder,
                               const TumRgbdSequenceContent& content) {
  const std::size_t n = content.frame_count;
  if (!content.frame_at && n > 0) return runtime_error("rgbd sequence: no frame source given");
  if ((!content.ground_truth.empty() && content.ground_truth.size() != n) ||
      (!content.odometry.empty() && content.odometry.size() != n) ||
      (!content.neck_pan_rad.empty() && content.neck_pan_rad.size() != n)) {
    return runtime_error("rgbd sequence: ground truth, odometry and neck angles need one entry " +
                         std::string("per frame (") + std::to_string(n) + ") or none");
  }
  std::filesystem::path target = folder;
  if (!target.has_filename()) target = target.parent_path();
  if (target.empty()) return runtime_error("'" + folder.string() + "': not a folder name");
  std::error_code ec;
  if (std::filesystem::exists(target, ec) && !std::filesystem::is_directory(target, ec)) {
    return runtime_error(target.string() + ": cannot write a sequence: a file is in the way");
  }
  const std::string pid = std::to_string(static_cast<long long>(::getpid()));
  std::filesystem::path tmp = target;
  tmp += ".tmp-" + pid;
  std::filesystem::remove_all(tmp, ec);
  if (Status s = write_contents(tmp, content); !s) {
    std::filesystem::remove_all(tmp, ec);
    return s;
  }
  // Swap the new folder in: an old one moves aside first (rename(2) cannot replace a non-empty
  // folder), and is removed once the new one is in place.
  std::filesystem::path old = target;
  old += ".old-" + pid;
  const bool had_old = std::filesystem::exists(target, ec);
  if (had_old) {
    std::filesystem::remove_all(old, ec);
    std::filesystem::rename(target, old, ec);
    if (ec) {
      const std::string reason = ec.message();
      std::filesystem::remove_all(tmp, ec);
      return runtime_error(target.string() + ": cannot replace: " + reason);
    }
  }
  std::filesystem::rename(tmp, target, ec);
  if (ec) {
    const std::string reason = ec.message();
    std::filesystem::remove_all(tmp, ec);
    if (had_old) std::filesystem::rename(old, target, ec);
    return runtime_error(target.string() + ": cannot write: " + reason);
  }
  if (had_old) std::filesystem::remove_all(old, ec);
  return Ok{};
}

Pose2 robot_pose_from_optical_frame(const StampedPose3& T_world_camera, double neck_pan_rad) {
  const Eigen::Vector3d z = T_world_camera.orientation.normalized() * Eigen::Vector3d::UnitZ();
  const double heading = std::atan2(z.y(), z.x());
  return {T_world_camera.position_m.x(), T_world_camera.position_m.y(),
          normalize_angle(heading - neck_pan_rad)};
}

}  // namespace tessera
