// Grid-matching pictures (render/gridmatch_svg.hpp): plain SVG text, cells as squares.
#include "tessera/render/gridmatch_svg.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tessera {
namespace {

constexpr double kCellPx = 22.0;
constexpr double kGapPx = 18.0;
constexpr double kCaptionPx = 34.0;  // two caption lines under a panel

const char* fill_of(std::int8_t v) { return v > 0 ? "#6e6e6e" : (v < 0 ? "#ffffff" : "#d9d9d9"); }

// One cell at (left, top): a map cell (grey, white, "?") or an S(i,j) cell (+1 green, -1 red).
void cell(std::string& svg, double left, double top, std::int8_t v, bool product) {
  const char* fill = product ? (v > 0 ? "#b7e1b1" : (v < 0 ? "#f2b8b5" : "#ffffff")) : fill_of(v);
  svg += fmt::format(
      R"(<rect x="{:.1f}" y="{:.1f}" width="{:.1f}" height="{:.1f}" fill="{}" stroke="#999999" stroke-width="0.5"/>)"
      "\n",
      left, top, kCellPx, kCellPx, fill);
  const char* text = product ? (v > 0 ? "1" : (v < 0 ? "-1" : "0")) : (v == 0 ? "?" : nullptr);
  if (text != nullptr) {
    svg += fmt::format(
        R"(<text x="{:.1f}" y="{:.1f}" font-size="11" text-anchor="middle" fill="#333333">{}</text>)"
        "\n",
        left + kCellPx / 2, top + kCellPx * 0.68, text);
  }
}

// A robot at the centre of (cx, cy) px heading `heading_rad` on the page (0: right, pi/2: up).
void robot(std::string& svg, double cx, double cy, double heading_rad, const char* colour) {
  const double r = kCellPx * 0.28, tip = kCellPx * 0.55;
  svg += fmt::format(R"(<circle cx="{:.1f}" cy="{:.1f}" r="{:.1f}" fill="{}"/>)"
                     "\n",
                     cx, cy, r, colour);
  svg += fmt::format(
      R"(<line x1="{:.1f}" y1="{:.1f}" x2="{:.1f}" y2="{:.1f}" stroke="{}" stroke-width="2"/>)"
      "\n",
      cx, cy, cx + tip * std::cos(heading_rad), cy - tip * std::sin(heading_rad), colour);
}

void caption(std::string& svg, double left, double top, const std::string& line1,
             const std::string& line2) {
  svg += fmt::format(R"(<text x="{:.1f}" y="{:.1f}" font-size="12" fill="#000000">{}</text>)"
                     "\n",
                     left, top + 13, line1);
  if (!line2.empty()) {
    svg += fmt::format(R"(<text x="{:.1f}" y="{:.1f}" font-size="12" fill="#000000">{}</text>)"
                       "\n",
                       left, top + 28, line2);
  }
}

// Size in px of a robot-frame window drawn heading up: its y cells across, its x cells down.
double panel_width(const slam::TernaryGrid& g) { return g.geometry().height() * kCellPx; }
double panel_height(const slam::TernaryGrid& g) { return g.geometry().width() * kCellPx; }

// A robot-frame window drawn as the lecture draws it, the robot moving up the page: the top row is
// the farthest ahead (largest x), each row runs from the robot's left (largest y) to its right.
void window_panel(std::string& svg, double left, double top, const slam::TernaryGrid& g,
                  bool product, bool framed) {
  const GridGeometry& geo = g.geometry();
  for (int x = 0; x < geo.width(); ++x) {
    for (int y = 0; y < geo.height(); ++y) {
      cell(svg, left + (geo.height() - 1 - y) * kCellPx, top + (geo.width() - 1 - x) * kCellPx,
           g.at({x, y}), product);
    }
  }
  const Cell at = geo.cell_at_unchecked({0.0, 0.0});
  if (geo.contains(at)) {
    robot(svg, left + (geo.height() - 0.5 - at.y) * kCellPx,
          top + (geo.width() - 0.5 - at.x) * kCellPx, 0.5 * std::numbers::pi, "#1f77b4");
  }
  if (framed) {
    svg += fmt::format(
        R"(<rect x="{:.1f}" y="{:.1f}" width="{:.1f}" height="{:.1f}" fill="none" stroke="#1f77b4" stroke-width="3"/>)"
        "\n",
        left - 2, top - 2, panel_width(g) + 4, panel_height(g) + 4);
  }
}

// The current map north up, with the odometry pose and the chosen one.
void map_panel(std::string& svg, double left, double top, const OccupancyGrid& map,
               const slam::GridMatchResult& r) {
  const GridGeometry& geo = map.geometry();
  for (int y = 0; y < geo.height(); ++y) {
    for (int x = 0; x < geo.width(); ++x) {
      cell(svg, left + x * kCellPx, top + (geo.height() - 1 - y) * kCellPx,
           slam::ternary_value(map, {x, y}), false);
    }
  }
  const auto at_px = [&](const Pose2& p, const char* colour) {
    robot(svg, left + (p.x - geo.origin().x) / geo.resolution_m() * kCellPx,
          top + (geo.height() - (p.y - geo.origin().y) / geo.resolution_m()) * kCellPx, p.theta,
          colour);
  };
  at_px(r.T_map_odometry, "#7f7f7f");
  at_px(r.T_map_robot(), "#1f77b4");
}

std::string document(double width, double height, const std::string& body) {
  return fmt::format(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="{:.0f}" height="{:.0f}" viewBox="0 0 {:.0f} {:.0f}" font-family="sans-serif">)"
      "\n"
      R"(<rect width="100%" height="100%" fill="#ffffff"/>)"
      "\n{}</svg>\n",
      width, height, width, height, body);
}

std::string pose_text(const Pose2& p) {
  return fmt::format("x {:.2f} m, y {:.2f} m, {:.0f} deg", p.x, p.y,
                     p.theta * 180.0 / std::numbers::pi);
}

std::string label_of(const GridMatchStep& step, std::size_t k) {
  if (k < step.labels.size()) return step.labels[k];
  const slam::CandidateOffset& o = step.result->candidates[k].offset;
  return fmt::format("dx {:+d}, dy {:+d}, turn {:+d}", o.dx_steps, o.dy_steps, o.dheading_steps);
}

}  // namespace

std::string gridmatch_candidate_svg(const GridMatchStep& step, std::size_t k) {
  const slam::GridMatchCandidate& c = step.result->candidates[k];
  const slam::TernaryGrid& p = *step.perception;
  const slam::TernaryGrid e = slam::expected_map(*step.map, p.geometry(), c.T_map_robot);
  const slam::TernaryGrid s = slam::similarity_cells(p, e);
  const double w = panel_width(p), h = panel_height(p);
  std::string body;
  const double top = kGapPx + kCaptionPx;
  body += fmt::format(
      R"(<text x="{:.1f}" y="{:.1f}" font-size="13" font-weight="bold">{}: S = {}{}</text>)"
      "\n",
      kGapPx, kGapPx + 4, label_of(step, k), c.similarity.score,
      k == step.result->best ? " (best)" : "");
  caption(body, kGapPx, kGapPx + 8, pose_text(c.T_map_robot), "");
  const double panel_step = w + 3 * kGapPx + 40;  // room for the captions
  window_panel(body, kGapPx, top, e, false, false);
  caption(body, kGapPx, top + h + 4, "expected map e(m, t)", "");
  window_panel(body, kGapPx + panel_step, top, p, false, false);
  caption(body, kGapPx + panel_step, top + h + 4, "perception p", "");
  window_panel(body, kGapPx + 2 * panel_step, top, s, true, false);
  caption(
      body, kGapPx + 2 * panel_step, top + h + 4, "S(i,j) = m p",
      fmt::format("{} agree, {} differ", c.similarity.agree_cells, c.similarity.disagree_cells()));
  return document(kGapPx + 3 * panel_step, top + h + kCaptionPx + kGapPx, body);
}

std::string gridmatch_sheet_svg(const GridMatchStep& step) {
  const slam::GridMatchResult& r = *step.result;
  const slam::TernaryGrid& p = *step.perception;
  const GridGeometry& mg = step.map->geometry();
  const double w = panel_width(p), h = panel_height(p);
  const double map_w = mg.width() * kCellPx, map_h = mg.height() * kCellPx;
  std::string body;
  // Row 1: the current map, the perception, S(i,j) at the best pose.
  double top = kGapPx;
  map_panel(body, kGapPx, top, *step.map, r);
  caption(body, kGapPx, top + map_h + 4, "current map m (grey: odometry, blue: chosen)", "");
  double left = 2 * kGapPx + map_w;
  window_panel(body, left, top, p, false, false);
  caption(body, left, top + h + 4, "perception p", "(sensor)");
  left += kGapPx + w + 30;
  const slam::TernaryGrid best_e = slam::expected_map(*step.map, p.geometry(), r.T_map_robot());
  window_panel(body, left, top, slam::similarity_cells(p, best_e), true, false);
  caption(body, left, top + h + 4, "S(i,j) at the best pose",
          fmt::format("S = {}", r.winner().similarity.score));
  const double row1_w = left + w + 2 * kGapPx + 60;
  top += std::max(map_h, h) + kCaptionPx + kGapPx;
  // Then the test poses, three to a row.
  const double col_w = w + 6 * kGapPx + 40;
  for (std::size_t k = 0; k < r.candidates.size(); ++k) {
    const double x = kGapPx + static_cast<double>(k % 3) * col_w;
    const double y = top + static_cast<double>(k / 3) * (h + kCaptionPx + kGapPx);
    const slam::TernaryGrid e =
        slam::expected_map(*step.map, p.geometry(), r.candidates[k].T_map_robot);
    window_panel(body, x, y, e, false, k == r.best);
    caption(body, x, y + h + 4, label_of(step, k),
            fmt::format("S = {}", r.candidates[k].similarity.score));
  }
  const std::size_t rows = (r.candidates.size() + 2) / 3;
  const double height = top + static_cast<double>(rows) * (h + kCaptionPx + kGapPx);
  return document(std::max(row1_w, kGapPx + 3 * col_w), height, body);
}

}  // namespace tessera
