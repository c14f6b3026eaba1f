#include "tessera/io/atomic_file.hpp"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

namespace tessera {
namespace {

// ".<name>.tmp-": hidden, so that a listing of the output folder (ls, a glob of *.png) never
// shows a temporary as an output, even one a killed process left behind.
std::string temp_prefix_for(const std::filesystem::path& path) {
  return "." + path.filename().string() + ".tmp-";
}

std::filesystem::path temp_path_for(const std::filesystem::path& path) {
  return path.parent_path() /
         (temp_prefix_for(path) + std::to_string(static_cast<long long>(::getpid())));
}

// True when `text` is a process id (digits only) of no running process.
bool names_dead_process(std::string_view text) {
  if (text.empty() || text.size() > 9) return false;
  long long pid = 0;
  for (const char c : text) {
    if (c < '0' || c > '9') return false;
    pid = pid * 10 + (c - '0');
  }
  return pid > 0 && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH;
}

// Removes the temporaries of `path` that processes killed while writing it left behind
// (".<name>.tmp-<pid>" whose process is gone). Best effort: errors are ignored, since the write
// itself does not depend on it.
void remove_stale_temps(const std::filesystem::path& path) {
  const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : ".";
  const std::string prefix = temp_prefix_for(path);
  std::error_code ec;
  std::filesystem::directory_iterator it(dir, ec);
  for (; !ec && it != std::filesystem::directory_iterator(); it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.starts_with(prefix) &&
        names_dead_process(std::string_view(name).substr(prefix.size()))) {
      ::unlink(it->path().c_str());
    }
  }
}

Status cannot_write(const std::filesystem::path& target, int error) {
  return runtime_error(target.string() + ": cannot write: " + std::strerror(error));
}

// Writes all of `bytes` to `fd`; 0 or the errno of the failure.
int write_all(int fd, std::string_view bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    done += static_cast<std::size_t>(n);
  }
  return 0;
}

// Flushes `fd` to disk and closes it; 0 or the errno of the failure (the fd is closed either way).
int sync_and_close(int fd) {
  if (::fsync(fd) != 0 && errno != EINVAL && errno != EROFS) {
    const int error = errno;
    ::close(fd);
    return error;
  }
  return ::close(fd) != 0 ? errno : 0;
}

// Writes and fsyncs `bytes` into a fresh `tmp`. Leaves nothing behind on failure.
Status write_temp(const std::filesystem::path& tmp, const std::filesystem::path& target,
                  std::string_view bytes) {
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) return cannot_write(target, errno);
  int error = write_all(fd, bytes);
  if (error != 0) {
    ::close(fd);
  } else {
    error = sync_and_close(fd);
  }
  if (error != 0) {
    ::unlink(tmp.c_str());
    return cannot_write(target, error);
  }
  return Ok{};
}

}  // namespace

Status write_file_atomic(const std::filesystem::path& path, std::string_view bytes) {
  const PendingFile file{path, bytes};
  return write_files_atomic(std::span<const PendingFile>(&file, 1));
}

Status write_files_atomic(std::span<const PendingFile> files) {
  std::vector<std::filesystem::path> temps;
  temps.reserve(files.size());
  const auto remove_temps = [&temps](std::size_t from) {
    for (std::size_t i = from; i < temps.size(); ++i) ::unlink(temps[i].c_str());
  };
  for (const PendingFile& f : files) {
    if (f.path.empty() || !f.path.has_filename()) {
      remove_temps(0);
      return runtime_error("'" + f.path.string() + "': cannot write: not a file name");
    }
    remove_stale_temps(f.path);
    std::filesystem::path tmp = temp_path_for(f.path);
    if (Status s = write_temp(tmp, f.path, f.bytes); !s) {
      remove_temps(0);
      return s;
    }
    temps.push_back(std::move(tmp));
  }
  for (std::size_t i = 0; i < files.size(); ++i) {
    if (::rename(temps[i].c_str(), files[i].path.c_str()) != 0) {
      const std::string reason = std::strerror(errno);
      remove_temps(i);
      return runtime_error(files[i].path.string() + ": cannot write: " + reason);
    }
  }
  return Ok{};
}

Result<AtomicFileWriter> AtomicFileWriter::open(const std::filesystem::path& path) {
  if (path.empty() || !path.has_filename()) {
    return runtime_error("'" + path.string() + "': cannot write: not a file name");
  }
  remove_stale_temps(path);
  std::filesystem::path temp = temp_path_for(path);
  const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) return cannot_write(path, errno).error();
  return AtomicFileWriter(path, std::move(temp), fd);
}

AtomicFileWriter::AtomicFileWriter(AtomicFileWriter&& other) noexcept
    : path_(std::move(other.path_)),
      temp_(std::move(other.temp_)),
      fd_(std::exchange(other.fd_, -1)),
      size_(other.size_),
      failed_(other.failed_) {}

AtomicFileWriter& AtomicFileWriter::operator=(AtomicFileWriter&& other) noexcept {
  if (this != &other) {
    abandon();
    path_ = std::move(other.path_);
    temp_ = std::move(other.temp_);
    fd_ = std::exchange(other.fd_, -1);
    size_ = other.size_;
    failed_ = other.failed_;
  }
  return *this;
}

AtomicFileWriter::~AtomicFileWriter() { abandon(); }

void AtomicFileWriter::abandon() {
  if (fd_ < 0) return;
  ::close(fd_);
  ::unlink(temp_.c_str());
  fd_ = -1;
}

Status AtomicFileWriter::append(std::string_view bytes) {
  if (fd_ < 0 || failed_) return runtime_error(path_.string() + ": cannot write: already failed");
  if (const int error = write_all(fd_, bytes); error != 0) {
    failed_ = true;
    return cannot_write(path_, error);
  }
  size_ += bytes.size();
  return Ok{};
}

Status AtomicFileWriter::commit() {
  if (fd_ < 0 || failed_) return runtime_error(path_.string() + ": cannot write: already failed");
  const int fd = std::exchange(fd_, -1);
  if (const int error = sync_and_close(fd); error != 0) {
    ::unlink(temp_.c_str());
    return cannot_write(path_, error);
  }
  if (::rename(temp_.c_str(), path_.c_str()) != 0) {
    const int error = errno;
    ::unlink(temp_.c_str());
    return cannot_write(path_, error);
  }
  return Ok{};
}

Status ensure_directory(const std::filesystem::path& dir) {
  std::error_code ec;
  if (std::filesystem::is_directory(dir, ec)) return Ok{};
  if (std::filesystem::exists(dir, ec)) {
    return runtime_error(dir.string() + ": cannot create directory: a file is in the way");
  }
  std::filesystem::create_directories(dir, ec);
  if (ec) return runtime_error(dir.string() + ": cannot create directory: " + ec.message());
  return Ok{};
}

}  // namespace tessera
