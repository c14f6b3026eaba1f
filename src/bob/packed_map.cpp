#include "tessera/bob/packed_map.hpp"

#include "internal/limits.hpp"

namespace tessera::bob {
namespace {

// Section 3.4: bit 0 occupancy, bit 1 sensed, bits 2-3 the direction that reached the cell.
constexpr std::uint8_t kOccupiedBit = 0x1;
constexpr std::uint8_t kSensedBit = 0x2;
constexpr std::uint8_t kStateMask = kOccupiedBit | kSensedBit;
constexpr int kDirectionShift = 2;

constexpr std::uint8_t code_of(CellState s) {
  switch (s) {
    case CellState::kUnsensed:
      return 0;
    case CellState::kFree:
      return kSensedBit;
    case CellState::kOccupied:
      return kSensedBit | kOccupiedBit;
    case CellState::kVisited:
      return kOccupiedBit;  // the code the paper leaves unused
  }
  return 0;
}

}  // namespace

Status PackedMap::init(std::uint8_t* buffer, std::size_t buffer_bytes, int width_cells,
                       int height_cells) {
  *this = PackedMap{};
  const Status s =
      internal::clear_grid_buffer(buffer, buffer_bytes, width_cells, height_cells, &bytes_needed);
  if (s != Status::kOk) return s;
  buffer_ = buffer;
  width_ = width_cells;
  height_ = height_cells;
  return Status::kOk;
}

std::uint8_t PackedMap::nibble(GridCell c) const {
  const std::uint8_t byte = buffer_[static_cast<std::size_t>(c.y) * bytes_per_row(width_) +
                                    static_cast<std::size_t>(c.x) / 2u];
  return (c.x & 1) != 0 ? static_cast<std::uint8_t>(byte >> 4)
                        : static_cast<std::uint8_t>(byte & 0xF);
}

void PackedMap::set_nibble(GridCell c, std::uint8_t v) {
  std::uint8_t& byte = buffer_[static_cast<std::size_t>(c.y) * bytes_per_row(width_) +
                               static_cast<std::size_t>(c.x) / 2u];
  byte = (c.x & 1) != 0 ? static_cast<std::uint8_t>((byte & 0x0F) | (v << 4))
                        : static_cast<std::uint8_t>((byte & 0xF0) | (v & 0x0F));
}

CellState PackedMap::state(GridCell c) const {
  switch (nibble(c) & kStateMask) {
    case kSensedBit:
      return CellState::kFree;
    case kSensedBit | kOccupiedBit:
      return CellState::kOccupied;
    case kOccupiedBit:
      return CellState::kVisited;
    default:
      return CellState::kUnsensed;
  }
}

Direction PackedMap::came_from(GridCell c) const {
  return static_cast<Direction>(direction_bits(c));
}

unsigned PackedMap::direction_bits(GridCell c) const {
  return (static_cast<unsigned>(nibble(c)) >> kDirectionShift) & 0x3u;
}

void PackedMap::set_direction_bits(GridCell c, unsigned bits) {
  set_nibble(
      c, static_cast<std::uint8_t>((nibble(c) & kStateMask) | ((bits & 0x3u) << kDirectionShift)));
}

void PackedMap::set_state(GridCell c, CellState s) {
  set_nibble(c, static_cast<std::uint8_t>((nibble(c) & ~kStateMask & 0xF) | code_of(s)));
}

void PackedMap::set_visited(GridCell c, Direction reached_by) {
  set_nibble(c, static_cast<std::uint8_t>(code_of(CellState::kVisited) |
                                          (static_cast<unsigned>(reached_by) << kDirectionShift)));
}

bool PackedMap::has_unsensed_neighbor(GridCell c) const {
  for (const Direction d : kClockwiseFromNorth) {
    const GridCell n = step(c, d);
    if (contains(n) && state(n) == CellState::kUnsensed) return true;
  }
  return false;
}

}  // namespace tessera::bob
