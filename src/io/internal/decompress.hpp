#pragma once
// Chunk decompression for the bag readers, on Debian's libbz2, liblz4 and libzstd. The caller
// says how many bytes the chunk must decompress to (ROS bag 2.0 chunk "size", MCAP
// uncompressed_size); anything else is an error, so a corrupt chunk never yields half a chunk.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "internal/byte_cursor.hpp"

namespace tessera::io_internal {

/// The largest chunk a reader decompresses (256 MiB): a bag that claims more is refused, not
/// allocated. rosbag's chunks are 768 KiB by default and MCAP writers' a few MiB.
inline constexpr std::uint64_t kMaxChunkBytes = std::uint64_t{1} << 28;

/// Decompresses `in` into `out` (resized to `size`). `method` is "bz2" (bzip2 stream), "lz4" (LZ4
/// frame format, as roslz4 and MCAP write it) or "zstd" (Zstandard frames). Returns an empty
/// string on success, otherwise what went wrong ("lz4: ... ", "decompressed to 100 bytes, the
/// chunk says 120").
[[nodiscard]] std::string decompress(std::string_view method, Bytes in, std::uint64_t size,
                                     std::vector<std::uint8_t>& out);

/// Decompresses `in`, one or more Zstandard frames whose size need not be stated (a streaming
/// writer's: rosbag2's file and message compression), into `out`, refusing more than `max_bytes`.
/// Returns an empty string on success, otherwise what went wrong ("zstd: truncated frame").
[[nodiscard]] std::string decompress_zstd(Bytes in, std::uint64_t max_bytes,
                                          std::vector<std::uint8_t>& out);

}  // namespace tessera::io_internal
