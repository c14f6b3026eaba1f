#include "tessera/bob/final_map.hpp"

#include "internal/limits.hpp"

namespace tessera::bob {

Status FinalMap::init(std::uint8_t* buffer, std::size_t buffer_bytes, int width_cells,
                      int height_cells) {
  *this = FinalMap{};
  const Status s =
      internal::clear_grid_buffer(buffer, buffer_bytes, width_cells, height_cells, &bytes_needed);
  if (s != Status::kOk) return s;
  buffer_ = buffer;
  width_ = width_cells;
  height_ = height_cells;
  return Status::kOk;
}

Status FinalMap::assign_from(const PackedMap& mapping) {
  if (mapping.width() != width_ || mapping.height() != height_ || buffer_ == nullptr) {
    return Status::kBadSize;
  }
  for (int y = 0; y < height_; ++y) {
    for (int x = 0; x < width_; ++x) {
      const GridCell c{x, y};
      set_occupied(c, !mapping.is_known_free(c));
    }
  }
  return Status::kOk;
}

bool FinalMap::occupied(GridCell c) const {
  const std::size_t byte =
      static_cast<std::size_t>(c.y) * bytes_per_row(width_) + static_cast<std::size_t>(c.x) / 8u;
  return ((buffer_[byte] >> (c.x % 8)) & 1u) != 0;
}

void FinalMap::set_occupied(GridCell c, bool occupied) {
  const std::size_t byte =
      static_cast<std::size_t>(c.y) * bytes_per_row(width_) + static_cast<std::size_t>(c.x) / 8u;
  const auto bit = static_cast<std::uint8_t>(1u << (c.x % 8));
  buffer_[byte] = occupied ? static_cast<std::uint8_t>(buffer_[byte] | bit)
                           : static_cast<std::uint8_t>(buffer_[byte] & ~bit);
}

}  // namespace tessera::bob
