#pragma once
// Parsing JSON input files (HouseExpo floor plans, ...) with nlohmann::json so that none of its
// exceptions leave the io module: syntax errors, numbers that overflow a double ("-1e3085") and
// absurd nesting all become one kInput error naming the file and, where known, the line.
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "tessera/core/result.hpp"

namespace tessera::io_internal {

/// Deepest nesting of arrays and objects parse_json accepts; none of tessera's JSON inputs comes
/// near it, and it keeps recursive walks over the document (dump()) within the stack.
inline constexpr int kMaxJsonDepth = 256;

/// The document in `text` (RFC 8259, one value, no comments). kInput errors, one line each:
/// "<name>:<line>: JSON syntax error: <reason>" (nlohmann's reason without its exception tag),
/// "<name>:<line>: JSON number out of range: '<token>' does not fit a double",
/// "<name>: JSON nested deeper than 256 levels".
[[nodiscard]] Result<nlohmann::json> parse_json(std::string_view text, const std::string& name);

}  // namespace tessera::io_internal
