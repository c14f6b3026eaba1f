#include "support/data.hpp"

#include <cstdlib>
#include <string_view>

#include "tessera/io/data_dir.hpp"

namespace tessera::support {

std::filesystem::path data_dir() { return tessera::data_dir(); }

std::filesystem::path data_path(const std::filesystem::path& relative) {
  return data_dir() / relative;
}

bool running_in_ci() {
  const char* env = std::getenv("CI");
  return env != nullptr && std::string_view(env) == "true";
}

}  // namespace tessera::support
