#pragma once
// Writing outputs so that a failed run never leaves a half-written file (../shared/DESIGN.md): the
// bytes go to the hidden ".<name>.tmp-<pid>" in the destination's folder, are flushed to disk, and
// the temporary is renamed over the destination (POSIX rename(2) is atomic within one file system).
// A process killed while writing (SIGKILL) leaves the destination as it was, old or new, plus at
// most its hidden temporary, which the next write of the same destination removes.
#include <filesystem>
#include <span>
#include <string_view>

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

/// Creates `dir` and its missing parents; succeeds when it already is a directory. kRuntime error
/// when it cannot be created or a non-directory is in the way.
[[nodiscard]] Status ensure_directory(const std::filesystem::path& dir);

}  // namespace tessera
