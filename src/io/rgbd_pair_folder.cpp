#include "tessera/io/rgbd_pair_folder.hpp"

#include <cmath>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "internal/cv_image.hpp"
#include "internal/file_util.hpp"
#include "internal/raw_image.hpp"
#include "internal/text_fields.hpp"

namespace tessera {
namespace {

/// TUM files print 4 decimals, so a quaternion's norm is off by less than 1e-3.
constexpr double kUnitQuaternionTolerance = 0.01;

std::string size_text(const cv::Mat& m) {
  return std::to_string(m.cols) + " x " + std::to_string(m.rows);
}

/// Decodes an image file as stored (no conversion). kInput errors name the file.
Result<cv::Mat> decode(const std::filesystem::path& path) {
  return io_internal::read_image_file(path, cv::IMREAD_UNCHANGED,
                                      io_internal::PngCheck::kStructure);
}

/// One line of numbers from an optional text file: blank lines and '#' comments are skipped, the
/// first other line must hold exactly `count` numbers and nothing may follow it.
Result<std::vector<double>> read_number_line(const std::filesystem::path& path, std::size_t count,
                                             const std::string& layout) {
  Result<std::string> text = io_internal::read_file_bytes(path);
  if (!text) return text.error();
  std::vector<double> values;
  const Status read = io_internal::for_each_record(
      *text, [&](int line_no, const std::vector<std::string_view>& fields) -> Status {
        const std::string where = path.string() + ":" + std::to_string(line_no) + ": ";
        if (!values.empty()) {
          return input_error(where + "expected one line '" + layout + "', got more");
        }
        if (fields.size() != count) {
          return input_error(where + "expected " + std::to_string(count) + " numbers '" + layout +
                             "', got " + std::to_string(fields.size()) + " fields");
        }
        for (const std::string_view f : fields) {
          double v = 0.0;
          if (!io_internal::parse_double(f, v)) {
            return input_error(where + "expected a number, got '" + std::string(f) + "'");
          }
          values.push_back(v);
        }
        return Ok{};
      });
  if (!read) return read.error();
  if (values.empty()) return input_error(path.string() + ": expected a line '" + layout + "'");
  return values;
}

Result<StampedPose3> read_pose(const std::filesystem::path& path) {
  Result<std::vector<double>> v = read_number_line(path, 7, "tx ty tz qx qy qz qw");
  if (!v) return v.error();
  const std::vector<double>& x = *v;
  const Eigen::Quaterniond q(x[6], x[3], x[4], x[5]);
  if (std::abs(q.norm() - 1.0) > kUnitQuaternionTolerance) {
    return input_error(path.string() +
                       ": quaternion (qx qy qz qw) must have unit length, norm is " +
                       io_internal::format_double(q.norm()));
  }
  StampedPose3 pose;
  pose.position_m = Eigen::Vector3d(x[0], x[1], x[2]);
  pose.orientation = q.normalized();
  return pose;
}

Result<PinholeIntrinsics> read_intrinsics(const std::filesystem::path& path) {
  Result<std::vector<double>> v = read_number_line(path, 4, "fx fy cx cy");
  if (!v) return v.error();
  const std::vector<double>& x = *v;
  if (!(x[0] > 0.0) || !(x[1] > 0.0)) {
    return input_error(path.string() + ": focal lengths fx and fy must be > 0 pixels");
  }
  PinholeIntrinsics k;
  k.fx_px = x[0];
  k.fy_px = x[1];
  k.cx_px = x[2];
  k.cy_px = x[3];
  return k;
}

}  // namespace

Result<RgbdFrame> read_rgbd_frame(const std::filesystem::path& colour,
                                  const std::filesystem::path& depth,
                                  const PinholeIntrinsics& intrinsics, double depth_units_per_m) {
  TESSERA_ASSERT(depth_units_per_m > 0.0);
  Result<cv::Mat> c = decode(colour);
  if (!c) return c.error();
  Result<cv::Mat> d = decode(depth);
  if (!d) return d.error();
  const int channels = c->channels();
  if (c->depth() != CV_8U || channels == 2 || channels > 4) {
    return input_error(colour.string() + ": colour must be an 8-bit grey, RGB or RGBA image, got " +
                       io_internal::describe_pixels(*c));
  }
  if (d->depth() != CV_16U || d->channels() != 1) {
    return input_error(depth.string() +
                       ": depth must be a 16-bit single-channel PNG (value / 5000 = metres), got " +
                       io_internal::describe_pixels(*d));
  }
  if (d->size() != c->size()) {
    return input_error(depth.string() + ": depth image is " + size_text(*d) + " but colour image " +
                       colour.string() + " is " + size_text(*c));
  }
  if (intrinsics.width_px != c->cols || intrinsics.height_px != c->rows) {
    return input_error(colour.string() + ": image is " + size_text(*c) +
                       " but the camera intrinsics are for " + std::to_string(intrinsics.width_px) +
                       " x " + std::to_string(intrinsics.height_px));
  }
  RgbdFrame frame;
  frame.width = c->cols;
  frame.height = c->rows;
  frame.intrinsics = intrinsics;
  frame.rgb.resize(3 * frame.pixel_count());
  frame.depth_m.resize(frame.pixel_count());
  std::size_t i = 0;
  for (int row = 0; row < frame.height; ++row) {
    const auto* cp = c->ptr<std::uint8_t>(row);
    const auto* dp = d->ptr<std::uint16_t>(row);
    for (int x = 0; x < frame.width; ++x, ++i) {
      if (channels == 1) {
        frame.rgb[3 * i] = frame.rgb[3 * i + 1] = frame.rgb[3 * i + 2] = cp[x];
      } else {  // OpenCV orders B, G, R(, A)
        frame.rgb[3 * i] = cp[channels * x + 2];
        frame.rgb[3 * i + 1] = cp[channels * x + 1];
        frame.rgb[3 * i + 2] = cp[channels * x];
      }
      frame.depth_m[i] = static_cast<float>(dp[x] / depth_units_per_m);
    }
  }
  return frame;
}

Eigen::Isometry3d RgbdPair::T_prev_curr_truth() const {
  TESSERA_ASSERT(has_ground_truth);
  return T_world_prev.transform().inverse() * T_world_curr.transform();
}

Result<RgbdPair> read_rgbd_pair_folder(const std::filesystem::path& dir) {
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) {
    return input_error(dir.string() + ": not a folder (expected img_prev.png, img_curr.png, " +
                       "dep_prev.png, dep_curr.png)");
  }
  RgbdPair pair;
  PinholeIntrinsics k = PinholeIntrinsics::tum_freiburg1();
  if (std::filesystem::exists(dir / "intrinsics.txt", ec)) {
    Result<PinholeIntrinsics> read = read_intrinsics(dir / "intrinsics.txt");
    if (!read) return read.error();
    // The size comes from the images.
    Result<cv::Mat> c = decode(dir / "img_prev.png");
    if (!c) return c.error();
    read->width_px = c->cols;
    read->height_px = c->rows;
    k = *read;
    pair.has_intrinsics_file = true;
  }
  Result<RgbdFrame> prev = read_rgbd_frame(dir / "img_prev.png", dir / "dep_prev.png", k);
  if (!prev) return prev.error();
  Result<RgbdFrame> curr = read_rgbd_frame(dir / "img_curr.png", dir / "dep_curr.png", k);
  if (!curr) return curr.error();
  pair.prev = std::move(prev).value();
  pair.curr = std::move(curr).value();

  const bool has_prev = std::filesystem::exists(dir / "pose_prev.txt", ec);
  const bool has_curr = std::filesystem::exists(dir / "pose_curr.txt", ec);
  if (has_prev != has_curr) {
    const auto missing = dir / (has_prev ? "pose_curr.txt" : "pose_prev.txt");
    return input_error(missing.string() + ": no such file (ground truth needs pose_prev.txt and " +
                       "pose_curr.txt)");
  }
  if (has_prev) {
    Result<StampedPose3> p = read_pose(dir / "pose_prev.txt");
    if (!p) return p.error();
    Result<StampedPose3> q = read_pose(dir / "pose_curr.txt");
    if (!q) return q.error();
    pair.T_world_prev = *p;
    pair.T_world_curr = *q;
    pair.has_ground_truth = true;
  }
  return pair;
}

}  // namespace tessera
