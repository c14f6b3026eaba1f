// One report and one configuration for every command (issue 13 parts 5 and 6, decision 0017):
// every command that writes report.json writes the core keys of docs/report-schema.md, and
// --print-config prints YAML that --config reads back into the same run; a wrong key or a wrong
// type in the file is a usage error (exit 2) naming the file, the key and the line.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_run.hpp"
#include "support/data.hpp"

namespace tessera {
namespace {

using support::run_cli;
using support::TempDir;
using ::testing::HasSubstr;

const std::filesystem::path kPhotos = "rgbd/rtabmap_loop_samples/images";

// A square of odometry edges whose last node drifted, closed by a loop edge.
const std::string kSquare =
    "VERTEX_SE2 0 0 0 0\nVERTEX_SE2 1 2 0 1.6\nVERTEX_SE2 2 2.1 2 3.1\nVERTEX_SE2 3 0.2 2.2 -1.5\n"
    "EDGE_SE2 0 1 2 0 1.5707963 100 0 0 100 0 100\nEDGE_SE2 1 2 2 0 1.5707963 100 0 0 100 0 100\n"
    "EDGE_SE2 2 3 2 0 1.5707963 100 0 0 100 0 100\nEDGE_SE2 3 0 2 0 1.5707963 100 0 0 100 0 100\n";
// Straight ahead at 1 m/s, one pose a second, stamps 0..4 s; the reference is 0.1 m to the side.
const std::string kStraight =
    "0 0 0 0 0 0 0 1\n1 1 0 0 0 0 0 1\n2 2 0 0 0 0 0 1\n3 3 0 0 0 0 0 1\n4 4 0 0 0 0 0 1\n";
const std::string kShifted =
    "0 0 0.1 0 0 0 0 1\n1 1 0.1 0 0 0 0 1\n2 2 0.1 0 0 0 0 1\n3 3 0.1 0 0 0 0 1\n4 4 0.1 0 0 0 0 1\n";

/// One command on small built-in inputs: its arguments (the output folder appended as
/// `out_flag` DIR) and where its report lands inside DIR.
struct Case {
  std::string name;
  std::string args;
  std::string out_flag = "--out";
  std::string report = "report.json";
};

std::vector<Case> cases(const TempDir& dir) {
  support::write_bytes(dir / "square.g2o", kSquare);
  support::write_bytes(dir / "traj.txt", kStraight);
  support::write_bytes(dir / "ref.txt", kShifted);
  support::write_bytes(dir / "rel.txt", "0 1 1 0 0 0 0 0\n1 3 2 0 0 0 0 0\n");
  return {
      {"explore", "explore --quiet --max-steps 200"},
      {"bob", "bob --quiet"},
      {"gridmatch", "gridmatch --quiet"},
      {"slam", "slam --quiet --builtin office --duration-s 20"},
      {"eval relations", "eval relations --trajectory " + (dir / "traj.txt").string() +
                             " --relations " + (dir / "rel.txt").string()},
      {"eval ate", "eval ate --trajectory " + (dir / "traj.txt").string() + " --reference " +
                       (dir / "ref.txt").string()},
      // The report goes beside the graph: DIR/opt.report.json for DIR/opt.g2o (see out()).
      {"posegraph optimize", "posegraph optimize --quiet " + (dir / "square.g2o").string(), "",
       "opt.report.json"},
  };
}

/// The output arguments of `c` for folder `out`.
std::string out_args(const Case& c, const std::filesystem::path& out) {
  if (c.out_flag.empty()) return " " + (out / "opt.g2o").string();
  return " " + c.out_flag + " " + out.string();
}

nlohmann::json run_for_report(const Case& c, const std::string& extra,
                              const std::filesystem::path& out) {
  std::filesystem::create_directories(out);
  const support::CliRun run = run_cli(c.args + extra + out_args(c, out));
  EXPECT_EQ(run.exit_code, 0) << c.name << ": " << run.output;
  if (run.exit_code != 0) return nullptr;
  return nlohmann::json::parse(support::read_bytes(out / c.report));
}

void expect_core_keys(const nlohmann::json& r, const std::string& command) {
  SCOPED_TRACE(command);
  ASSERT_TRUE(r.is_object());
  EXPECT_EQ(r.value("tessera_version", ""), TESSERA_PROJECT_VERSION);
  EXPECT_EQ(r.value("command", ""), command);
  ASSERT_TRUE(r.contains("seed"));
  EXPECT_TRUE(r["seed"].is_null() || r["seed"].is_number_unsigned());
  ASSERT_TRUE(r.contains("options"));
  EXPECT_TRUE(r["options"].is_object());
  ASSERT_TRUE(r.contains("timing"));
  const nlohmann::json& t = r["timing"];
  ASSERT_TRUE(t.contains("wall_s") && t.contains("data_duration_s") &&
              t.contains("realtime_factor"))
      << t.dump();
  EXPECT_GE(t["wall_s"].get<double>(), 0.0);
  if (t["data_duration_s"].is_number() && t["wall_s"].get<double>() > 0.0) {
    EXPECT_DOUBLE_EQ(t["realtime_factor"].get<double>(),
                     t["data_duration_s"].get<double>() / t["wall_s"].get<double>());
  } else {
    EXPECT_TRUE(t["realtime_factor"].is_null());
  }
}

/// A report without what differs from run to run: "timing", the per-stage seconds that slam
/// ("slam": matching_s, ...) and posegraph ("posegraph": time_s) report beside their counts, and
/// posegraph's "output" (the two runs write to different folders).
nlohmann::json without_timing(nlohmann::json r) {
  r.erase("timing");
  r.erase("output");
  for (const char* section : {"slam", "posegraph"}) {
    if (!r.contains(section)) continue;
    for (const char* key :
         {"matching_s", "loop_search_s", "optimization_s", "whole_map_s", "map_s", "time_s"}) {
      r[section].erase(key);
    }
  }
  return r;
}

/// A folder name for a case: "eval relations" -> "eval_relations".
std::string folder(std::string name) {
  for (char& c : name) {
    if (c == ' ') c = '_';
  }
  return name;
}

TEST(CliReport, EveryCommandThatWritesAReportWritesTheCoreKeys) {
  TempDir dir;
  for (const Case& c : cases(dir)) {
    expect_core_keys(run_for_report(c, "", dir / ("core_" + folder(c.name))), c.name);
  }
}

TEST(CliReport, FusionWorldRunWritesTheCoreKeys) {
  TESSERA_REQUIRE_DATA(support::data_path(kPhotos));
  TempDir dir;
  const Case c{"fusion", "fusion --quiet --builtin office --route-length-m 3 --seed 2 --textures " +
                             support::data_path(kPhotos).string()};
  expect_core_keys(run_for_report(c, "", dir / "fusion"), "fusion");
}

TEST(CliReport, BobPutsTableOneUnderMapAccuracy) {
  TempDir dir;
  const nlohmann::json r = run_for_report({"bob", "bob --quiet"}, "", dir / "bob");
  for (const char* key :
       {"cells_compared", "correct", "empty_as_occupied", "occupied_as_empty", "success_rate"}) {
    EXPECT_TRUE(r["map_accuracy"].contains(key)) << key;
  }
  EXPECT_TRUE(r["map_accuracy"].contains("path_cells"));  // Table 1's own columns beside them
  EXPECT_FALSE(r.contains("bob"));
}

// `tessera X --print-config > c.yaml && tessera X --config c.yaml` is the run with the defaults.
TEST(CliConfig, PrintedConfigReadsBackIntoTheSameReportForEveryCommand) {
  TempDir dir;
  for (const Case& c : cases(dir)) {
    SCOPED_TRACE(c.name);
    const support::CliRun printed = run_cli(c.args + " --print-config" + out_args(c, dir / "p"));
    ASSERT_EQ(printed.exit_code, 0) << printed.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "p" / c.report)) << "--print-config ran the command";
    const auto yaml = dir / (folder(c.name) + ".yaml");
    support::write_bytes(yaml, printed.output);
    // The file read back prints itself again.
    const support::CliRun again =
        run_cli(c.args + " --config " + yaml.string() + " --print-config" + out_args(c, dir / "p"));
    ASSERT_EQ(again.exit_code, 0) << again.output;
    EXPECT_EQ(again.output, printed.output);

    const nlohmann::json defaults = run_for_report(c, "", dir / ("d_" + folder(c.name)));
    const nlohmann::json configured =
        run_for_report(c, " --config " + yaml.string(), dir / ("c_" + folder(c.name)));
    EXPECT_EQ(without_timing(configured), without_timing(defaults));
  }
}

TEST(CliConfig, TheFileChangesTheRunAndTheCommandLineWinsOverIt) {
  TempDir dir;
  support::write_bytes(dir / "c.yaml", "# two robots\nrobots: 2\nstrategy: priority\n");
  const Case c{"explore", "explore --quiet --max-steps 50"};
  const nlohmann::json from_file = run_for_report(c, " --config " + (dir / "c.yaml").string(),
                                                  dir / "a");
  EXPECT_EQ(from_file["options"]["robots"], 2);
  EXPECT_EQ(from_file["options"]["strategy"], "priority");
  const nlohmann::json overridden = run_for_report(
      c, " --robots 3 --config " + (dir / "c.yaml").string(), dir / "b");
  EXPECT_EQ(overridden["options"]["robots"], 3);
  EXPECT_EQ(overridden["options"]["strategy"], "priority");
}

TEST(CliConfig, AnUnknownKeyIsAUsageErrorNamingFileKeyAndLine) {
  TempDir dir;
  const auto file = dir / "bad.yaml";
  support::write_bytes(file, "robots: 2\n\nrobtos: 3\n");
  const support::CliRun run = run_cli("explore --config " + file.string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_THAT(run.output, HasSubstr(file.string() + ":3: unknown key 'robtos'"));
  EXPECT_THAT(run.output, HasSubstr("robots"));  // the keys it knows
}

TEST(CliConfig, AWrongTypeIsAUsageErrorNamingFileKeyAndLine) {
  TempDir dir;
  const auto file = dir / "bad.yaml";
  for (const std::string& body : {std::string("sensor: lidar\nrobots: many\n"),
                                  std::string("sensor: lidar\nrobots: [1, 2]\n"),
                                  std::string("sensor: lidar\nrobots: 0\n")}) {
    support::write_bytes(file, body);
    const support::CliRun run = run_cli("explore --config " + file.string());
    EXPECT_EQ(run.exit_code, 2) << body << run.output;
    EXPECT_THAT(run.output, HasSubstr(file.string() + ":2: key 'robots': ")) << body;
  }
}

TEST(CliConfig, AnInputIsNotASetting) {
  TempDir dir;
  const auto file = dir / "bad.yaml";
  support::write_bytes(file, "trajectory: t.txt\n");
  const support::CliRun run = run_cli("eval ate --trajectory a --reference b --config " +
                                      file.string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_THAT(run.output, HasSubstr(file.string() + ":1: unknown key 'trajectory' (an input"));
}

TEST(CliConfig, NotYamlIsAUsageErrorWithItsLine) {
  TempDir dir;
  const auto file = dir / "bad.yaml";
  support::write_bytes(file, "robots: 2\nstrategy: [nearest\n");
  const support::CliRun run = run_cli("explore --config " + file.string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_THAT(run.output, HasSubstr(file.string() + ":"));
}

}  // namespace
}  // namespace tessera
