#pragma once
// Helpers for the io tests: a private temporary folder per test, small file writers, fixtures.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

namespace tessera::io_test {

/// A fresh folder under the system temp dir, removed with everything in it at scope exit.
class TempDir {
 public:
  TempDir() {
    static int counter = 0;
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::string test = info != nullptr ? info->name() : "test";
    path_ =
        std::filesystem::temp_directory_path() /
        ("tessera-io-" + test + "-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  [[nodiscard]] const std::filesystem::path& path() const { return path_; }
  [[nodiscard]] std::filesystem::path operator/(const std::string& name) const {
    return path_ / name;
  }

 private:
  std::filesystem::path path_;
};

inline void write_bytes(const std::filesystem::path& path, std::string_view bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  ASSERT_TRUE(out.good()) << path;
}

inline std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// Names of the entries of `dir`, sorted.
inline std::vector<std::string> files_in(const std::filesystem::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
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
