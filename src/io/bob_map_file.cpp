#include "tessera/io/bob_map_file.hpp"

#include <string>

#include "internal/file_util.hpp"
#include "tessera/io/atomic_file.hpp"

namespace tessera {
namespace {

constexpr char kMagic[4] = {'B', 'O', 'B', '1'};
constexpr int kMaxU16 = 65535;

std::size_t row_bytes(int width) { return (static_cast<std::size_t>(width) + 7u) / 8u; }

void put_u16(std::string& out, int v) {
  out.push_back(static_cast<char>(v & 0xff));
  out.push_back(static_cast<char>((v >> 8) & 0xff));
}

int get_u16(std::string_view b, std::size_t at) {
  return static_cast<int>(static_cast<unsigned char>(b[at])) |
         (static_cast<int>(static_cast<unsigned char>(b[at + 1])) << 8);
}

}  // namespace

Result<std::string> encode_bob_map(const BobMapFile& map) {
  if (map.width < 1 || map.height < 1 || map.width > kMaxU16 || map.height > kMaxU16) {
    return input_error("bob map: width and height must be 1 to 65535, got " +
                       std::to_string(map.width) + " x " + std::to_string(map.height));
  }
  if (map.cell_mm < 0 || map.cell_mm > kMaxU16) {
    return input_error("bob map: cell size must be 0 to 65535 mm, got " +
                       std::to_string(map.cell_mm));
  }
  const std::size_t expected = row_bytes(map.width) * static_cast<std::size_t>(map.height);
  if (map.rows.size() != expected) {
    return input_error("bob map: " + std::to_string(map.rows.size()) + " bytes of rows, expected " +
                       std::to_string(expected));
  }
  std::string out(kMagic, sizeof kMagic);
  put_u16(out, map.width);
  put_u16(out, map.height);
  put_u16(out, map.cell_mm);
  out.append(reinterpret_cast<const char*>(map.rows.data()), map.rows.size());
  return out;
}

Result<BobMapFile> decode_bob_map(std::string_view bytes, const std::string& name) {
  if (bytes.size() < kBobMapHeaderBytes || bytes.substr(0, 4) != std::string_view(kMagic, 4)) {
    return input_error(name + ": not a BOB1 map (bad magic or shorter than the header)");
  }
  BobMapFile map;
  map.width = get_u16(bytes, 4);
  map.height = get_u16(bytes, 6);
  map.cell_mm = get_u16(bytes, 8);
  if (map.width < 1 || map.height < 1) {
    return input_error(name + ": width and height must be >= 1, got " + std::to_string(map.width) +
                       " x " + std::to_string(map.height));
  }
  const std::size_t expected = row_bytes(map.width) * static_cast<std::size_t>(map.height);
  if (bytes.size() - kBobMapHeaderBytes != expected) {
    return input_error(name + ": " + std::to_string(bytes.size() - kBobMapHeaderBytes) +
                       " bytes of rows, expected " + std::to_string(expected) + " for " +
                       std::to_string(map.width) + " x " + std::to_string(map.height));
  }
  const auto* p = reinterpret_cast<const std::uint8_t*>(bytes.data()) + kBobMapHeaderBytes;
  map.rows.assign(p, p + expected);
  return map;
}

Status write_bob_map(const std::filesystem::path& path, const BobMapFile& map) {
  Result<std::string> bytes = encode_bob_map(map);
  if (!bytes) return bytes.error();
  return write_file_atomic(path, *bytes);
}

Result<BobMapFile> read_bob_map(const std::filesystem::path& path) {
  Result<std::string> bytes = io_internal::read_file_bytes(path);
  if (!bytes) return bytes.error();
  return decode_bob_map(*bytes, path.string());
}

Result<OccupancyGrid> bob_map_to_grid(const BobMapFile& map, const std::string& name) {
  if (map.cell_mm <= 0) return input_error(name + ": cell side 0 mm, expected > 0");
  const std::size_t row_bytes = (static_cast<std::size_t>(map.width) + 7u) / 8u;
  if (map.width < 1 || map.height < 1 ||
      map.rows.size() != row_bytes * static_cast<std::size_t>(map.height)) {
    return input_error(name + ": map rows do not match its " + std::to_string(map.width) + " x " +
                       std::to_string(map.height) + " cells");
  }
  OccupancyGrid grid(GridGeometry({0.0, 0.0}, map.cell_mm / 1000.0, map.width, map.height));
  for (int y = 0; y < map.height; ++y) {
    for (int x = 0; x < map.width; ++x) {
      const std::uint8_t byte =
          map.rows[static_cast<std::size_t>(y) * row_bytes + static_cast<std::size_t>(x) / 8u];
      grid.set_probability({x, y}, ((byte >> (x % 8)) & 1u) != 0 ? 1.0 : 0.0);
    }
  }
  return grid;
}

}  // namespace tessera
