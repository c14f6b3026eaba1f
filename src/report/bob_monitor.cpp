#include "tessera/report/bob_monitor.hpp"

#include <algorithm>
#include <cmath>

namespace tessera {
namespace {

void plot(RgbImage& img, int x, int row, Rgb c) {
  if (0 <= x && x < img.width && 0 <= row && row < img.height) img.set(x, row, c);
}

/// A thick line (3 px) between pixel centres.
void line(RgbImage& img, double x0, double r0, double x1, double r1, Rgb c) {
  const int steps = static_cast<int>(std::ceil(std::max(std::abs(x1 - x0), std::abs(r1 - r0)))) + 1;
  for (int i = 0; i <= steps; ++i) {
    const double t = static_cast<double>(i) / steps;
    const int x = static_cast<int>(std::lround(x0 + t * (x1 - x0)));
    const int r = static_cast<int>(std::lround(r0 + t * (r1 - r0)));
    for (int dx = -1; dx <= 1; ++dx) {
      for (int dr = -1; dr <= 1; ++dr) plot(img, x + dx, r + dr, c);
    }
  }
}

}  // namespace

RgbImage render_bob_monitor(const BobResult& run, int pixels_per_cell) {
  TESSERA_ASSERT(pixels_per_cell >= 8);
  const int p = pixels_per_cell;
  RgbImage img(run.width * p + 1, run.height * p + 1, kBobGridLine);
  const std::size_t row_bytes = (static_cast<std::size_t>(run.width) + 7u) / 8u;
  for (int y = 0; y < run.height; ++y) {
    for (int x = 0; x < run.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(run.width) +
                            static_cast<std::size_t>(x);
      const std::uint8_t byte =
          run.final_map[static_cast<std::size_t>(y) * row_bytes + static_cast<std::size_t>(x / 8)];
      const bool occupied = ((byte >> (x % 8)) & 1u) != 0;
      const Rgb c = run.sensed[i] == 0 ? kBobUnsensed : (occupied ? kBobOccupied : kBobEmpty);
      const int top = (run.height - 1 - y) * p;
      for (int r = top + 1; r < top + p; ++r) {
        for (int px = x * p + 1; px < (x + 1) * p; ++px) img.set(px, r, c);
      }
    }
  }
  auto centre = [&](Cell c, double& px, double& row) {
    px = (c.x + 0.5) * p;
    row = (run.height - 1 - c.y + 0.5) * p;
  };
  const double head = 0.3 * p;
  for (std::size_t k = 1; k < run.route.size(); ++k) {
    double x0, r0, x1, r1;
    centre(run.route[k - 1], x0, r0);
    centre(run.route[k], x1, r1);
    // Offset to the right of the direction of travel, so that a backtrack along the same cells
    // draws a separate lane instead of covering the way out.
    const double ux = (x1 - x0) / p, ur = (r1 - r0) / p;
    const double off = p / 6.0;
    x0 -= off * ur;
    x1 -= off * ur;
    r0 += off * ux;
    r1 += off * ux;
    line(img, x0, r0, x1, r1, kBobRoute);
    // Arrow head at the cell reached: two strokes back from its centre, 45 degrees off the move.
    line(img, x1, r1, x1 - head * (ux + ur), r1 - head * (ur - ux), kBobRoute);
    line(img, x1, r1, x1 - head * (ux - ur), r1 - head * (ur + ux), kBobRoute);
  }
  return img;
}

}  // namespace tessera
