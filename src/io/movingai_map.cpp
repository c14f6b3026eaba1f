#include "tessera/io/movingai_map.hpp"

#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "internal/decoders.hpp"
#include "internal/file_util.hpp"

namespace tessera {
namespace {

// The file's lines without their terminators ("\n" or "\r\n").
std::vector<std::string_view> split_lines(std::string_view text) {
  std::vector<std::string_view> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    lines.push_back(line);
    start = end + 1;
  }
  return lines;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

// Passable terrain (movingai.com/benchmarks/formats.html): '.', 'G' ground, 'S' swamp.
bool passable(char c) { return c == '.' || c == 'G' || c == 'S'; }

}  // namespace

Result<OccupancyGrid> read_movingai_map(const std::filesystem::path& path, double cell_size_m) {
  if (!(cell_size_m > 0.0)) {
    return input_error(path.string() + ": cell size must be > 0, got " +
                       io_internal::format_double(cell_size_m));
  }
  Result<std::string> text = io_internal::read_file_bytes(path);
  if (!text) return text.error();
  return io_internal::decode_movingai_map(*text, path.string(), cell_size_m);
}

namespace io_internal {

Result<OccupancyGrid> decode_movingai_map(std::string_view text, const std::string& name,
                                          double cell_size_m) {
  if (!(cell_size_m > 0.0)) {
    return input_error(name + ": cell size must be > 0, got " + format_double(cell_size_m));
  }
  const std::vector<std::string_view> lines = split_lines(text);
  const auto at = [&name](std::size_t index, const std::string& what) {
    return input_error(name + ":" + std::to_string(index + 1) + ": " + what);
  };

  // Header: "type <name>", "height H", "width W" (any order), then "map".
  long height = -1, width = -1;
  bool has_type = false;
  std::size_t i = 0;
  for (;; ++i) {
    if (i >= lines.size()) {
      return input_error(name +
                         ": bad Moving AI header: no 'map' line (expected 'type octile', "
                         "'height H', 'width W', 'map')");
    }
    const std::string_view line = trim(lines[i]);
    if (line.empty()) continue;
    if (line == "map") break;
    const std::size_t space = line.find_first_of(" \t");
    const std::string_view key = line.substr(0, space);
    const std::string_view value =
        space == std::string_view::npos ? std::string_view{} : trim(line.substr(space));
    if (key == "type") {
      has_type = true;
    } else if (key == "height" || key == "width") {
      const std::string v(value);
      char* end = nullptr;
      const long n = std::strtol(v.c_str(), &end, 10);
      if (v.empty() || *end != '\0' || n <= 0 || n > 1'000'000) {
        return at(i, "bad Moving AI header: " + std::string(key) +
                         " must be a positive integer, got '" + v + "'");
      }
      (key == "height" ? height : width) = n;
    } else {
      return at(i, "bad Moving AI header: expected 'type', 'height', 'width' or 'map', got '" +
                       std::string(line.substr(0, 20)) + "'");
    }
  }
  if (!has_type || height < 0 || width < 0) {
    return at(i, std::string("bad Moving AI header: 'map' before ") + (!has_type    ? "'type'"
                                                                       : height < 0 ? "'height'"
                                                                                    : "'width'"));
  }
  const std::size_t map_line = i;
  const int w = static_cast<int>(width), h = static_cast<int>(height);

  // Rows; trailing empty lines are allowed.
  std::size_t last = lines.size();
  while (last > map_line + 1 && trim(lines[last - 1]).empty()) --last;
  const std::size_t rows = last - (map_line + 1);
  if (rows != static_cast<std::size_t>(h)) {
    return at(rows < static_cast<std::size_t>(h) ? last - 1 : map_line + 1 + h,
              "height says " + std::to_string(h) + " but " + std::to_string(rows) + " rows follow");
  }
  for (int r = 0; r < h; ++r) {
    const std::size_t index = map_line + 1 + static_cast<std::size_t>(r);
    if (lines[index].size() != static_cast<std::size_t>(w)) {
      return at(index, "row " + std::to_string(r + 1) + " has " +
                           std::to_string(lines[index].size()) + " cells, expected width " +
                           std::to_string(w));
    }
  }
  OccupancyGrid grid(GridGeometry({0.0, 0.0}, cell_size_m, w, h));
  for (int r = 0; r < h; ++r) {
    const std::string_view row = lines[map_line + 1 + static_cast<std::size_t>(r)];
    const int y = h - 1 - r;  // file row 0 is the top
    for (int x = 0; x < w; ++x) {
      grid.set_probability({x, y}, passable(row[static_cast<std::size_t>(x)]) ? 0.0 : 1.0);
    }
  }
  return grid;
}

}  // namespace io_internal

}  // namespace tessera
