#pragma once
// A tessera process started by another (tessera team starts the simulator and the robots): argv
// run as /proc/self/exe, its output to a log file, and never left behind: the destructor stops it
// (SIGTERM, then SIGKILL after a grace period), and the kernel stops it if its parent dies.
#include <sys/types.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "tessera/core/result.hpp"

namespace tessera::cli {

class ChildProcess {
 public:
  /// Starts this executable with `args` (not including argv[0]); stdout and stderr go to `log`.
  /// kRuntime error when it cannot start.
  [[nodiscard]] static Result<ChildProcess> start(const std::vector<std::string>& args,
                                                  const std::filesystem::path& log);
  ChildProcess(ChildProcess&& other) noexcept;
  ChildProcess& operator=(ChildProcess&& other) noexcept;
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;
  ~ChildProcess();

  [[nodiscard]] pid_t pid() const { return pid_; }
  /// True while it runs (reaps it when it has ended).
  [[nodiscard]] bool running();
  /// SIGKILL now, as a crash or a pulled plug would end it.
  void kill();
  /// SIGTERM, then waits up to grace_s for it to end (SIGKILL after). Returns its exit code
  /// (128 + signal when a signal ended it); nullopt when it had already been reaped.
  std::optional<int> stop(double grace_s = 10.0);

 private:
  explicit ChildProcess(pid_t pid) : pid_(pid) {}
  pid_t pid_ = -1;
  std::optional<int> exit_code_;
};

}  // namespace tessera::cli
