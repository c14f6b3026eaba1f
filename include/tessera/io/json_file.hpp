#pragma once
#include <filesystem>
#include <nlohmann/json.hpp>

#include "tessera/core/result.hpp"

namespace tessera {

/// JSON text as tessera writes it: pretty, 2-space indent, trailing newline. Invalid UTF-8 in
/// strings is replaced by U+FFFD instead of failing.
[[nodiscard]] std::string encode_json(const nlohmann::json& value);

/// encode_json(value) written to `path` atomically (atomic_file.hpp).
[[nodiscard]] Status write_json_atomic(const std::filesystem::path& path,
                                       const nlohmann::json& value);

}  // namespace tessera
