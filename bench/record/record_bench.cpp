// What --record costs on a SLAM run (issue 15: under 10 % of the run's time): laser SLAM on the
// Intel Research Lab log (first 1,088 s, 5,505 scans), then the same run recorded to MCAP
// (record_laser_slam into an McapWriter: every scan, odometry and pose, the map and the path;
// zstd chunks, summary). Prints the SLAM time, the recording time, their ratio, the file's size and
// message count.
//
//   record_bench [--log FILE] [--out FILE.mcap]
//
// The data folder is TESSERA_DATA_DIR, default ../shared/data beside the project.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>

#include "tessera/io/carmen_log.hpp"
#include "tessera/io/data_dir.hpp"
#include "tessera/io/mcap_writer.hpp"
#include "tessera/record/slam_recording.hpp"
#include "tessera/slam/laser_slam.hpp"

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
  using namespace tessera;
  std::filesystem::path log_path = data_dir() / "laser/intel/intel-raw-first5505-sot.clf";
  std::filesystem::path out = std::filesystem::temp_directory_path() / "tessera_record_bench.mcap";
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    if (flag == "--log") {
      log_path = argv[i + 1];
    } else if (flag == "--out") {
      out = argv[i + 1];
    } else {
      std::fprintf(stderr, "usage: record_bench [--log FILE] [--out FILE.mcap]\n");
      return 2;
    }
  }
  Result<LaserLog> log = read_carmen_log(log_path);
  if (!log) {
    std::fprintf(stderr, "record_bench: %s\n", log.error().message.c_str());
    return 3;
  }
  auto t0 = std::chrono::steady_clock::now();
  Result<slam::LaserSlamResult> result = slam::run_laser_slam(*log, {});
  const double slam_s = seconds_since(t0);
  if (!result) {
    std::fprintf(stderr, "record_bench: %s\n", result.error().message.c_str());
    return 4;
  }
  t0 = std::chrono::steady_clock::now();
  Result<McapWriter> writer = McapWriter::open(out);
  Status recorded = writer ? record_laser_slam(*writer, *log, *result) : writer.error();
  if (recorded) recorded = writer->finish();
  const double record_s = seconds_since(t0);
  if (!recorded) {
    std::fprintf(stderr, "record_bench: %s\n", recorded.error().message.c_str());
    return 4;
  }
  std::printf("log              %s (%zu scans)\n", log_path.string().c_str(), log->scans.size());
  std::printf("slam             %.2f s\n", slam_s);
  std::printf("record           %.3f s (%.1f %% of the SLAM time)\n", record_s,
              100.0 * record_s / slam_s);
  std::printf("file             %s: %.1f MB, %llu messages, %zu chunks\n", out.string().c_str(),
              static_cast<double>(std::filesystem::file_size(out)) / 1e6,
              static_cast<unsigned long long>(writer->message_count()), writer->chunk_count());
  return 0;
}
