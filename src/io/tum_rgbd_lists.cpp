#include "internal/tum_rgbd_lists.hpp"

#include <algorithm>
#include <cmath>

#include "internal/file_util.hpp"
#include "internal/text_fields.hpp"

namespace tessera::io_internal {
namespace {

std::string where(const std::string& file, int line) {
  return file + ":" + std::to_string(line) + ": ";
}

}  // namespace

Result<std::vector<ListedImage>> decode_tum_image_list(std::string_view text,
                                                       const std::string& path) {
  std::vector<ListedImage> images;
  const Status read = for_each_record(
      text, [&](int line_no, const std::vector<std::string_view>& fields) -> Status {
        if (fields.size() != 2) {
          return input_error(where(path, line_no) + "expected 't filename', got " +
                             std::to_string(fields.size()) + " fields");
        }
        ListedImage image;
        if (!parse_double(fields[0], image.t_s)) {
          return input_error(where(path, line_no) + "expected a time stamp in seconds, got '" +
                             std::string(fields[0]) + "'");
        }
        image.name = std::string(fields[1]);
        image.line = line_no;
        images.push_back(std::move(image));
        return Ok{};
      });
  if (!read) return read.error();
  std::stable_sort(images.begin(), images.end(),
                   [](const ListedImage& a, const ListedImage& b) { return a.t_s < b.t_s; });
  return images;
}

std::vector<std::pair<std::size_t, std::size_t>> associate(const std::vector<ListedImage>& rgb,
                                                           const std::vector<ListedImage>& depth,
                                                           double max_difference_s) {
  struct Candidate {
    double difference;
    std::size_t a, b;
  };
  std::vector<Candidate> candidates;
  std::size_t lo = 0;
  for (std::size_t i = 0; i < rgb.size(); ++i) {
    while (lo < depth.size() && depth[lo].t_s < rgb[i].t_s - max_difference_s) ++lo;
    for (std::size_t j = lo; j < depth.size() && depth[j].t_s <= rgb[i].t_s + max_difference_s;
         ++j) {
      candidates.push_back({std::abs(rgb[i].t_s - depth[j].t_s), i, j});
    }
  }
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& x, const Candidate& y) {
    if (x.difference != y.difference) return x.difference < y.difference;
    if (x.a != y.a) return x.a < y.a;
    return x.b < y.b;
  });
  std::vector<bool> used_a(rgb.size(), false), used_b(depth.size(), false);
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (const Candidate& c : candidates) {
    if (used_a[c.a] || used_b[c.b]) continue;
    used_a[c.a] = used_b[c.b] = true;
    pairs.emplace_back(c.a, c.b);
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

Result<PinholeIntrinsics> decode_tum_intrinsics(std::string_view text, const std::string& path,
                                                bool& has_size) {
  std::vector<double> v;
  const Status read = for_each_record(
      text, [&](int line_no, const std::vector<std::string_view>& fields) -> Status {
        if (!v.empty()) {
          return input_error(where(path, line_no) +
                             "expected one line 'fx fy cx cy [width height]'");
        }
        if (fields.size() != 4 && fields.size() != 6) {
          return input_error(where(path, line_no) + "expected 'fx fy cx cy [width height]', got " +
                             std::to_string(fields.size()) + " fields");
        }
        for (const std::string_view f : fields) {
          double x = 0.0;
          if (!parse_double(f, x)) {
            return input_error(where(path, line_no) + "expected a number, got '" + std::string(f) +
                               "'");
          }
          v.push_back(x);
        }
        if (!(v[0] > 0.0) || !(v[1] > 0.0)) {
          return input_error(where(path, line_no) + "focal lengths fx and fy must be > 0 pixels");
        }
        if (v.size() == 6 && !(v[4] >= 1.0 && v[5] >= 1.0 && v[4] == std::floor(v[4]) &&
                               v[5] == std::floor(v[5]) && v[4] <= 65535.0 && v[5] <= 65535.0)) {
          return input_error(where(path, line_no) +
                             "width and height must be positive whole pixels");
        }
        return Ok{};
      });
  if (!read) return read.error();
  if (v.empty()) return input_error(path + ": expected a line 'fx fy cx cy [width height]'");
  PinholeIntrinsics k;
  k.fx_px = v[0];
  k.fy_px = v[1];
  k.cx_px = v[2];
  k.cy_px = v[3];
  has_size = v.size() == 6;
  if (has_size) {
    k.width_px = static_cast<int>(v[4]);
    k.height_px = static_cast<int>(v[5]);
  }
  return k;
}

Result<std::vector<std::pair<double, double>>> decode_tum_neck(std::string_view text,
                                                               const std::string& path) {
  std::vector<std::pair<double, double>> out;
  const Status read = for_each_record(
      text, [&](int line_no, const std::vector<std::string_view>& fields) -> Status {
        double t = 0.0, pan = 0.0;
        if (fields.size() != 2 || !parse_double(fields[0], t) || !parse_double(fields[1], pan)) {
          return input_error(where(path, line_no) + "expected 't neck_pan_rad' (two numbers)");
        }
        out.emplace_back(t, pan);
        return Ok{};
      });
  if (!read) return read.error();
  std::stable_sort(out.begin(), out.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  return out;
}

}  // namespace tessera::io_internal
