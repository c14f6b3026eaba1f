// Bag reading speed: writes a ~100 MB bag of uncompressed LaserScan + Odometry (+ tf) messages to
// a temp folder, as a ROS 1 bag (chunks "none") and as an MCAP file (uncompressed chunks), and
// measures read_ros_bag keeping every message's bytes (bytes/s = message data read), and the
// whole bag -> LaserLog conversion (decoding, tf, odometry interpolation). Target: at least
// 200 MB/s of message data (docs/benchmarks.md).
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "support/synthetic_bag.hpp"
#include "tessera/io/robot_bag.hpp"
#include "tessera/io/ros_bag.hpp"

namespace tessera {
namespace {

/// ~100 MB of messages: 1081-beam scans with 1081 intensities (8.7 kB each, a Hokuyo
/// UTM-30LX at 0.25 degrees) and odometry and tf at twice the scan rate.
constexpr std::size_t kScans = 11'000;
constexpr std::size_t kBeams = 1081;

struct BenchBags {
  std::filesystem::path dir;
  std::filesystem::path ros1;
  std::filesystem::path mcap;
  std::uint64_t message_bytes = 0;

  BenchBags() {
    dir = std::filesystem::temp_directory_path() /
          ("tessera-bag-bench-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    for (RosEncoding e : {RosEncoding::kRos1, RosEncoding::kCdr}) {
      support::SyntheticRun run = support::synthetic_run(e, kScans, kBeams);
      for (support::MessageToWrite& m : run.messages) {
        if (m.topic != 0) continue;  // give every scan its intensities too
        Result<LaserScanMessage> scan = decode_laser_scan(m.data, e);
        scan->intensities.assign(kBeams, 100.0F);
        m.data = support::encode_laser_scan(*scan, e);
      }
      std::uint64_t bytes = 0;
      for (const auto& m : run.messages) bytes += m.data.size();
      const bool ros1_bag = e == RosEncoding::kRos1;
      const auto path = dir / (ros1_bag ? "run.bag" : "run.mcap");
      std::ofstream out(path, std::ios::binary);
      const std::string file = ros1_bag
                                   ? support::write_ros1_bag(run.topics, run.messages, "none", 400)
                                   : support::write_mcap(run.topics, run.messages, "", "cdr", 400);
      out.write(file.data(), static_cast<std::streamsize>(file.size()));
      (ros1_bag ? ros1 : mcap) = path;
      if (ros1_bag) message_bytes = bytes;
    }
  }
  ~BenchBags() {
    std::error_code ec;
    std::filesystem::remove_all(dir, ec);
  }
};

const BenchBags& bags() {
  static const BenchBags b;
  return b;
}

void read_all(benchmark::State& state, const std::filesystem::path& path) {
  BagReadOptions keep;
  keep.keep = [](const BagTopic&) { return true; };
  std::uint64_t bytes = 0;
  for (auto _ : state) {
    Result<RosBag> bag = read_ros_bag(path, keep);
    if (!bag) {
      state.SkipWithError(bag.error().message.c_str());
      return;
    }
    bytes = bag->data.size();
    benchmark::DoNotOptimize(bag->data.data());
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(bytes * state.iterations()));
  state.counters["message_MB"] = static_cast<double>(bytes) / 1e6;
  state.counters["file_MB"] = static_cast<double>(std::filesystem::file_size(path)) / 1e6;
}

void BM_ReadRos1BagAllMessages(benchmark::State& state) { read_all(state, bags().ros1); }
void BM_ReadMcapAllMessages(benchmark::State& state) { read_all(state, bags().mcap); }

void BM_Ros1BagToLaserLog(benchmark::State& state) {
  std::size_t scans = 0;
  for (auto _ : state) {
    Result<RobotBag> r = read_robot_bag(bags().ros1);
    if (!r) {
      state.SkipWithError(r.error().message.c_str());
      return;
    }
    scans = r->log.scans.size();
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(bags().message_bytes * state.iterations()));
  state.counters["scans_per_s"] =
      benchmark::Counter(static_cast<double>(scans), benchmark::Counter::kIsIterationInvariantRate);
}

BENCHMARK(BM_ReadRos1BagAllMessages)->Unit(benchmark::kMillisecond)->MinTime(2.0)->UseRealTime();
BENCHMARK(BM_ReadMcapAllMessages)->Unit(benchmark::kMillisecond)->MinTime(2.0)->UseRealTime();
BENCHMARK(BM_Ros1BagToLaserLog)->Unit(benchmark::kMillisecond)->MinTime(2.0)->UseRealTime();

}  // namespace
}  // namespace tessera

BENCHMARK_MAIN();
