#pragma once
// The BOBMapping final map as a file (`tessera bob` writes map.bob): a small header and the
// robot's 1-bit map exactly as it sits in the robot's memory (bob/final_map.hpp).
//
//   offset  size  field
//   0       4     magic "BOB1" (ASCII)
//   4       2     width in cells, unsigned little-endian, >= 1
//   6       2     height in cells, unsigned little-endian, >= 1
//   8       2     cell side in millimetres, unsigned little-endian (220 for 0.22 m)
//   10      ...   height rows of ceil(width / 8) bytes each, cell row 0 (the lowest, y = 0)
//                 first; cell (x, y) is bit x % 8 (least significant first) of byte
//                 y * ceil(width / 8) + x / 8; 1 = not known to be wholly free (sensed
//                 occupied, never sensed, or stood in with an obstacle detected inside it,
//                 docs/decisions/0008), 0 = known empty; padding bits are 0.
//
// The file is exactly 10 + height * ceil(width / 8) bytes (an 11 x 14 map: 38 bytes).
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "tessera/core/result.hpp"
#include "tessera/grid/occupancy_grid.hpp"

namespace tessera {

inline constexpr std::size_t kBobMapHeaderBytes = 10;

struct BobMapFile {
  int width = 0;
  int height = 0;
  int cell_mm = 0;
  std::vector<std::uint8_t> rows;  // height * ceil(width / 8) bytes, FinalMap layout
  [[nodiscard]] bool operator==(const BobMapFile&) const = default;
};

/// The file's bytes. kInput error when a size does not fit 16 bits, width/height < 1 or rows has
/// the wrong length.
[[nodiscard]] Result<std::string> encode_bob_map(const BobMapFile& map);

/// Parses bytes read from `name` (used in messages: "name: bad magic, not a BOB1 map").
[[nodiscard]] Result<BobMapFile> decode_bob_map(std::string_view bytes, const std::string& name);

/// encode_bob_map written atomically (atomic_file.hpp).
[[nodiscard]] Status write_bob_map(const std::filesystem::path& path, const BobMapFile& map);

/// Reads and decodes a map.bob file; kInput errors name the file.
[[nodiscard]] Result<BobMapFile> read_bob_map(const std::filesystem::path& path);

/// The map as an occupancy grid (cell side cell_mm / 1000 m, origin (0, 0)): bit 1 occupied,
/// 0 free. The 1-bit map cannot tell an unsensed cell from an occupied one; both are occupied,
/// as the robot treats them. Lets `tessera info` and `tessera render` open map.bob files.
/// kInput error when cell_mm is 0.
[[nodiscard]] Result<OccupancyGrid> bob_map_to_grid(const BobMapFile& map, const std::string& name);

}  // namespace tessera
