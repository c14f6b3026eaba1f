#include "tessera/render/hex_map_svg.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "internal/cv_image.hpp"
#include "tessera/io/atomic_file.hpp"
#include "tessera/io/image_file.hpp"

namespace tessera {
namespace {

constexpr double kMaxPixels = static_cast<double>(std::int64_t{1} << 28);

// The picture's frame: map metres to pixels, north up.
struct Frame {
  double min_x = 0.0, max_y = 0.0, ppm = 1.0;
  int width_px = 0, height_px = 0;
  [[nodiscard]] double px(double x_m) const { return (x_m - min_x) * ppm; }
  [[nodiscard]] double py(double y_m) const { return (max_y - y_m) * ppm; }
};

struct Bounds {
  double lo_x = std::numeric_limits<double>::infinity(), lo_y = lo_x;
  double hi_x = -std::numeric_limits<double>::infinity(), hi_y = hi_x;
  void add(Vec2 p) {
    lo_x = std::min(lo_x, p.x);
    lo_y = std::min(lo_y, p.y);
    hi_x = std::max(hi_x, p.x);
    hi_y = std::max(hi_y, p.y);
  }
};

bool finite(Vec2 p) { return std::isfinite(p.x) && std::isfinite(p.y); }

Status check_points(const std::vector<Vec2>& points, const char* what) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!finite(points[i])) {
      return input_error(std::string("hex map picture: ") + what + " point " + std::to_string(i) +
                         " is not finite");
    }
  }
  return Ok{};
}

// Checks the picture and computes its frame.
Result<Frame> frame_of(const HexMapPicture& pic) {
  if (pic.map == nullptr) return input_error("hex map picture: no map to draw");
  const fusion::HexCellMap& map = *pic.map;
  if (map.empty()) return input_error("hex map picture: the map has no cells");
  if (!(std::isfinite(pic.pixels_per_m) && pic.pixels_per_m > 0.0)) {
    return input_error("hex map picture: pixels per metre must be > 0, got " +
                       std::to_string(pic.pixels_per_m));
  }
  const auto cell_ok = [&](std::ptrdiff_t id) {
    return id == -1 || (id >= 0 && static_cast<std::size_t>(id) < map.cell_count());
  };
  if (!cell_ok(pic.start_cell)) {
    return input_error("hex map picture: start cell " + std::to_string(pic.start_cell) +
                       " does not exist (the map has " + std::to_string(map.cell_count()) +
                       " cells)");
  }
  if (!cell_ok(pic.goal_cell)) {
    return input_error("hex map picture: goal cell " + std::to_string(pic.goal_cell) +
                       " does not exist (the map has " + std::to_string(map.cell_count()) +
                       " cells)");
  }
  for (const auto& [points, what] :
       {std::pair{&pic.image_nodes_m, "image node"}, std::pair{&pic.taught_path_m, "taught path"},
        std::pair{&pic.repeated_path_m, "repeated path"},
        std::pair{&pic.true_path_m, "true path"}}) {
    if (Status s = check_points(*points, what); !s) return s.error();
  }
  Bounds b;
  const double r = map.options().cell_radius_m / std::sqrt(3.0);  // circumradius
  for (const fusion::HexCell& c : map.cells()) {
    if (!finite(c.centre_m)) return input_error("hex map picture: a cell centre is not finite");
    b.add(c.centre_m - Vec2{r, r});
    b.add(c.centre_m + Vec2{r, r});
  }
  for (const auto* points :
       {&pic.image_nodes_m, &pic.taught_path_m, &pic.repeated_path_m, &pic.true_path_m}) {
    for (const Vec2 p : *points) b.add(p);
  }
  for (const auto& [lo, hi] : pic.obstacles_m) {
    if (!finite(lo) || !finite(hi))
      return input_error("hex map picture: an obstacle is not finite");
    b.add(lo);
    b.add(hi);
  }
  if (pic.floor_plan != nullptr && pic.floor_plan->geometry().size() > 0) {
    const GridGeometry& g = pic.floor_plan->geometry();
    b.add(g.origin());
    b.add(g.origin() + Vec2{g.width() * g.resolution_m(), g.height() * g.resolution_m()});
  }
  const double margin = map.options().cell_radius_m;
  Frame f;
  f.ppm = pic.pixels_per_m;
  f.min_x = b.lo_x - margin;
  f.max_y = b.hi_y + margin;
  const double w = std::ceil((b.hi_x - b.lo_x + 2 * margin) * f.ppm);
  const double h = std::ceil((b.hi_y - b.lo_y + 2 * margin) * f.ppm);
  if (!(w * h <= kMaxPixels)) {
    return input_error("hex map picture: a " + std::to_string(w) + " x " + std::to_string(h) +
                       " px picture is too large; use fewer pixels per metre");
  }
  f.width_px = std::max(1, static_cast<int>(w));
  f.height_px = std::max(1, static_cast<int>(h));
  return f;
}

// Solid cells of the floor plan as row runs [x0, x1) per row: one rectangle per run.
struct Run {
  int row = 0, x0 = 0, x1 = 0;
};
std::vector<Run> solid_runs(const World& w) {
  std::vector<Run> runs;
  const GridGeometry& g = w.geometry();
  for (int y = 0; y < g.height(); ++y) {
    int x = 0;
    while (x < g.width()) {
      if (!w.solid({x, y})) {
        ++x;
        continue;
      }
      const int x0 = x;
      while (x < g.width() && w.solid({x, y})) ++x;
      runs.push_back({y, x0, x});
    }
  }
  return runs;
}

std::string hex(Rgb c) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", c.r, c.g, c.b);
  return buf;
}

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  return buf;
}

void svg_polyline(std::string& out, const Frame& f, const std::vector<Vec2>& pts, const char* cls,
                  Rgb color) {
  if (pts.size() < 2) return;
  out += "<polyline class=\"";
  out += cls;
  out += "\" fill=\"none\" stroke=\"" + hex(color) + "\" stroke-width=\"2\" points=\"";
  for (const Vec2 p : pts) out += num(f.px(p.x)) + "," + num(f.py(p.y)) + " ";
  out += "\"/>\n";
}

std::string svg_hexagon(const Frame& f, Vec2 centre, double radius_m, const std::string& attrs) {
  std::string s = "<polygon " + attrs + " points=\"";
  for (const Vec2 v : HexGrid::corners(centre, radius_m)) {
    s += num(f.px(v.x)) + "," + num(f.py(v.y)) + " ";
  }
  return s + "\"/>\n";
}

}  // namespace

Result<std::string> render_hex_map_svg(const HexMapPicture& pic) {
  Result<Frame> fr = frame_of(pic);
  if (!fr) return fr.error();
  const Frame& f = *fr;
  const fusion::HexCellMap& map = *pic.map;
  const double d = map.options().cell_radius_m;
  std::string out;
  out.reserve(256 + 160 * map.cell_count());
  out += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(f.width_px) +
         "\" height=\"" + std::to_string(f.height_px) + "\" viewBox=\"0 0 " +
         std::to_string(f.width_px) + " " + std::to_string(f.height_px) + "\">\n";
  out += "<title>tessera hex-cell map: " + std::to_string(map.cell_count()) + " cells, " +
         std::to_string(pic.image_nodes_m.size()) + " image nodes</title>\n";
  out += "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";

  if (pic.floor_plan != nullptr) {
    const GridGeometry& g = pic.floor_plan->geometry();
    out += "<g id=\"floor_plan\" fill=\"" + hex(kHexFloorPlanColor) + "\">\n";
    for (const Run& run : solid_runs(*pic.floor_plan)) {
      const double x0 = g.origin().x + run.x0 * g.resolution_m();
      const double y1 = g.origin().y + (run.row + 1) * g.resolution_m();
      out += "<rect x=\"" + num(f.px(x0)) + "\" y=\"" + num(f.py(y1)) + "\" width=\"" +
             num((run.x1 - run.x0) * g.resolution_m() * f.ppm) + "\" height=\"" +
             num(g.resolution_m() * f.ppm) + "\"/>\n";
    }
    out += "</g>\n";
  }

  if (!pic.obstacles_m.empty()) {
    out += "<g id=\"obstacles\" fill=\"" + hex(kHexObstacleColor) + "\">\n";
    for (const auto& [lo, hi] : pic.obstacles_m) {
      out += "<rect class=\"obstacle\" x=\"" + num(f.px(lo.x)) + "\" y=\"" + num(f.py(hi.y)) +
             "\" width=\"" + num((hi.x - lo.x) * f.ppm) + "\" height=\"" +
             num((hi.y - lo.y) * f.ppm) + "\"/>\n";
    }
    out += "</g>\n";
  }

  out += "<g id=\"markers\">\n";
  if (pic.start_cell >= 0) {
    out += svg_hexagon(f, map.cell(static_cast<std::size_t>(pic.start_cell)).centre_m, d,
                       "class=\"start\" fill=\"" + hex(kHexStartColor) + "\"");
  }
  if (pic.goal_cell >= 0) {
    out += svg_hexagon(f, map.cell(static_cast<std::size_t>(pic.goal_cell)).centre_m, d,
                       "class=\"goal\" fill=\"" + hex(kHexGoalColor) + "\"");
  }
  out += "</g>\n";

  out +=
      "<g id=\"cells\" fill=\"none\" stroke=\"" + hex(kHexCellColor) + "\" stroke-width=\"1\">\n";
  for (std::size_t i = 0; i < map.cell_count(); ++i) {
    out += svg_hexagon(f, map.cell(i).centre_m, d,
                       "class=\"cell\" id=\"cell" + std::to_string(i) + "\"");
  }
  out += "</g>\n";

  const CellGraph graph = map.graph(pic.adjacency);
  out += "<g id=\"adjacency\" stroke=\"" + hex(kHexAdjacencyColor) + "\" stroke-width=\"1\">\n";
  for (std::size_t i = 0; i < graph.size(); ++i) {
    for (const std::size_t j : graph.adjacent[i]) {
      if (j < i) continue;
      const Vec2 a = graph.centres_m[i], b = graph.centres_m[j];
      out += "<line x1=\"" + num(f.px(a.x)) + "\" y1=\"" + num(f.py(a.y)) + "\" x2=\"" +
             num(f.px(b.x)) + "\" y2=\"" + num(f.py(b.y)) + "\"/>\n";
    }
  }
  out += "</g>\n";

  out += "<g id=\"paths\">\n";
  svg_polyline(out, f, pic.true_path_m, "true", kHexTruePathColor);
  svg_polyline(out, f, pic.taught_path_m, "taught", kHexTaughtPathColor);
  svg_polyline(out, f, pic.repeated_path_m, "repeated", kHexRepeatedPathColor);
  out += "</g>\n";

  out += "<g id=\"image_nodes\" fill=\"" + hex(kHexImageNodeColor) + "\">\n";
  const double dot_px = std::max(2.0, 0.03 * f.ppm);
  for (const Vec2 p : pic.image_nodes_m) {
    out += "<circle cx=\"" + num(f.px(p.x)) + "\" cy=\"" + num(f.py(p.y)) + "\" r=\"" +
           num(dot_px) + "\"/>\n";
  }
  out += "</g>\n</svg>\n";
  return out;
}

Result<RgbImage> render_hex_map_image(const HexMapPicture& pic) {
  Result<Frame> fr = frame_of(pic);
  if (!fr) return fr.error();
  const Frame& f = *fr;
  const fusion::HexCellMap& map = *pic.map;
  const double d = map.options().cell_radius_m;
  const auto color = [](Rgb c) { return cv::Scalar(c.r, c.g, c.b); };  // the Mat is R, G, B
  const auto pt = [&](Vec2 p) {
    return cv::Point(static_cast<int>(std::lround(f.px(p.x))),
                     static_cast<int>(std::lround(f.py(p.y))));
  };
  const auto hexagon = [&](Vec2 centre) {
    std::vector<cv::Point> poly;
    for (const Vec2 v : HexGrid::corners(centre, d)) poly.push_back(pt(v));
    return poly;
  };
  cv::Mat image(f.height_px, f.width_px, CV_8UC3, cv::Scalar(255, 255, 255));

  if (pic.floor_plan != nullptr) {
    const GridGeometry& g = pic.floor_plan->geometry();
    for (const Run& run : solid_runs(*pic.floor_plan)) {
      const Vec2 lo = g.origin() + Vec2{run.x0 * g.resolution_m(), run.row * g.resolution_m()};
      const Vec2 hi =
          g.origin() + Vec2{run.x1 * g.resolution_m(), (run.row + 1) * g.resolution_m()};
      cv::rectangle(image, cv::Point(pt({lo.x, hi.y})), cv::Point(pt({hi.x, lo.y})),
                    color(kHexFloorPlanColor), cv::FILLED);
    }
  }
  for (const auto& [lo, hi] : pic.obstacles_m) {
    cv::rectangle(image, pt({lo.x, hi.y}), pt({hi.x, lo.y}), color(kHexObstacleColor), cv::FILLED);
  }
  if (pic.start_cell >= 0) {
    cv::fillConvexPoly(image, hexagon(map.cell(static_cast<std::size_t>(pic.start_cell)).centre_m),
                       color(kHexStartColor), cv::LINE_AA);
  }
  if (pic.goal_cell >= 0) {
    cv::fillConvexPoly(image, hexagon(map.cell(static_cast<std::size_t>(pic.goal_cell)).centre_m),
                       color(kHexGoalColor), cv::LINE_AA);
  }
  for (const fusion::HexCell& c : map.cells()) {
    const std::vector<std::vector<cv::Point>> polys{hexagon(c.centre_m)};
    cv::polylines(image, polys, true, color(kHexCellColor), 1, cv::LINE_AA);
  }
  const CellGraph graph = map.graph(pic.adjacency);
  for (std::size_t i = 0; i < graph.size(); ++i) {
    for (const std::size_t j : graph.adjacent[i]) {
      if (j > i) {
        cv::line(image, pt(graph.centres_m[i]), pt(graph.centres_m[j]), color(kHexAdjacencyColor),
                 1, cv::LINE_AA);
      }
    }
  }
  const auto path = [&](const std::vector<Vec2>& pts, Rgb c) {
    for (std::size_t k = 1; k < pts.size(); ++k) {
      cv::line(image, pt(pts[k - 1]), pt(pts[k]), color(c), 2, cv::LINE_AA);
    }
  };
  path(pic.true_path_m, kHexTruePathColor);
  path(pic.taught_path_m, kHexTaughtPathColor);
  path(pic.repeated_path_m, kHexRepeatedPathColor);
  const int dot_px = std::max(2, static_cast<int>(std::lround(0.03 * f.ppm)));
  for (const Vec2 p : pic.image_nodes_m) {
    cv::circle(image, pt(p), dot_px, color(kHexImageNodeColor), cv::FILLED, cv::LINE_AA);
  }

  return io_internal::to_rgb_image(image);
}

Status write_hex_map_svg(const std::filesystem::path& path, const HexMapPicture& picture) {
  Result<std::string> svg = render_hex_map_svg(picture);
  if (!svg) return Error{svg.error().kind, path.string() + ": " + svg.error().message};
  return write_file_atomic(path, *svg);
}

Status write_hex_map_png(const std::filesystem::path& path, const HexMapPicture& picture) {
  Result<RgbImage> image = render_hex_map_image(picture);
  if (!image) return Error{image.error().kind, path.string() + ": " + image.error().message};
  Result<std::string> png = encode_png(*image);
  if (!png) return Error{png.error().kind, path.string() + ": " + png.error().message};
  return write_file_atomic(path, *png);
}

}  // namespace tessera
