#pragma once
// Where tests find the real datasets: io/data_dir.hpp (TESSERA_DATA_DIR, empty counts as unset,
// default ../shared/data beside the project root), the lookup the CLI and benchmarks use too. When CI=true a missing dataset fails the test instead of skipping
// it.
#include <gtest/gtest.h>

#include <filesystem>

namespace tessera::support {

[[nodiscard]] std::filesystem::path data_dir();
/// data_dir() / relative.
[[nodiscard]] std::filesystem::path data_path(const std::filesystem::path& relative);
[[nodiscard]] bool running_in_ci();

}  // namespace tessera::support

/// Skips the test when `path` does not exist, or fails it when CI=true.
#define TESSERA_REQUIRE_DATA(path)                                                           \
  do {                                                                                       \
    if (!std::filesystem::exists(path)) {                                                    \
      if (::tessera::support::running_in_ci()) {                                             \
        FAIL() << "dataset missing (CI=true): " << (path).string();                          \
      } else {                                                                               \
        GTEST_SKIP() << "dataset missing: " << (path).string() << " (set TESSERA_DATA_DIR)"; \
      }                                                                                      \
    }                                                                                        \
  } while (false)
