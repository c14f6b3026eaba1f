// tessera play: a CARMEN log or a ROS bag played as ROS 2 topics (nodes/log_player.hpp) on
// Cyclone DDS, paced by its stamps, so that `tessera slam --ros` (or any ROS 2 node) runs on real
// data. A bag is read as `tessera slam --bag` reads it (io/robot_bag.hpp: one scan topic, one
// odometry topic, the laser's place from its tf).
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <thread>

#include "commands.hpp"
#include "dds_options.hpp"
#include "laser_input.hpp"
#include "tessera/io/carmen_log.hpp"
#include "tessera/io/robot_bag.hpp"
#include "tessera/io/ros_bag.hpp"
#include "tessera/nodes/log_player.hpp"

namespace tessera::cli {
namespace {

// How long the player waits after its scan writer has found a reader before it sends (below).
constexpr int kDiscoveryGraceMs = 500;

// The scans and odometry to play: a bag read as `slam --bag` reads it, or a CARMEN log.
Result<LaserLog> read_played_log(const std::filesystem::path& path, const std::string& scan_topic,
                                 const std::string& odom_topic) {
  if (is_ros_bag_path(path)) {
    Result<RobotBag> bag = read_robot_bag(path, {scan_topic, odom_topic, ""});
    if (!bag.ok()) return bag.error();
    return std::move(bag->log);
  }
  if (!scan_topic.empty() || !odom_topic.empty()) {
    return usage_error("--scan-topic and --odom-topic choose a bag's topics; " + path.string() +
                       " is no bag");
  }
  return read_carmen_log(path);
}

}  // namespace

PlayCommand::PlayCommand(CLI::App& app) {
  sub_ = app.add_subcommand(
      "play",
      "Play a laser log or a ROS bag as ROS 2 topics on Cyclone DDS: <ns>/scan, <ns>/odom, /clock "
      "and /tf_static (base_link -> laser), each scan at its stamp scaled by --rate, once the "
      "first subscriber of the scans has appeared. A bag of scans alone is played without "
      "<ns>/odom (and without base_link).");
  sub_->add_option("log", log_,
                   "CARMEN log (.clf/.log: FLASER, ROBOTLASER1, RAWLASER1) or ROS bag (.bag, .db3, "
                   ".mcap or a ROS 2 bag folder)")
      ->required();
  sub_->add_option("--scan-topic", scan_topic_,
                   "Bag: the LaserScan topic (default: the bag's only one)");
  sub_->add_option("--odom-topic", odom_topic_,
                   "Bag: the Odometry topic (default: the bag's only one)");
  sub_->add_option("--rate", rate_, "Log seconds per wall-clock second (0: as fast as possible)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  sub_->add_option("--ns", ns_, "Namespace of the topics and frames, e.g. /r1 (default: none)");
  add_dds_options(*sub_, domain_, network_);
  sub_->add_option("--wait-s", wait_s_, "How long to wait for the first subscriber")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  sub_->add_option("--max-scans", max_scans_, "Stop after this many scans (0: the whole log)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  sub_->add_option("--from-s", from_s_, "Play the scans from this many seconds after the first one")
      ->check(CLI::NonNegativeNumber);
  sub_->add_option("--to-s", to_s_, "Play the scans up to this many seconds after the first one")
      ->check(CLI::NonNegativeNumber);
  sub_->add_flag("--quiet", quiet_, "No progress line and no summary");
}

int PlayCommand::run() const {
  if (Status s = check_window(from_s_, to_s_); !s) return report_error(s.error());
  Result<LaserLog> log = read_played_log(log_, scan_topic_, odom_topic_);
  if (!log.ok()) return report_error(log.error());
  if (Status s = cut_to_window(*log, from_s_, to_s_, log_.string()); !s) {
    return report_error(s.error());
  }
  Result<std::unique_ptr<net::Transport>> transport = open_dds(domain_, network_);
  if (!transport.ok()) return report_error(transport.error());
  Result<std::unique_ptr<nodes::LogPlayer>> player =
      nodes::LogPlayer::create(*log, {.ns = ns_}, **transport);
  if (!player.ok()) return report_error(player.error());

  const StopSignals stop;
  const auto t_wait = std::chrono::steady_clock::now();
  while ((*player)->scan_subscribers() == 0) {
    if (StopSignals::requested()) return kExitOk;
    if (seconds_since(t_wait) > wait_s_) {
      return report_error(runtime_error("play: no subscriber of the scans appeared in " +
                                        fmt::format("{:g}", wait_s_) + " s"));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  // DDS discovery is two-way and the two halves need not finish together: our writer can know
  // the reader before the reader knows our writer, and a best-effort reader drops what comes
  // from a writer it has not yet discovered. A moment's grace lets the first scans count.
  std::this_thread::sleep_for(std::chrono::milliseconds(kDiscoveryGraceMs));
  const std::int64_t total =
      max_scans_ > 0
          ? std::min<std::int64_t>(max_scans_, static_cast<std::int64_t>(log->scans.size()))
          : static_cast<std::int64_t>(log->scans.size());
  ProgressLine progress(!quiet_ && stderr_is_terminal());
  const auto t0 = std::chrono::steady_clock::now();
  const double first_s = (*player)->next_stamp_s();
  while (!StopSignals::requested() && !(*player)->done() &&
         static_cast<std::int64_t>((*player)->published()) < total) {
    if (rate_ > 0.0) {
      // Stamps may go backwards in real logs: such a scan goes out at once.
      const double due_s = std::max((*player)->next_stamp_s() - first_s, 0.0) / rate_;
      std::this_thread::sleep_until(t0 +
                                    std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                        std::chrono::duration<double>(due_s)));
    }
    if (Status s = (*player)->publish_next(); !s.ok()) return report_error(s.error());
    const auto done = static_cast<std::int64_t>((*player)->published());
    if (done % 25 == 0) progress.show("play: scan", done, total, "scans");
  }
  progress.finish();
  // The last scans may still be on their way (a reliable reader may ask for a resend): the
  // writers stay a moment before they go.
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  if (!quiet_) {
    fmt::print("play: {} scans published in {:.1f} s\n", (*player)->published(), seconds_since(t0));
  }
  return kExitOk;
}

}  // namespace tessera::cli
