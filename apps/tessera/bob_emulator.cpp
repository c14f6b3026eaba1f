#include "bob_emulator.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <thread>
#include <vector>

namespace tessera::cli {

Result<bool> Emulator::start(const std::string& qemu, const std::string& elf, int port) {
  std::vector<std::string> args = {qemu,
                                   "-M",
                                   "mps2-an386",
                                   "-display",
                                   "none",
                                   "-monitor",
                                   "none",
                                   "-serial",
                                   "tcp:127.0.0.1:" + std::to_string(port),
                                   "-semihosting-config",
                                   "enable=on,target=native",
                                   "-kernel",
                                   elf};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t parent = ::getpid();
  pid_ = ::fork();
  if (pid_ < 0) return runtime_error(std::string("cannot start ") + qemu + ": fork failed");
  if (pid_ == 0) {
    // The emulator dies with this process, even if it is killed (a timeout in a test).
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(127);
    const int null_fd = ::open("/dev/null", O_RDWR);
    if (null_fd >= 0) {
      ::dup2(null_fd, 0);
      ::dup2(null_fd, 1);
    }
    ::execvp(argv[0], argv.data());
    ::_exit(127);
  }
  return true;
}

void Emulator::stop() {
  if (pid_ <= 0) return;
  ::kill(pid_, SIGTERM);
  int status = 0;
  for (int i = 0; i < 50; ++i) {  // up to 1 s, then SIGKILL
    if (::waitpid(pid_, &status, WNOHANG) == pid_) {
      pid_ = -1;
      return;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ::kill(pid_, SIGKILL);
  ::waitpid(pid_, &status, 0);
  pid_ = -1;
}

}  // namespace tessera::cli
