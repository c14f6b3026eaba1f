// Outputs survive a kill: `tessera explore` and `tessera slam` write every output file through
// write_files_atomic, and the --record file through AtomicFileWriter (a hidden temporary, fsync,
// rename), so a run killed with SIGKILL at any
// moment leaves each output either as the previous complete run wrote it or as the new run writes
// it, never half-written, and no temporary that could be taken for an output.
//
// Each test runs the command to completion with seed A, then again and again into the same --out
// with seeds B and A in turn, killing each run after a seeded random delay aimed at its end, where
// it writes. After every kill each visible file must equal, byte for byte, that file of a complete
// run with seed A or with seed B (report.json without its timing figures), and every hidden
// file must be a temporary of an output. TESSERA_KILL_RUNS sets the number of kills (default 20,
// 10 under AddressSanitizer; `make kill-test` runs 200).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "support/temp_dir.hpp"

extern char** environ;

namespace tessera {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// Kills per command in ctest. Under AddressSanitizer every run takes several times longer, and the
// sanitizer build adds nothing to what the kills check (the program's own writes), so fewer.
#ifdef __SANITIZE_ADDRESS__
constexpr int kDefaultKills = 10;
#else
constexpr int kDefaultKills = 20;
#endif

// Starts the program with `args`, its output thrown away.
pid_t start(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  std::string program = TESSERA_CLI;
  argv.push_back(program.data());
  std::vector<std::string> copies = args;
  for (std::string& a : copies) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  pid_t pid = -1;
  const int rc = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  return rc == 0 ? pid : -1;
}

// Waits for `pid`; its exit code, or -1 when a signal ended it.
int wait_for(pid_t pid) {
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return -2;
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// The run's arguments for `seed` into `out`.
using ArgsFor = std::vector<std::string> (*)(int seed, const fs::path& out);

// report.json without the figures that differ from run to run: its "timing" object (wall time,
// planning time, real-time factor) and the measured step times of "slam" (matching_s, map_s, ...).
void drop_timing(nlohmann::json& report) {
  if (!report.is_object()) return;
  report.erase("timing");
  if (auto slam = report.find("slam"); slam != report.end() && slam->is_object()) {
    for (auto it = slam->begin(); it != slam->end();) {
      if (it.key().ends_with("_s")) {
        it = slam->erase(it);
      } else {
        ++it;
      }
    }
  }
}

// A file's contents as compared: report.json re-encoded without timing, others byte for byte.
// A report.json that does not parse is returned as it is (and then matches no reference).
std::string comparable(const fs::path& path) {
  std::string bytes = support::read_bytes(path);
  if (path.filename() != "report.json") return bytes;
  nlohmann::json j = nlohmann::json::parse(bytes, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded()) return bytes;
  drop_timing(j);
  return j.dump();
}

struct Outputs {
  std::map<std::string, std::string> visible;  // name -> comparable contents
  std::vector<std::string> hidden;             // names starting with '.'
};

Outputs outputs_in(const fs::path& dir) {
  Outputs o;
  if (!fs::exists(dir)) return o;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name.front() == '.') {
      o.hidden.push_back(name);
    } else {
      o.visible[name] = comparable(entry.path());
    }
  }
  return o;
}

// Runs `args_for` to completion with seed A, then kills `kills` runs into the same folder.
void check_kills(ArgsFor args_for, int expected_outputs) {
  support::TempDir dir;
  constexpr int kSeedA = 1, kSeedB = 2;
  const fs::path ref_a = dir / "ref_a", ref_b = dir / "ref_b", out = dir / "out";

  // Reference outputs of complete runs, and how long a run takes.
  // A complete run's time: the shortest of the three complete runs (the first one warms the
  // caches up and is slower).
  double run_s = 1e9;
  const auto run_complete = [&run_s, args_for](int seed, const fs::path& folder) {
    const auto t0 = Clock::now();
    const int code = wait_for(start(args_for(seed, folder)));
    run_s = std::min(run_s, std::chrono::duration<double>(Clock::now() - t0).count());
    return code;
  };
  ASSERT_EQ(run_complete(kSeedA, ref_a), 0);
  ASSERT_EQ(run_complete(kSeedB, ref_b), 0);
  const Outputs a = outputs_in(ref_a), b = outputs_in(ref_b);
  ASSERT_EQ(static_cast<int>(a.visible.size()), expected_outputs);
  ASSERT_EQ(b.visible.size(), a.visible.size());
  ASSERT_NE(a.visible, b.visible) << "seeds A and B must give different outputs";
  std::set<std::string> temp_prefixes;
  for (const auto& [name, bytes] : a.visible) temp_prefixes.insert("." + name + ".tmp-");

  ASSERT_EQ(run_complete(kSeedA, out), 0);
  const int kills = std::getenv("TESSERA_KILL_RUNS") ? std::atoi(std::getenv("TESSERA_KILL_RUNS"))
                                                     : kDefaultKills;
  std::mt19937 rng(20261201);
  // Kill between 40% and 110% of a complete run's time: the outputs are written at the end.
  std::uniform_real_distribution<double> delay_s(0.4 * run_s, 1.1 * run_s);
  int killed = 0, mixed = 0, with_temp = 0;
  for (int i = 0; i < kills; ++i) {
    const pid_t pid = start(args_for(i % 2 == 0 ? kSeedB : kSeedA, out));
    ASSERT_GT(pid, 0);
    std::this_thread::sleep_for(std::chrono::duration<double>(delay_s(rng)));
    if (::kill(pid, SIGKILL) == 0 && wait_for(pid) == -1) ++killed;
    const Outputs now = outputs_in(out);
    ASSERT_EQ(now.visible.size(), a.visible.size()) << "kill " << i;
    int from_a = 0, from_b = 0;
    for (const auto& [name, bytes] : now.visible) {
      ASSERT_EQ(a.visible.count(name), 1u) << "kill " << i << ": unexpected output " << name;
      const bool is_a = bytes == a.visible.at(name), is_b = bytes == b.visible.at(name);
      EXPECT_TRUE(is_a || is_b) << "kill " << i << ": " << name
                                << " is neither seed A's nor seed B's complete file";
      from_a += is_a && !is_b;
      from_b += is_b && !is_a;
    }
    mixed += from_a > 0 && from_b > 0;
    for (const std::string& name : now.hidden) {
      bool temp = false;
      for (const std::string& prefix : temp_prefixes) temp = temp || name.starts_with(prefix);
      EXPECT_TRUE(temp) << "kill " << i << ": unexpected hidden file " << name;
    }
    with_temp += !now.hidden.empty();
  }
  // A complete run replaces everything and removes the temporaries killed runs left behind.
  ASSERT_EQ(wait_for(start(args_for(kSeedB, out))), 0);
  const Outputs last = outputs_in(out);
  EXPECT_EQ(last.visible, b.visible);
  EXPECT_TRUE(last.hidden.empty()) << last.hidden.front();
  std::printf(
      "%d runs killed of %d (a complete run takes %.3f s); %d left old and new files "
      "side by side, %d left a temporary\n",
      killed, kills, run_s, mixed, with_temp);
  ::testing::Test::RecordProperty("killed", killed);
  ::testing::Test::RecordProperty("mixed", mixed);
  ::testing::Test::RecordProperty("with_temp", with_temp);
}

// Both commands also record the run (--record) into the output folder: the MCAP file is written
// piece by piece while the others are written whole, and must survive a kill the same way.
std::vector<std::string> explore_args(int seed, const fs::path& out) {
  return {"explore", "--builtin", "labyrinth",  "--seed",   std::to_string(seed),
          "--quiet", "--out",     out.string(), "--record", (out / "run.mcap").string()};
}

// slam also saves its session (--save): a run killed while it saves leaves the previous session.
std::vector<std::string> slam_args(int seed, const fs::path& out) {
  return {"slam",
          "--builtin",
          "labyrinth",
          "--seed",
          std::to_string(seed),
          "--duration-s",
          "5",
          "--quiet",
          "--out",
          out.string(),
          "--record",
          (out / "run.mcap").string(),
          "--save",
          (out / "run.tsm").string()};
}

TEST(CliKill, ExploreKilledAtRandomLeavesEveryOutputOldOrNewAndComplete) {
  // map.yaml, map.pgm, map.png, trajectory.txt, report.json, run.mcap
  check_kills(&explore_args, 6);
}

TEST(CliKill, SlamKilledAtRandomLeavesEveryOutputOldOrNewAndComplete) {
  // map.yaml, map.pgm, map.png, trajectory.txt, graph.g2o, report.json, truth.txt, odometry.txt,
  // run.mcap, run.tsm
  check_kills(&slam_args, 10);
}

}  // namespace
}  // namespace tessera
