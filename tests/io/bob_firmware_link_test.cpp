// The host's end of the serial link to the BOBMapping firmware (io/bob_firmware_link.hpp), against
// a fake firmware on a thread: bad or missing answers are errors, never hangs.
#include "tessera/io/bob_firmware_link.hpp"

#include <arpa/inet.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <thread>

namespace tessera {
namespace {

using ::testing::HasSubstr;
using namespace std::chrono_literals;

/// Connects to 127.0.0.1:port, sends `text`, keeps the connection open until `hold` has passed,
/// and stores what it received.
class FakeFirmware {
 public:
  FakeFirmware(int port, std::string text, std::chrono::milliseconds hold)
      : thread_([this, port, text = std::move(text), hold] {
          const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
          sockaddr_in addr{};
          addr.sin_family = AF_INET;
          addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
          addr.sin_port = htons(static_cast<std::uint16_t>(port));
          if (::connect(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) == 0) {
            (void)::send(fd, text.data(), text.size(), MSG_NOSIGNAL);
            const auto until = std::chrono::steady_clock::now() + hold;
            char buf[256];
            while (std::chrono::steady_clock::now() < until) {
              timeval tv{0, 20000};
              ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
              const ssize_t n = ::recv(fd, buf, sizeof buf, 0);
              if (n > 0) received_.append(buf, static_cast<std::size_t>(n));
            }
          }
          ::close(fd);
        }) {}
  ~FakeFirmware() {
    if (thread_.joinable()) thread_.join();
  }
  FakeFirmware(const FakeFirmware&) = delete;
  FakeFirmware& operator=(const FakeFirmware&) = delete;
  void join() { thread_.join(); }
  [[nodiscard]] const std::string& received() const { return received_; }

 private:
  std::string received_;
  std::thread thread_;
};

TEST(BobFirmwareLink, ReadsTheVariantFromTheHelloAndAnswersTheGridRequest) {
  auto link = BobFirmwareLink::listen(2000ms);
  ASSERT_TRUE(link.ok()) << link.error().message;
  std::string received;
  {
    FakeFirmware fw((*link)->port(), "H 1 0\nW\nI 0\n", 300ms);
    ASSERT_TRUE((*link)->accept().ok());
    EXPECT_EQ((*link)->firmware_options().backtrack, bob::Backtrack::kShortestKnownPath);
    EXPECT_FALSE((*link)->firmware_options().resense);
    const Result<bob::Status> s = (*link)->begin({bob::Backtrack::kShortestKnownPath, false}, 11, 14);
    ASSERT_TRUE(s.ok()) << s.error().message;
    EXPECT_EQ(*s, bob::Status::kOk);
    fw.join();
    received = fw.received();
  }
  EXPECT_EQ(received, "G 11 14\n");
}

TEST(BobFirmwareLink, ABadHelloIsAnError) {
  auto link = BobFirmwareLink::listen(2000ms);
  ASSERT_TRUE(link.ok());
  FakeFirmware fw((*link)->port(), "hello world\n", 100ms);
  const Result<bool> r = (*link)->accept();
  ASSERT_FALSE(r.ok());
  EXPECT_THAT(r.error().message, HasSubstr("expected its hello"));
}

TEST(BobFirmwareLink, AFirmwareThatStopsAnsweringIsAnErrorAfterTheTimeout) {
  auto link = BobFirmwareLink::listen(200ms);
  ASSERT_TRUE(link.ok());
  FakeFirmware fw((*link)->port(), "H 0 1\n", 600ms);
  ASSERT_TRUE((*link)->accept().ok());
  const Result<bob::Status> s = (*link)->begin({bob::Backtrack::kTrail, true}, 11, 14);
  ASSERT_FALSE(s.ok());
  EXPECT_THAT(s.error().message, HasSubstr("no answer within 200 ms"));
}

TEST(BobFirmwareLink, OptionsThatDifferFromTheFirmwaresAreRefused) {
  auto link = BobFirmwareLink::listen(500ms);
  ASSERT_TRUE(link.ok());
  FakeFirmware fw((*link)->port(), "H 0 1\n", 100ms);
  ASSERT_TRUE((*link)->accept().ok());
  const Result<bob::Status> s = (*link)->begin({bob::Backtrack::kTrail, false}, 11, 14);
  ASSERT_FALSE(s.ok());
  EXPECT_THAT(s.error().message, HasSubstr("differ"));
}

TEST(BobFirmwareLink, NoFirmwareConnectingIsAnErrorAfterTheTimeout) {
  auto link = BobFirmwareLink::listen(100ms);
  ASSERT_TRUE(link.ok());
  const Result<bool> r = (*link)->accept();
  ASSERT_FALSE(r.ok());
  EXPECT_THAT(r.error().message, HasSubstr("did not connect"));
}

}  // namespace
}  // namespace tessera
