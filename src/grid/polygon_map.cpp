#include "tessera/grid/polygon_map.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

#include "tessera/core/assert.hpp"
#include "tessera/grid/ray_cast.hpp"

namespace tessera {
namespace {

/// p on the closed segment a-b (exact test: collinear and within the segment's box).
bool on_segment(Vec2 a, Vec2 b, Vec2 p) {
  if ((b - a).cross(p - a) != 0.0) return false;
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

/// Point in a closed simple polygon: on the boundary counts as inside, else the even-odd crossing
/// rule (a horizontal ray to +x; an edge counts when it straddles p.y half-open, so a vertex on the
/// ray is counted once).
bool inside_polygon(const Polygon& polygon, Vec2 p) {
  const std::vector<Vec2>& v = polygon.vertices;
  const std::size_t n = v.size();
  if (n == 0) return false;
  bool inside = false;
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    if (on_segment(v[j], v[i], p)) return true;
    if ((v[i].y > p.y) != (v[j].y > p.y)) {
      const double x_cross = v[i].x + (v[j].x - v[i].x) * (p.y - v[i].y) / (v[j].y - v[i].y);
      if (p.x < x_cross) inside = !inside;
    }
  }
  return inside;
}

/// True when the closed segment a-b has a point strictly inside the open box (lo, hi) (Liang-Barsky
/// clipping with strict inequalities). A segment along the box's border or through a corner only
/// does not count: it touches the cell with zero area.
bool segment_meets_open_box(Vec2 a, Vec2 b, Vec2 lo, Vec2 hi) {
  double s_lo = -std::numeric_limits<double>::infinity();
  double s_hi = std::numeric_limits<double>::infinity();
  bool empty = false;
  const auto axis = [&](double p, double d, double min, double max) {
    if (d == 0.0) {
      if (!(min < p && p < max)) empty = true;
      return;
    }
    double s0 = (min - p) / d, s1 = (max - p) / d;
    if (s0 > s1) std::swap(s0, s1);
    s_lo = std::max(s_lo, s0);
    s_hi = std::min(s_hi, s1);
  };
  axis(a.x, b.x - a.x, lo.x, hi.x);
  axis(a.y, b.y - a.y, lo.y, hi.y);
  // The open interval (s_lo, s_hi) must meet the closed parameter range [0, 1].
  return !empty && s_lo < s_hi && s_lo < 1.0 && s_hi > 0.0;
}

}  // namespace

bool PolygonMap::inside_any(Vec2 p_m) const {
  return std::any_of(polygons_.begin(), polygons_.end(),
                     [p_m](const Polygon& polygon) { return inside_polygon(polygon, p_m); });
}

bool PolygonMap::occupied(Vec2 p_m) const {
  return meaning_ == Meaning::kObstacles ? inside_any(p_m) : !inside_any(p_m);
}

std::pair<Vec2, Vec2> PolygonMap::bounds() const {
  TESSERA_ASSERT(corner_count() > 0);
  constexpr double kInf = std::numeric_limits<double>::infinity();
  Vec2 lo{kInf, kInf}, hi{-kInf, -kInf};
  for (const Polygon& polygon : polygons_) {
    for (const Vec2& v : polygon.vertices) {
      lo = {std::min(lo.x, v.x), std::min(lo.y, v.y)};
      hi = {std::max(hi.x, v.x), std::max(hi.y, v.y)};
    }
  }
  return {lo, hi};
}

std::size_t PolygonMap::corner_count() const {
  std::size_t n = 0;
  for (const Polygon& polygon : polygons_) n += polygon.vertices.size();
  return n;
}

OccupancyGrid PolygonMap::rasterize(const GridGeometry& geometry) const {
  const bool obstacles = meaning_ == Meaning::kObstacles;
  // 1 = occupied. Cells no polygon's box reaches are free for obstacles, solid outside free space.
  std::vector<std::uint8_t> occupied_cells(geometry.size(), obstacles ? 0 : 1);
  const double res = geometry.resolution_m();
  const Vec2 origin = geometry.origin();

  for (const Polygon& polygon : polygons_) {
    const std::vector<Vec2>& v = polygon.vertices;
    if (v.size() < 3) continue;  // a point or a segment has no area: it overlaps no cell
    // The polygon's bounding box in cells, clipped to the grid.
    Vec2 lo = v.front(), hi = v.front();
    for (const Vec2& p : v) {
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    }
    const Cell c_lo = geometry.cell_at_unchecked(lo);
    const Cell c_hi = geometry.cell_at_unchecked(hi);
    const int x0 = std::max(c_lo.x, 0), y0 = std::max(c_lo.y, 0);
    const int x1 = std::min(c_hi.x, geometry.width() - 1);
    const int y1 = std::min(c_hi.y, geometry.height() - 1);
    if (x0 > x1 || y0 > y1) continue;
    const int box_w = x1 - x0 + 1;
    const auto box_index = [&](Cell c) {
      return static_cast<std::size_t>(c.y - y0) * static_cast<std::size_t>(box_w) +
             static_cast<std::size_t>(c.x - x0);
    };

    // Boundary cells: an edge passes through the cell's open square. Every such cell contains a
    // point of the edge, so the exact traversal visits it; the exact box test then drops the cells
    // the edge only grazes along a border or at a corner.
    std::vector<std::uint8_t> boundary(
        static_cast<std::size_t>(box_w) * static_cast<std::size_t>(y1 - y0 + 1), 0);
    for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
      const Vec2 a = v[j], b = v[i];
      if (a == b) continue;
      traverse_ray(geometry, a, b, [&](Cell c, double, double) {
        if (c.x < x0 || c.x > x1 || c.y < y0 || c.y > y1) return;
        const Vec2 corner{origin.x + c.x * res, origin.y + c.y * res};
        if (segment_meets_open_box(a, b, corner, corner + Vec2{res, res})) {
          boundary[box_index(c)] = 1;
        }
      });
    }

    // The other cells are wholly inside or wholly outside: decide by the centre, one scanline per
    // row (even-odd crossings of the row's centre line, sorted). An edge crosses the centre line
    // yc when yc is in [min y, max y) of its ends; the edges are walked as an active-edge table
    // sorted by min y, so a row costs the edges it crosses, not all of them (a tall plan of many
    // vertices was rows x vertices).
    struct Edge {
      Vec2 a, b;
      double y_min, y_max;
    };
    std::vector<Edge> edges;
    edges.reserve(v.size());
    for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
      if (v[i].y == v[j].y) continue;  // horizontal: never straddles a centre line
      edges.push_back({v[i], v[j], std::min(v[i].y, v[j].y), std::max(v[i].y, v[j].y)});
    }
    std::sort(edges.begin(), edges.end(),
              [](const Edge& e, const Edge& f) { return e.y_min < f.y_min; });
    std::vector<const Edge*> active;
    std::size_t next_edge = 0;
    std::vector<double> crossings;
    for (int y = y0; y <= y1; ++y) {
      const double yc = origin.y + (y + 0.5) * res;
      while (next_edge < edges.size() && edges[next_edge].y_min <= yc) {
        active.push_back(&edges[next_edge++]);
      }
      std::erase_if(active, [yc](const Edge* e) { return e->y_max <= yc; });
      crossings.clear();
      for (const Edge* e : active) {
        crossings.push_back(e->a.x + (e->b.x - e->a.x) * (yc - e->a.y) / (e->b.y - e->a.y));
      }
      std::sort(crossings.begin(), crossings.end());
      std::size_t k = 0;
      for (int x = x0; x <= x1; ++x) {
        const Cell c{x, y};
        const double xc = origin.x + (x + 0.5) * res;
        while (k < crossings.size() && crossings[k] < xc) ++k;
        const bool centre_inside = (k % 2) == 1;
        const bool on_boundary = boundary[box_index(c)] != 0;
        std::uint8_t& cell = occupied_cells[geometry.index_of(c)];
        if (obstacles) {
          if (on_boundary || centre_inside) cell = 1;  // some of the obstacle lies in the cell
        } else {
          if (!on_boundary && centre_inside) cell = 0;  // the whole cell lies in this free polygon
        }
      }
    }
  }

  OccupancyGrid grid(geometry);
  for (std::size_t i = 0; i < occupied_cells.size(); ++i) {
    grid.set_probability(geometry.cell_of(i), occupied_cells[i] != 0 ? 1.0 : 0.0);
  }
  return grid;
}

}  // namespace tessera
