#include "tessera/render/wall_textures.hpp"

#include <algorithm>
#include <cctype>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>

#include "internal/cv_image.hpp"
#include "internal/file_util.hpp"

namespace tessera {
namespace {

/// Natural order of two names: runs of digits compare by value, the rest by character.
bool natural_less(const std::string& a, const std::string& b) {
  std::size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    const bool da = std::isdigit(static_cast<unsigned char>(a[i])) != 0;
    const bool db = std::isdigit(static_cast<unsigned char>(b[j])) != 0;
    if (da && db) {
      std::size_t ie = i, je = j;
      while (ie < a.size() && std::isdigit(static_cast<unsigned char>(a[ie])) != 0) ++ie;
      while (je < b.size() && std::isdigit(static_cast<unsigned char>(b[je])) != 0) ++je;
      // Compare by value: strip leading zeros, then length, then digits.
      std::size_t is = i, js = j;
      while (is + 1 < ie && a[is] == '0') ++is;
      while (js + 1 < je && b[js] == '0') ++js;
      if (ie - is != je - js) return ie - is < je - js;
      const int c = a.compare(is, ie - is, b, js, je - js);
      if (c != 0) return c < 0;
      i = ie;
      j = je;
    } else {
      if (a[i] != b[j]) return a[i] < b[j];
      ++i;
      ++j;
    }
  }
  return a.size() - i < b.size() - j;
}

bool natural_path_less(const std::filesystem::path& a, const std::filesystem::path& b) {
  auto ia = a.begin(), ib = b.begin();
  for (; ia != a.end() && ib != b.end(); ++ia, ++ib) {
    const std::string sa = ia->string(), sb = ib->string();
    if (sa == sb) continue;
    return natural_less(sa, sb);
  }
  return ia == a.end() && ib != b.end();
}

bool is_texture_file(const std::filesystem::path& p, std::string_view prefix) {
  const std::string ext = io_internal::lower_extension(p);
  if (ext != ".jpg" && ext != ".jpeg" && ext != ".png") return false;
  return p.filename().string().starts_with(prefix);
}

}  // namespace

Result<std::vector<std::filesystem::path>> list_texture_images(const std::filesystem::path& folder,
                                                               bool recursive,
                                                               std::string_view name_prefix) {
  std::error_code ec;
  if (!std::filesystem::is_directory(folder, ec)) {
    return input_error(folder.string() + ": not a folder (expected photos as .jpg or .png)");
  }
  std::vector<std::filesystem::path> files;
  const auto consider = [&](const std::filesystem::directory_entry& e) {
    std::error_code ec2;
    if (e.is_regular_file(ec2) && is_texture_file(e.path(), name_prefix)) files.push_back(e.path());
  };
  if (recursive) {
    for (const auto& e : std::filesystem::recursive_directory_iterator(folder, ec)) consider(e);
  } else {
    for (const auto& e : std::filesystem::directory_iterator(folder, ec)) consider(e);
  }
  if (ec) return input_error(folder.string() + ": cannot list: " + ec.message());
  if (files.empty()) {
    return input_error(
        folder.string() + ": no .jpg, .jpeg or .png file" +
        (name_prefix.empty() ? std::string() : " named '" + std::string(name_prefix) + "*'") +
        (recursive ? " in it or its sub-folders" : ""));
  }
  std::sort(files.begin(), files.end(), natural_path_less);
  return files;
}

Result<WallTexture> read_wall_texture(const std::filesystem::path& path) {
  Result<cv::Mat> decoded =
      io_internal::read_image_file(path, cv::IMREAD_UNCHANGED, io_internal::PngCheck::kNone);
  if (!decoded) return decoded.error();
  const cv::Mat& m = *decoded;
  const int channels = m.channels();
  if (m.depth() != CV_8U || channels == 2 || channels > 4) {
    return input_error(path.string() +
                       ": a wall texture must be an 8-bit grey, RGB or RGBA image, got " +
                       io_internal::describe_pixels(m));
  }
  WallTexture t;
  t.width = m.cols;
  t.height = m.rows;
  t.name = path.filename().string();
  t.rgb.resize(3 * static_cast<std::size_t>(t.width) * static_cast<std::size_t>(t.height));
  std::size_t i = 0;
  for (int row = 0; row < m.rows; ++row) {
    const auto* p = m.ptr<std::uint8_t>(row);
    for (int x = 0; x < m.cols; ++x, i += 3) {
      if (channels == 1) {
        t.rgb[i] = t.rgb[i + 1] = t.rgb[i + 2] = p[x];
      } else {  // OpenCV orders B, G, R(, A)
        t.rgb[i] = p[channels * x + 2];
        t.rgb[i + 1] = p[channels * x + 1];
        t.rgb[i + 2] = p[channels * x];
      }
    }
  }
  return t;
}

Result<std::vector<WallTexture>> read_wall_textures(
    const std::vector<std::filesystem::path>& paths) {
  std::vector<WallTexture> textures;
  textures.reserve(paths.size());
  for (const auto& p : paths) {
    Result<WallTexture> t = read_wall_texture(p);
    if (!t) return t.error();
    textures.push_back(std::move(t).value());
  }
  return textures;
}

}  // namespace tessera
