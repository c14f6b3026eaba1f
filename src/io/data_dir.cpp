#include "tessera/io/data_dir.hpp"

#include <cstdlib>

namespace tessera {

std::filesystem::path data_dir() {
  if (const char* env = std::getenv("TESSERA_DATA_DIR"); env != nullptr && *env != '\0') {
    return env;
  }
  return TESSERA_DEFAULT_DATA_DIR;
}

}  // namespace tessera
