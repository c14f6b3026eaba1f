#pragma once
// The data folder of the table programs in bench/fusion (loop_recall, stationary_table), which take
// it as an optional command-line argument.
#include <filesystem>

#include "tessera/io/data_dir.hpp"

namespace tessera::bench {

/// `argument` when the program was given one (not null); else the data folder every tessera
/// program uses (io/data_dir.hpp).
inline std::filesystem::path table_data_dir(const char* argument) {
  if (argument != nullptr) return argument;
  return data_dir();
}

}  // namespace tessera::bench
