// Chunk decompression: bzip2 (libbz2's one-shot BZ2_bzBuffToBuffDecompress), LZ4 frames
// (lz4frame.h streaming API: roslz4 and MCAP both write the LZ4 frame format) and Zstandard
// (ZSTD_decompress; frames need not state their content size), and Zstandard data of unknown size
// (ZSTD_decompressStream, for rosbag2's compressed files and messages).
#include "internal/decompress.hpp"

#include <bzlib.h>
#include <lz4frame.h>
#include <zstd.h>

#include <limits>
#include <memory>

namespace tessera::io_internal {
namespace {

std::string size_mismatch(std::uint64_t got, std::uint64_t size) {
  return "decompressed to " + std::to_string(got) + " bytes, the chunk says " +
         std::to_string(size);
}

std::string bz2(Bytes in, std::vector<std::uint8_t>& out) {
  if (in.size() > std::numeric_limits<unsigned int>::max() ||
      out.size() > std::numeric_limits<unsigned int>::max()) {
    return "bz2: chunk larger than 4 GiB";
  }
  auto out_len = static_cast<unsigned int>(out.size());
  // libbz2 takes non-const pointers but does not write the source.
  const int rc =
      BZ2_bzBuffToBuffDecompress(reinterpret_cast<char*>(out.data()), &out_len,
                                 const_cast<char*>(reinterpret_cast<const char*>(in.data())),
                                 static_cast<unsigned int>(in.size()), 0, 0);
  if (rc == BZ_OUTBUFF_FULL) return "bz2: decompresses to more than the chunk's stated size";
  if (rc != BZ_OK) return "bz2: corrupt data (libbz2 error " + std::to_string(rc) + ")";
  if (out_len != out.size()) return size_mismatch(out_len, out.size());
  return {};
}

std::string lz4(Bytes in, std::vector<std::uint8_t>& out) {
  LZ4F_dctx* raw = nullptr;
  if (LZ4F_isError(LZ4F_createDecompressionContext(&raw, LZ4F_VERSION))) {
    return "lz4: cannot create a decompression context";
  }
  const std::unique_ptr<LZ4F_dctx, decltype(&LZ4F_freeDecompressionContext)> ctx(
      raw, &LZ4F_freeDecompressionContext);
  std::size_t in_pos = 0, out_pos = 0;
  while (in_pos < in.size()) {
    std::size_t in_n = in.size() - in_pos;
    std::size_t out_n = out.size() - out_pos;
    const std::size_t hint = LZ4F_decompress(ctx.get(), out.data() + out_pos, &out_n,
                                             in.data() + in_pos, &in_n, nullptr);
    if (LZ4F_isError(hint)) return std::string("lz4: ") + LZ4F_getErrorName(hint);
    in_pos += in_n;
    out_pos += out_n;
    if (hint == 0 && in_pos < in.size()) continue;  // a frame ended; another may follow
    if (in_n == 0 && out_n == 0) {
      return out_pos == out.size() ? "lz4: decompresses to more than the chunk's stated size"
                                   : "lz4: truncated frame";
    }
  }
  if (out_pos != out.size()) return size_mismatch(out_pos, out.size());
  return {};
}

std::string zstd(Bytes in, std::vector<std::uint8_t>& out) {
  const std::size_t n = ZSTD_decompress(out.data(), out.size(), in.data(), in.size());
  if (ZSTD_isError(n)) return std::string("zstd: ") + ZSTD_getErrorName(n);
  if (n != out.size()) return size_mismatch(n, out.size());
  return {};
}

}  // namespace

std::string decompress(std::string_view method, Bytes in, std::uint64_t size,
                       std::vector<std::uint8_t>& out) {
  if (size > kMaxChunkBytes) {
    return "chunk says it holds " + std::to_string(size) + " bytes uncompressed, more than the " +
           std::to_string(kMaxChunkBytes) + " this reader accepts";
  }
  out.assign(static_cast<std::size_t>(size), 0);
  if (method == "bz2") return bz2(in, out);
  if (method == "lz4") return lz4(in, out);
  if (method == "zstd") return zstd(in, out);
  return "unknown compression '" + std::string(method) + "'";
}

std::string decompress_zstd(Bytes in, std::uint64_t max_bytes, std::vector<std::uint8_t>& out) {
  const std::unique_ptr<ZSTD_DCtx, decltype(&ZSTD_freeDCtx)> ctx(ZSTD_createDCtx(), &ZSTD_freeDCtx);
  if (!ctx) return "zstd: out of memory";
  out.clear();
  ZSTD_inBuffer input{in.data(), in.size(), 0};
  std::size_t filled = 0;
  std::size_t pending = 1;  // ZSTD_decompressStream's last result: 0 once a frame is complete
  while (input.pos < input.size || pending != 0) {
    if (filled == out.size()) {
      if (out.size() >= max_bytes) {
        return "zstd: decompresses to more than " + std::to_string(max_bytes) +
               " bytes, the most this reader accepts";
      }
      const std::uint64_t grown = std::max<std::uint64_t>(2 * out.size(), std::uint64_t{1} << 16);
      out.resize(static_cast<std::size_t>(std::min<std::uint64_t>(grown, max_bytes)));
    }
    ZSTD_outBuffer output{out.data() + filled, out.size() - filled, 0};
    const std::size_t consumed_before = input.pos;
    pending = ZSTD_decompressStream(ctx.get(), &output, &input);
    if (ZSTD_isError(pending)) return std::string("zstd: ") + ZSTD_getErrorName(pending);
    filled += output.pos;
    // With room to write, no progress means the frame needs input that is not there.
    if (output.pos == 0 && input.pos == consumed_before) return "zstd: truncated frame";
  }
  out.resize(filled);
  return {};
}

}  // namespace tessera::io_internal
