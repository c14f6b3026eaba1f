#pragma once
// The monitor picture of BOBMapping Figure 5a for a simulated run (mission/bob_mission.hpp):
// one square per cell, green = sensed empty, red = occupied in the final map (sensed occupied, or
// stood in with an obstacle detected inside, docs/decisions/0008), yellow = not sensed, and an
// arrow for every move of the route (centre of a cell to centre of the next, shifted to the right
// of the direction of travel so a backtrack shows as a second lane; the head in the cell reached).
// Top image row = highest cell row (docs/conventions.md).
#include "tessera/io/rgb_image.hpp"
#include "tessera/mission/bob_mission.hpp"

namespace tessera {

inline constexpr Rgb kBobEmpty{60, 170, 60};
inline constexpr Rgb kBobOccupied{200, 40, 40};
inline constexpr Rgb kBobUnsensed{235, 210, 50};
inline constexpr Rgb kBobRoute{20, 30, 120};
inline constexpr Rgb kBobGridLine{90, 90, 90};

/// Precondition: pixels_per_cell >= 8.
[[nodiscard]] RgbImage render_bob_monitor(const BobResult& run, int pixels_per_cell = 24);

}  // namespace tessera
