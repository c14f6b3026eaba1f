#pragma once
// Writing outputs so that a failed run never leaves a half-written file (../shared/DESIGN.md): the
// bytes go to the hidden ".<name>.tmp-<pid>" in the destination's folder, are flushed to disk, and
// the temporary is renamed over the destination (POSIX rename(2) is atomic within one file system).
// A process killed while writing (SIGKILL) leaves the destination as it was, old or new, plus at
// most its hidden temporary, which the next write of the same destination removes.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string_view>
#include <utility>

#include "tessera/core/result.hpp"

namespace tessera {

/// Writes `bytes` to `path` atomically. On any failure the temporary is removed, `path` is left as
/// it was, and a kRuntime error names the path and the reason. Cost: one write, one fsync.
[[nodiscard]] Status write_file_atomic(const std::filesystem::path& path, std::string_view bytes);

/// One file of a group written by write_files_atomic.
struct PendingFile {
  std::filesystem::path path;
  std::string_view bytes;
};

/// Writes several files that belong together (a map's .yaml and its .pgm): every temporary is
/// written and flushed first, and only then are they renamed into place, so a failed write leaves
/// none of the new files behind. (Renames are atomic one by one, not as a group.)
[[nodiscard]] Status write_files_atomic(std::span<const PendingFile> files);

/// A file written piece by piece and put in place only when complete (an MCAP recording): the
/// pieces go to the hidden temporary of write_file_atomic, commit() flushes it to disk and renames
/// it over `path`. Destroyed without commit() (the run failed, an exception), it removes the
/// temporary and leaves `path` as it was. Move-only.
class AtomicFileWriter {
 public:
  /// Starts writing `path`'s temporary. kRuntime error naming `path` when it cannot be created.
  [[nodiscard]] static Result<AtomicFileWriter> open(const std::filesystem::path& path);
  AtomicFileWriter(AtomicFileWriter&& other) noexcept;
  AtomicFileWriter& operator=(AtomicFileWriter&& other) noexcept;
  AtomicFileWriter(const AtomicFileWriter&) = delete;
  AtomicFileWriter& operator=(const AtomicFileWriter&) = delete;
  ~AtomicFileWriter();

  /// Appends `bytes`. kRuntime error naming the path (disk full, ...); the writer is then failed
  /// and commit() refuses.
  [[nodiscard]] Status append(std::string_view bytes);
  /// Flushes, closes and renames the temporary over the path. Once only.
  [[nodiscard]] Status commit();
  /// Bytes appended so far.
  [[nodiscard]] std::uint64_t size() const { return size_; }
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

 private:
  AtomicFileWriter(std::filesystem::path path, std::filesystem::path temp, int fd)
      : path_(std::move(path)), temp_(std::move(temp)), fd_(fd) {}
  void abandon();
  std::filesystem::path path_;
  std::filesystem::path temp_;
  int fd_ = -1;
  std::uint64_t size_ = 0;
  bool failed_ = false;
};

/// Creates `dir` and its missing parents; succeeds when it already is a directory. kRuntime error
/// when it cannot be created or a non-directory is in the way.
[[nodiscard]] Status ensure_directory(const std::filesystem::path& dir);

}  // namespace tessera
