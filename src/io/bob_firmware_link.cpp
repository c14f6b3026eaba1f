#include "tessera/io/bob_firmware_link.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <sstream>
#include <vector>

namespace tessera {
namespace {

std::string errno_text() { return std::strerror(errno); }

// "<letter> a b c" -> the numbers after the letter.
std::vector<long long> numbers_of(const std::string& line) {
  std::istringstream in(line.substr(1));
  std::vector<long long> out;
  long long v = 0;
  while (in >> v) out.push_back(v);
  return out;
}

Result<std::vector<std::uint8_t>> hex_bytes(const std::string& line) {
  const std::size_t from = line.find(' ');
  const std::string hex = from == std::string::npos ? std::string() : line.substr(from + 1);
  if (hex.size() % 2 != 0) return runtime_error("firmware: odd hex length in \"" + line + "\"");
  std::vector<std::uint8_t> out;
  for (std::size_t i = 0; i < hex.size(); i += 2) {
    const auto nibble = [](char c) -> int {
      if (c >= '0' && c <= '9') return c - '0';
      if (c >= 'a' && c <= 'f') return c - 'a' + 10;
      return -1;
    };
    const int hi = nibble(hex[i]);
    const int lo = nibble(hex[i + 1]);
    if (hi < 0 || lo < 0) return runtime_error("firmware: bad hex in \"" + line + "\"");
    out.push_back(static_cast<std::uint8_t>(hi * 16 + lo));
  }
  return out;
}

// "<letter> <4-bit map hex> <final map hex>".
Result<BobExplorerSummary> maps_of(const std::string& line) {
  const std::size_t a = line.find(' ');
  const std::size_t b = a == std::string::npos ? a : line.find(' ', a + 1);
  if (b == std::string::npos) return runtime_error("firmware: expected two maps, got \"" + line + "\"");
  Result<std::vector<std::uint8_t>> packed = hex_bytes(line.substr(a, b - a));
  if (!packed) return packed.error();
  Result<std::vector<std::uint8_t>> final_map = hex_bytes(line.substr(b));
  if (!final_map) return final_map.error();
  BobExplorerSummary out;
  out.packed_map = std::move(*packed);
  out.final_map = std::move(*final_map);
  return out;
}

Result<bob::Status> status_of(const std::string& line) {
  const std::vector<long long> v = numbers_of(line);
  if (v.size() != 1 || v[0] < 0 || v[0] > static_cast<long long>(bob::Status::kAlreadyStarted)) {
    return runtime_error("firmware: expected a status, got \"" + line + "\"");
  }
  return static_cast<bob::Status>(v[0]);
}

}  // namespace

Result<std::unique_ptr<BobFirmwareLink>> BobFirmwareLink::listen(
    std::chrono::milliseconds timeout) {
  std::unique_ptr<BobFirmwareLink> link(new BobFirmwareLink(timeout));
  link->listen_fd_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (link->listen_fd_ < 0) return runtime_error("serial link: socket: " + errno_text());
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  addr.sin_port = 0;
  if (::bind(link->listen_fd_, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0 ||
      ::listen(link->listen_fd_, 1) != 0) {
    return runtime_error("serial link: listening on 127.0.0.1: " + errno_text());
  }
  socklen_t len = sizeof addr;
  if (::getsockname(link->listen_fd_, reinterpret_cast<sockaddr*>(&addr), &len) != 0) {
    return runtime_error("serial link: getsockname: " + errno_text());
  }
  link->port_ = ntohs(addr.sin_port);
  return link;
}

BobFirmwareLink::~BobFirmwareLink() {
  if (fd_ >= 0) ::close(fd_);
  if (listen_fd_ >= 0) ::close(listen_fd_);
}

Result<bool> BobFirmwareLink::accept() {
  pollfd p{listen_fd_, POLLIN, 0};
  if (::poll(&p, 1, static_cast<int>(timeout_.count())) <= 0) {
    return runtime_error("serial link: the firmware did not connect within " +
                         std::to_string(timeout_.count()) + " ms");
  }
  fd_ = ::accept4(listen_fd_, nullptr, nullptr, SOCK_CLOEXEC);
  if (fd_ < 0) return runtime_error("serial link: accept: " + errno_text());
  Result<std::string> hello = expect('H', "its hello");
  if (!hello) return hello.error();
  const std::vector<long long> v = numbers_of(*hello);
  if (v.size() != 2 || v[0] < 0 || v[0] > 1 || v[1] < 0 || v[1] > 1) {
    return runtime_error("firmware: bad hello \"" + *hello + "\"");
  }
  firmware_options_.backtrack = v[0] == 0 ? bob::Backtrack::kTrail
                                          : bob::Backtrack::kShortestKnownPath;
  firmware_options_.resense = v[1] == 1;
  return true;
}

Result<std::string> BobFirmwareLink::read_line() {
  for (;;) {
    const std::size_t nl = pending_.find('\n');
    if (nl != std::string::npos) {
      std::string line = pending_.substr(0, nl);
      pending_.erase(0, nl + 1);
      if (!line.empty() && line.back() == '\r') line.pop_back();
      transcript_ += line;
      transcript_ += '\n';
      return line;
    }
    pollfd p{fd_, POLLIN, 0};
    if (::poll(&p, 1, static_cast<int>(timeout_.count())) <= 0) {
      return runtime_error("firmware: no answer within " + std::to_string(timeout_.count()) +
                           " ms");
    }
    char buf[4096];
    const ssize_t n = ::recv(fd_, buf, sizeof buf, 0);
    if (n <= 0) return runtime_error("firmware: the serial link closed");
    pending_.append(buf, static_cast<std::size_t>(n));
  }
}

Result<std::string> BobFirmwareLink::expect(char letter, const char* what) {
  Result<std::string> line = read_line();
  if (!line) return line.error();
  if (line->empty() || (*line)[0] != letter) {
    return runtime_error(std::string("firmware: expected ") + what + " ('" + letter + "'), got \"" +
                         *line + "\"");
  }
  return line;
}

Result<bool> BobFirmwareLink::write(const std::string& text) {
  std::size_t sent = 0;
  while (sent < text.size()) {
    const ssize_t n = ::send(fd_, text.data() + sent, text.size() - sent, MSG_NOSIGNAL);
    if (n <= 0) return runtime_error("firmware: writing to the serial link: " + errno_text());
    sent += static_cast<std::size_t>(n);
  }
  return true;
}

Result<bob::Status> BobFirmwareLink::begin(const bob::ExplorerOptions& options, int width,
                                           int height) {
  if (options.backtrack != firmware_options_.backtrack ||
      options.resense != firmware_options_.resense) {
    return runtime_error("firmware: its explorer options (hello) differ from the run's");
  }
  if (Result<std::string> w = expect('W', "a grid request"); !w) return w.error();
  if (Result<bool> ok = write("G " + std::to_string(width) + " " + std::to_string(height) + "\n");
      !ok) {
    return ok.error();
  }
  Result<std::string> init = expect('I', "the init status");
  if (!init) return init.error();
  Result<bob::Status> status = status_of(*init);
  start_sensing_ = status && *status == bob::Status::kOk;
  return status;
}

Result<bob::Status> BobFirmwareLink::report(const StepSensing& step) {
  // At the start the firmware asks for the readings ("S"); after a move its "M" was the request.
  if (start_sensing_) {
    if (Result<std::string> s = expect('S', "a start-sensing request"); !s) return s.error();
    start_sensing_ = false;
  }
  std::string text;
  for (const CellDetection* d : {&step.left, &step.front, &step.right}) {
    if (!d->seen) continue;
    text += "T " + std::to_string(d->cell.x) + " " + std::to_string(d->cell.y) + " " +
            (d->occupied ? "1" : "0") + "\n";
  }
  for (const Cell c : step.also_occupied) {
    text += "X " + std::to_string(c.x) + " " + std::to_string(c.y) + "\n";
  }
  text += "E\n";
  if (Result<bool> ok = write(text); !ok) return ok.error();
  if (Status s = read_maps(); !s) return s.error();
  return bob::Status::kOk;
}

Result<bob::Status> BobFirmwareLink::start(Cell cell) {
  if (Result<std::string> p = expect('P', "a start-cell request"); !p) return p.error();
  if (Result<bool> ok = write("C " + std::to_string(cell.x) + " " + std::to_string(cell.y) + "\n");
      !ok) {
    return ok.error();
  }
  Result<std::string> a = expect('A', "the start status");
  if (!a) return a.error();
  return status_of(*a);
}

Result<bob::Status> BobFirmwareLink::next_move(bob::Direction& move) {
  if (finished_) return bob::Status::kFinished;
  Result<std::string> line = read_line();
  if (!line) return line.error();
  if (!line->empty() && (*line)[0] == 'M') {
    const std::vector<long long> v = numbers_of(*line);
    if (v.size() != 1 || v[0] < 0 || v[0] > 3) {
      return runtime_error("firmware: bad move \"" + *line + "\"");
    }
    move = static_cast<bob::Direction>(v[0]);
    return bob::Status::kOk;
  }
  if (line->empty() || (*line)[0] != 'F') {
    return runtime_error("firmware: expected a move or the end, got \"" + *line + "\"");
  }
  const std::vector<long long> v = numbers_of(*line);
  if (v.size() != 6 || v[1] < 0 || v[1] > static_cast<long long>(bob::StopReason::kNoReachableTarget)) {
    return runtime_error("firmware: bad end line \"" + *line + "\"");
  }
  summary_.stop_reason = static_cast<bob::StopReason>(v[1]);
  summary_.moves = static_cast<std::uint32_t>(v[2]);
  summary_.turns = static_cast<std::uint32_t>(v[3]);
  summary_.resensed = static_cast<std::uint32_t>(v[4]);
  summary_.ignored_readings = static_cast<std::uint32_t>(v[5]);
  Result<std::string> maps = expect('D', "its final maps");
  if (!maps) return maps.error();
  Result<BobExplorerSummary> m = maps_of(*maps);
  if (!m) return m.error();
  summary_.packed_map = std::move(m->packed_map);
  summary_.final_map = std::move(m->final_map);
  finished_ = true;
  return status_of("F " + std::to_string(v[0]));
}

Result<bob::Status> BobFirmwareLink::blocked() {
  if (Result<bool> ok = write("B\n"); !ok) return ok.error();
  Result<std::string> a = expect('A', "the blocked status");
  if (!a) return a.error();
  if (Status s = read_maps(); !s) return s.error();
  return status_of(*a);
}

Status BobFirmwareLink::read_maps() {
  Result<std::string> line = expect('U', "its maps after the step");
  if (!line) return line.error();
  Result<BobExplorerSummary> m = maps_of(*line);
  if (!m) return m.error();
  snapshot_ = std::move(*m);
  return Ok{};
}

Result<BobExplorerSummary> BobFirmwareLink::snapshot() { return snapshot_; }

Result<BobExplorerSummary> BobFirmwareLink::summary() {
  if (!finished_) return runtime_error("firmware: asked for its maps before it finished");
  return summary_;
}

}  // namespace tessera
