#pragma once
// The QEMU process that runs the BOB firmware for `tessera bob --firmware` (scripts/
// bob_firmware_test.sh, docs/bob-firmware.md): an emulated MPS2 AN386 (Cortex-M4) whose UART0 is
// connected to 127.0.0.1:port.
#include <sys/types.h>

#include <string>

#include "tessera/core/result.hpp"

namespace tessera::cli {

/// Stopped (SIGTERM, then SIGKILL) when this goes out of scope, whatever happened; the emulator
/// also dies with this process if it is killed (a timeout in a test).
class Emulator {
 public:
  Emulator() = default;
  Emulator(const Emulator&) = delete;
  Emulator& operator=(const Emulator&) = delete;
  ~Emulator() { stop(); }

  /// Starts `qemu` on `elf` with its serial port on 127.0.0.1:port; does not wait for it.
  Result<bool> start(const std::string& qemu, const std::string& elf, int port);
  /// Stops the emulator if it runs (up to 1 s after SIGTERM, then SIGKILL).
  void stop();

 private:
  pid_t pid_ = -1;
};

}  // namespace tessera::cli
