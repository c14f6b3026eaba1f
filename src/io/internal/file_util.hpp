#pragma once
// Private helpers shared by the io readers and writers.
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

#include "tessera/core/result.hpp"

namespace tessera::io_internal {

/// Largest grid a reader builds (2^28 cells, 1.3 GB as an OccupancyGrid); beyond it a file or an
/// option is wrong, and the reader says so instead of exhausting memory.
inline constexpr std::size_t kMaxCells = std::size_t{1} << 28;

/// The whole file. kInput "<path>: no such file" / "<path>: is a directory" /
/// "<path>: cannot read: <reason>".
[[nodiscard]] Result<std::string> read_file_bytes(const std::filesystem::path& path);

/// 1-based line number of byte `offset` in `text`.
[[nodiscard]] int line_of_offset(std::string_view text, std::size_t offset);

/// Shortest decimal text that reads back as exactly `v` ("0.05", not "0.050000000000000003").
[[nodiscard]] std::string format_double(double v);

/// Lower-case extension including the dot (".yaml"), empty if none.
[[nodiscard]] std::string lower_extension(const std::filesystem::path& path);

/// Parses a whole string as a finite double (no trailing garbage).
[[nodiscard]] bool parse_double(std::string_view text, double& out);

}  // namespace tessera::io_internal
