#include "tessera/sim/blank_room.hpp"

#include <cmath>
#include <numbers>
#include <utility>

#include "tessera/sim/builtin_world.hpp"

namespace tessera {
namespace {

constexpr double kResolutionM = 0.05;
constexpr int kWidthCells = 120;   // 6 m
constexpr int kHeightCells = 100;  // 5 m
constexpr double kWestX = 0.05, kSouthY = 0.05;

World blank_room_world() {
  return walled_room(kWidthCells, kHeightCells, kResolutionM, "blank_room");
}

/// Facing the south-west corner along the diagonal, distance_m from it.
BlankView corner_view(std::string name, double distance_m, bool solvable) {
  const double d = distance_m / std::sqrt(2.0);
  return {std::move(name), {kWestX + d, kSouthY + d, -0.75 * std::numbers::pi}, solvable};
}

}  // namespace

Result<BlankRoom> make_blank_room(const RgbdCameraOptions& camera) {
  Result<RgbdCamera> cam = RgbdCamera::create(blank_room_world(), camera, {}, {});
  if (!cam) return cam.error();
  constexpr double kSouth = -0.5 * std::numbers::pi;
  std::vector<BlankView> views = {
      {"wall (1.5 m)", {3.0, kSouthY + 1.5, kSouth}, false},
      {"wall and floor (3 m)", {3.0, kSouthY + 3.0, kSouth}, false},
      corner_view("corner (1.5 m)", 1.5, false),
      corner_view("corner and floor (3.2 m)", 3.2, true),
      corner_view("corner, floor and ceiling (4.2 m)", 4.2, true),
  };
  return BlankRoom{std::move(cam).value(), std::move(views)};
}

}  // namespace tessera
