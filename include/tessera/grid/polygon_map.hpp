#pragma once
#include <cstddef>
#include <utility>
#include <vector>

#include "tessera/core/vec2.hpp"
#include "tessera/grid/grid_geometry.hpp"
#include "tessera/grid/occupancy_grid.hpp"

namespace tessera {

/// A simple polygon (no self-intersections), vertices in metres, either winding.
struct Polygon {
  std::vector<Vec2> vertices;
};

/// The lecture's continuous map ("Discrete & continuous maps"): objects stored as polygons by their
/// corners. Exact at any scale; memory grows with the corners, not the area.
class PolygonMap {
 public:
  /// What the polygons are. kObstacles: each polygon is a solid object, outside is free (the
  /// lecture's triangle). kFreeSpace: polygons outline free space, everything outside is solid (a
  /// HouseExpo floor plan's contour).
  enum class Meaning { kObstacles, kFreeSpace };

  explicit PolygonMap(Meaning meaning = Meaning::kObstacles) : meaning_(meaning) {}

  void add(Polygon polygon) { polygons_.push_back(std::move(polygon)); }
  [[nodiscard]] const std::vector<Polygon>& polygons() const { return polygons_; }
  [[nodiscard]] Meaning meaning() const { return meaning_; }

  /// True when p_m lies inside any polygon (boundary counts as inside).
  [[nodiscard]] bool inside_any(Vec2 p_m) const;
  /// True when p_m is in an obstacle: inside a polygon for kObstacles, outside all for kFreeSpace.
  [[nodiscard]] bool occupied(Vec2 p_m) const;

  /// Axis-aligned bounds of all vertices: {min, max}. Precondition: at least one vertex.
  [[nodiscard]] std::pair<Vec2, Vec2> bounds() const;

  /// Rasterises onto `geometry`: a cell is occupied (p = 1 - 1e-4 after clamping) when any part of
  /// an obstacle overlaps it (the lecture: a cell partly covered by the object counts as occupied),
  /// else free (p = 1e-4). Every cell of the result is known. "Overlaps" means with positive area:
  /// a cell that only touches an obstacle along its border or at a corner stays free.
  ///  - kObstacles: occupied when some polygon's interior meets the cell's open square.
  ///  - kFreeSpace: free only when one single polygon contains the whole cell square, so a cell
  ///    any part of which lies outside the free space is occupied. A cell split between two
  ///    touching free-space polygons counts as occupied too (errors fall on the safe side).
  /// Cost: O(perimeter in cells + area of the polygons' bounding boxes in cells + vertices * rows).
  [[nodiscard]] OccupancyGrid rasterize(const GridGeometry& geometry) const;

  /// Corners stored, over all polygons (the lecture: a unit square object needs 4).
  [[nodiscard]] std::size_t corner_count() const;
  /// Memory of the continuous form: 2 doubles per corner (16 bytes).
  [[nodiscard]] std::size_t memory_bytes() const { return corner_count() * 2 * sizeof(double); }

 private:
  Meaning meaning_;
  std::vector<Polygon> polygons_;
};

}  // namespace tessera
