#pragma once
// The data folder of the table programs in bench/fusion (loop_recall, stationary_table), which take
// it as an optional command-line argument.
#include <cstdlib>
#include <filesystem>

namespace tessera::bench {

/// `argument` when the program was given one (not null); else TESSERA_DATA_DIR when it is set;
/// else TESSERA_DEFAULT_DATA_DIR, the ../shared/data beside the project (bench/fusion/CMakeLists).
inline std::filesystem::path table_data_dir(const char* argument) {
  if (argument != nullptr) return argument;
  if (const char* env = std::getenv("TESSERA_DATA_DIR")) return env;
  return TESSERA_DEFAULT_DATA_DIR;
}

}  // namespace tessera::bench
