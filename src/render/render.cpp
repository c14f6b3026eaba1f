#include "tessera/render/render.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <string>

#include "internal/cv_image.hpp"
#include "tessera/io/atomic_file.hpp"
#include "tessera/io/image_file.hpp"

namespace tessera {
namespace {

constexpr std::int64_t kMaxPixels = std::int64_t{1} << 28;

cv::Scalar to_scalar(Rgb c) { return cv::Scalar(c.r, c.g, c.b); }  // the Mat is R, G, B

void fill_cell(cv::Mat& image, Cell c, int height_cells, int ppc, Rgb color) {
  const cv::Rect rect(c.x * ppc, (height_cells - 1 - c.y) * ppc, ppc, ppc);
  image(rect).setTo(to_scalar(color));
}

// Pixel at the centre of the cell containing p_m (image row 0 is the top).
cv::Point cell_center_px(const GridGeometry& g, Vec2 p_m, int ppc) {
  const Cell c = g.cell_at_unchecked(p_m);
  return {c.x * ppc + ppc / 2, (g.height() - 1 - c.y) * ppc + ppc / 2};
}

}  // namespace

int auto_pixels_per_cell(int width_cells, int height_cells) {
  const int long_side = std::max(width_cells, height_cells);
  if (long_side <= 0) return 1;
  return std::max(1, (1000 + long_side - 1) / long_side);
}

Result<RgbImage> render_image(const RenderLayers& layers, int pixels_per_cell) {
  if (layers.map == nullptr) return input_error("render: no map to draw");
  if (pixels_per_cell < 0) {
    return input_error("render: pixels per cell must be >= 0 (0 = automatic), got " +
                       std::to_string(pixels_per_cell));
  }
  const OccupancyGrid& map = *layers.map;
  const GridGeometry& g = map.geometry();
  if (g.width() == 0 || g.height() == 0) return input_error("render: the map has no cells");
  const int ppc =
      pixels_per_cell == 0 ? auto_pixels_per_cell(g.width(), g.height()) : pixels_per_cell;
  const std::int64_t w_px = std::int64_t{g.width()} * ppc, h_px = std::int64_t{g.height()} * ppc;
  if (w_px * h_px > kMaxPixels) {
    return input_error("render: a " + std::to_string(w_px) + " x " + std::to_string(h_px) +
                       " px picture is too large; use fewer pixels per cell");
  }
  cv::Mat image(static_cast<int>(h_px), static_cast<int>(w_px), CV_8UC3);

  // Cells: probability shaded (free white, occupied black), unknown grey, truth errors coloured.
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) {
      const Cell c{x, y};
      Rgb color = kUnknownColor;
      if (const std::optional<double> p = map.probability_at(c)) {
        const auto v = static_cast<std::uint8_t>(std::lround(255.0 * (1.0 - *p)));
        color = {v, v, v};
        if (layers.truth != nullptr) {
          const bool solid = layers.truth->solid(
              layers.truth->geometry().cell_at_unchecked(layers.T_truth_map * g.center_of(c)));
          const CellState state = map.state(c);
          if (state == CellState::kFree && solid) color = kOccupiedAsEmptyColor;
          if (state == CellState::kOccupied && !solid) color = kEmptyAsOccupiedColor;
        }
      }
      fill_cell(image, c, g.height(), ppc, color);
    }
  }
  for (const Cell c : layers.frontier) {
    if (g.contains(c)) fill_cell(image, c, g.height(), ppc, kFrontierColor);
  }

  // Paths between cell centres, then each robot's final position as a dot in its path's colour.
  constexpr std::size_t kPalette = sizeof(kPathPalette) / sizeof(kPathPalette[0]);
  const int thickness = std::max(1, ppc / 4);
  for (std::size_t i = 0; i < layers.paths_m.size(); ++i) {
    const std::vector<Vec2>& path = layers.paths_m[i];
    const cv::Scalar color = to_scalar(kPathPalette[i % kPalette]);
    for (std::size_t k = 1; k < path.size(); ++k) {
      cv::line(image, cell_center_px(g, path[k - 1], ppc), cell_center_px(g, path[k], ppc), color,
               thickness, cv::LINE_8);
    }
  }
  const int radius = std::max(3, ppc);
  for (std::size_t i = 0; i < layers.robots_m.size(); ++i) {
    const cv::Point center = cell_center_px(g, layers.robots_m[i], ppc);
    cv::circle(image, center, radius, to_scalar(kPathPalette[i % kPalette]), cv::FILLED,
               cv::LINE_8);
    cv::circle(image, center, radius, cv::Scalar(0, 0, 0), 1, cv::LINE_8);
  }

  return io_internal::to_rgb_image(image);
}

Result<std::string> render_png(const RenderLayers& layers, int pixels_per_cell) {
  Result<RgbImage> image = render_image(layers, pixels_per_cell);
  if (!image) return image.error();
  return encode_png(*image);
}

Status write_png(const std::filesystem::path& path, const RenderLayers& layers,
                 int pixels_per_cell) {
  Result<std::string> png = render_png(layers, pixels_per_cell);
  if (!png) return Error{png.error().kind, path.string() + ": " + png.error().message};
  return write_file_atomic(path, *png);
}

}  // namespace tessera
