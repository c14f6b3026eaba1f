#pragma once
// The host's end of the serial link to the BOBMapping firmware (firmware/bob/main.cpp, its wire
// protocol is described there and in docs/bob-firmware.md): the firmware runs the explorer and
// asks; the simulator (run_bob) moves the body, reads the sensors and answers. The link is a TCP
// connection on 127.0.0.1, which QEMU's `-serial tcp:127.0.0.1:PORT` makes of the emulated
// board's UART0.
#include <chrono>
#include <memory>
#include <string>

#include "tessera/core/result.hpp"
#include "tessera/sim/bob_explorer_port.hpp"

namespace tessera {

/// The firmware's side of BobExplorerPort across the serial link. Every wait for the firmware is
/// bounded by `timeout`: a firmware that does not answer is an error (kRuntime), never a hang.
class BobFirmwareLink final : public BobExplorerPort {
 public:
  /// Listens on 127.0.0.1 on a port the system picks (port()). kRuntime when that fails.
  [[nodiscard]] static Result<std::unique_ptr<BobFirmwareLink>> listen(
      std::chrono::milliseconds timeout);
  ~BobFirmwareLink() override;
  BobFirmwareLink(const BobFirmwareLink&) = delete;
  BobFirmwareLink& operator=(const BobFirmwareLink&) = delete;

  [[nodiscard]] int port() const { return port_; }
  /// Waits for the firmware's connection (QEMU connects when it starts) and reads its hello.
  [[nodiscard]] Result<bool> accept();
  /// From the hello: the firmware's explorer options (variant and re-sensing).
  [[nodiscard]] const bob::ExplorerOptions& firmware_options() const { return firmware_options_; }

  Result<bob::Status> begin(const bob::ExplorerOptions& options, int width, int height) override;
  Result<bob::Status> report(const StepSensing& step) override;
  Result<bob::Status> start(Cell cell) override;
  Result<bob::Status> next_move(bob::Direction& move) override;
  Result<bob::Status> blocked() override;
  Result<BobExplorerSummary> summary() override;
  Result<BobExplorerSummary> snapshot() override;

  /// Every line the firmware sent, for a monitor or a log (io/bob_monitor.hpp).
  [[nodiscard]] const std::string& transcript() const { return transcript_; }

 private:
  explicit BobFirmwareLink(std::chrono::milliseconds timeout) : timeout_(timeout) {}
  [[nodiscard]] Result<std::string> read_line();
  /// Reads a line and checks that it starts with `letter`.
  [[nodiscard]] Result<std::string> expect(char letter, const char* what);
  [[nodiscard]] Result<bool> write(const std::string& text);
  /// The "U" line the firmware streams after every step: its maps, kept for snapshot().
  [[nodiscard]] Status read_maps();

  std::chrono::milliseconds timeout_;
  int listen_fd_ = -1;
  int fd_ = -1;
  int port_ = 0;
  std::string pending_;  // bytes received after the last full line
  std::string transcript_;
  bob::ExplorerOptions firmware_options_{};
  BobExplorerSummary summary_;
  BobExplorerSummary snapshot_;
  bool finished_ = false;
  bool start_sensing_ = false;  // the firmware asks "S" for the readings at the start pose
};

}  // namespace tessera
