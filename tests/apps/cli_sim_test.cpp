// tessera sim as a process: another DDS participant (this test) sees its topics, drives a robot by
// /r1/cmd_vel, and stops it with SIGTERM, on which it exits 0; bad options are usage errors.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include "cli_run.hpp"
#include "support/dds_isolation.hpp"
#include "tessera/io/ros_message_encoders.hpp"
#include "tessera/io/ros_messages.hpp"
#include "tessera/net/dds_transport.hpp"

extern char** environ;

namespace tessera {
namespace {

using net::Qos;
using ::testing::HasSubstr;

// The program, started with `args`; killed (SIGKILL) if the test leaves before it exits.
class Process {
 public:
  explicit Process(std::vector<std::string> args) {
    args.insert(args.begin(), TESSERA_CLI);
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    if (posix_spawn(&pid_, TESSERA_CLI, nullptr, nullptr, argv.data(), environ) != 0) pid_ = -1;
  }
  ~Process() {
    if (pid_ > 0) {
      kill(pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
    }
  }
  [[nodiscard]] bool started() const { return pid_ > 0; }
  // Sends `signal` and waits up to `timeout_s` for the exit; its exit code, or -1.
  int stop(int signal, double timeout_s) {
    kill(pid_, signal);
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
    while (std::chrono::steady_clock::now() < end) {
      int status = 0;
      if (waitpid(pid_, &status, WNOHANG) == pid_) {
        pid_ = -1;
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return -1;
  }

 private:
  pid_t pid_ = -1;
};

TEST(CliSim, PublishesTheRobotsTopicsObeysCmdVelAndStopsOnSigterm) {
  const std::uint32_t domain = support::test_dds_domain();
  Process sim({"sim", "--robots", "2", "--start", "3,7", "--start", "6,7,1.57", "--rate", "5",
               "--domain", std::to_string(domain), "--quiet"});
  ASSERT_TRUE(sim.started());
  auto me = net::make_dds_transport({.domain_id = domain});
  ASSERT_TRUE(me.ok()) << me.error().message;
  net::Transport& t = **me;
  std::vector<LaserScanMessage> scans;
  std::vector<OdometryMessage> odoms;
  std::int64_t clock_ns = -1;
  ASSERT_TRUE(t.subscribe({"/r2/scan", std::string(kRos2LaserScan), Qos::sensor_data()},
                          [&](std::span<const std::uint8_t> cdr) {
                            if (auto m = decode_laser_scan(cdr, RosEncoding::kCdr); m.ok()) {
                              scans.push_back(*m);
                            }
                          })
                  .ok());
  ASSERT_TRUE(t.subscribe({"/r1/odom", std::string(kRos2Odometry), Qos::sensor_data()},
                          [&](std::span<const std::uint8_t> cdr) {
                            if (auto m = decode_odometry(cdr, RosEncoding::kCdr); m.ok()) {
                              odoms.push_back(*m);
                            }
                          })
                  .ok());
  ASSERT_TRUE(t.subscribe({"/clock", std::string(kRos2Clock), Qos::sensor_data()},
                          [&](std::span<const std::uint8_t> cdr) {
                            if (auto m = decode_cdr_clock(cdr); m.ok()) clock_ns = m->clock_ns;
                          })
                  .ok());
  const auto cmd = t.advertise({"/r1/cmd_vel", std::string(kRos2Twist), Qos::reliable(10)});
  ASSERT_TRUE(cmd.ok());
  TwistMessage forward;
  forward.linear_x_mps = 0.5;
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  double driven_m = 0.0;
  while (std::chrono::steady_clock::now() < end && driven_m < 0.3) {
    ASSERT_TRUE(t.publish(*cmd, encode_cdr(forward)).ok());
    t.wait(0.02);
    t.poll();
    if (!odoms.empty()) driven_m = odoms.back().pose.x_m;
  }
  EXPECT_GE(driven_m, 0.3) << odoms.size() << " odometry messages";
  ASSERT_FALSE(scans.empty());
  EXPECT_EQ(scans.back().header.frame_id, "r2/laser");
  EXPECT_EQ(scans.back().ranges_m.size(), 360U);
  EXPECT_GT(clock_ns, 0);
  EXPECT_EQ(odoms.back().header.frame_id, "r1/odom");
  EXPECT_EQ(sim.stop(SIGTERM, 20.0), 0);
}

TEST(CliSim, BadOptionsAreUsageAndInputErrors) {
  const auto starts = support::run_cli("sim --robots 2 --start 3,7 --duration-s 1");
  EXPECT_EQ(starts.exit_code, 2);
  EXPECT_THAT(starts.output, HasSubstr("--start: given 1 times for 2 robots"));
  const auto start_text = support::run_cli("sim --start '3;6' --duration-s 1");
  EXPECT_EQ(start_text.exit_code, 2);
  EXPECT_THAT(start_text.output, HasSubstr("expected X,Y or X,Y,THETA"));
  const auto domain = support::run_cli("sim --domain 300 --duration-s 1");
  EXPECT_EQ(domain.exit_code, 2);
  const auto wall = support::run_cli("sim --start 0.01,0.01 --duration-s 1");
  EXPECT_EQ(wall.exit_code, 3);
  EXPECT_THAT(wall.output, HasSubstr("is in a wall"));
  const auto missing = support::run_cli("sim --world /nonexistent/map.yaml --duration-s 1");
  EXPECT_EQ(missing.exit_code, 3);
}

TEST(CliSim, RunsForItsDurationAsFastAsItCan) {
  const auto run = support::run_cli("sim --robots 3 --rate 0 --duration-s 2 --domain " +
                                    std::to_string(support::test_dds_domain()));
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_THAT(run.output, HasSubstr("sim: 3 robots, 2.0 s simulated"));
}

}  // namespace
}  // namespace tessera
