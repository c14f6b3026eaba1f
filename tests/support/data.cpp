#include "support/data.hpp"

#include <cstdlib>
#include <string_view>

namespace tessera::support {

std::filesystem::path data_dir() {
  if (const char* env = std::getenv("TESSERA_DATA_DIR"); env != nullptr && *env != '\0') {
    return env;
  }
  return TESSERA_DEFAULT_DATA_DIR;
}

std::filesystem::path data_path(const std::filesystem::path& relative) {
  return data_dir() / relative;
}

bool running_in_ci() {
  const char* env = std::getenv("CI");
  return env != nullptr && std::string_view(env) == "true";
}

}  // namespace tessera::support
