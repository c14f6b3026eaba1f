#pragma once
// Helpers for the io tests: a private temporary folder per test, small file writers, fixtures.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include "support/temp_dir.hpp"
#include "tessera/grid/occupancy_grid.hpp"

namespace tessera::io_test {

using support::read_bytes;
using support::TempDir;
using support::write_bytes;

/// Names of the entries of `dir`, sorted.
inline std::vector<std::string> files_in(const std::filesystem::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

/// Row y of a grid as text: '.' free, `occupied` for occupied cells, '?' unknown.
inline std::string row_text(const OccupancyGrid& g, char occupied, int y) {
  std::string s;
  for (int x = 0; x < g.geometry().width(); ++x) {
    const CellState st = g.state({x, y});
    s += st == CellState::kUnknown ? '?' : st == CellState::kOccupied ? occupied : '.';
  }
  return s;
}

/// tests/fixtures/io/<relative> in the source tree (TESSERA_SOURCE_DIR, set by CTest).
inline std::filesystem::path fixture(const std::string& relative) {
  const char* root = std::getenv("TESSERA_SOURCE_DIR");
  const std::filesystem::path base = root != nullptr && *root != '\0' ? root : ".";
  return base / "tests" / "fixtures" / "io" / relative;
}

/// A small P2 PGM from rows of values, top row first.
inline std::string ascii_pgm(const std::vector<std::vector<int>>& rows, int maxval = 255) {
  std::string s = "P2\n" + std::to_string(rows.empty() ? 0 : rows[0].size()) + " " +
                  std::to_string(rows.size()) + "\n" + std::to_string(maxval) + "\n";
  for (const auto& row : rows) {
    for (std::size_t i = 0; i < row.size(); ++i) s += (i ? " " : "") + std::to_string(row[i]);
    s += "\n";
  }
  return s;
}

}  // namespace tessera::io_test
