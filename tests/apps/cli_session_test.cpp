// Saved sessions from the command line (issue 16): slam --save writes one, info describes it,
// session export gives back the run's own map, trajectory and graph, and a damaged, truncated or
// newer file is one input error naming it, with nothing written.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "cli_run.hpp"
#include "support/temp_dir.hpp"

namespace tessera {
namespace {

using support::read_bytes;
using support::run_cli;
using support::TempDir;
using support::write_bytes;
using ::testing::HasSubstr;

// One simulated SLAM run saved as a session, shared by the tests.
const std::filesystem::path& saved_run() {
  static const TempDir dir;
  static const bool ran = [] {
    const auto r =
        run_cli("slam --builtin office --duration-s 20 --quiet --out " +
                (dir.path() / "run").string() + " --save " + (dir.path() / "run.tsm").string());
    EXPECT_EQ(r.exit_code, 0) << r.output;
    return true;
  }();
  (void)ran;
  return dir.path();
}

TEST(CliSession, SavedSessionIsDescribedAndExportsTheRunsOwnOutputs) {
  const auto& dir = saved_run();
  const auto info = run_cli("info " + (dir / "run.tsm").string());
  ASSERT_EQ(info.exit_code, 0) << info.output;
  EXPECT_THAT(info.output, HasSubstr("tessera session, format 3"));
  EXPECT_THAT(info.output, HasSubstr("scans       201 over 20.0 s"));
  const TempDir out;
  const auto exported = run_cli("session export " + (dir / "run.tsm").string() + " --quiet --out " +
                                out.path().string());
  ASSERT_EQ(exported.exit_code, 0) << exported.output;
  for (const char* f : {"trajectory.txt", "graph.g2o", "map.pgm", "map.yaml"}) {
    EXPECT_EQ(read_bytes(out.path() / f), read_bytes(dir / "run" / f)) << f;
  }
  EXPECT_TRUE(std::filesystem::exists(out.path() / "map.png"));
  const nlohmann::json report = nlohmann::json::parse(read_bytes(out.path() / "report.json"));
  EXPECT_EQ(report["command"], "session export");
  EXPECT_TRUE(report.contains("tessera_version"));
  EXPECT_TRUE(report["timing"].contains("wall_s"));
  EXPECT_EQ(report["session"]["scans"], 201);
}

TEST(CliSession, DamagedTruncatedAndNewerSessionsAreInputErrorsThatWriteNothing) {
  const std::string good = read_bytes(saved_run() / "run.tsm");
  ASSERT_GT(good.size(), 1000u);
  const TempDir dir;
  std::string flipped = good;
  flipped[good.size() / 2] = static_cast<char>(flipped[good.size() / 2] ^ 0x01);
  std::string newer = good;
  newer[8] = 7;
  const std::pair<std::string, std::string> cases[] = {
      {good.substr(0, good.size() / 3), "truncated"},
      {flipped, "checksum mismatch, the file is damaged"},
      {newer, "session format 7 is not one this tessera reads"},
      {"P2\n1 1\n255\n0\n", "not a tessera session"}};
  for (const auto& [bytes, why] : cases) {
    const auto file = dir.path() / "bad.tsm";
    write_bytes(file, bytes);
    const auto info = run_cli("info " + file.string());
    EXPECT_EQ(info.exit_code, 3) << why;
    EXPECT_THAT(info.output, HasSubstr(file.string() + ": " + why));
    const auto exported =
        run_cli("session export " + file.string() + " --out " + (dir.path() / "out").string());
    EXPECT_EQ(exported.exit_code, 3) << why;
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "out")) << why;
    EXPECT_EQ(read_bytes(file), bytes) << "the session file is left as it was";
  }
}

TEST(CliSession, SaveIsForLogBagAndWorldRuns) {
  const auto r = run_cli("slam --ros --save s.tsm");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.output, HasSubstr("--save saves a --log, --bag or --world run"));
  const auto no_file = run_cli("session export");
  EXPECT_EQ(no_file.exit_code, 2);
}

}  // namespace
}  // namespace tessera
