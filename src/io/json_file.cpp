#include "tessera/io/json_file.hpp"

#include "tessera/io/atomic_file.hpp"

namespace tessera {

std::string encode_json(const nlohmann::json& value) {
  return value.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

Status write_json_atomic(const std::filesystem::path& path, const nlohmann::json& value) {
  return write_file_atomic(path, encode_json(value));
}

}  // namespace tessera
