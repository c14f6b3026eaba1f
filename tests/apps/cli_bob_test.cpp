// tessera bob end to end: outputs and report fields on a small world, and bad input (exit 3, one
// line, nothing written).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_run.hpp"

namespace tessera {
namespace {

using support::count_lines;
using support::read_bytes;
using support::run_cli;
using support::TempDir;
using ::testing::HasSubstr;

/// A map_server map at 0.22 m per cell; rows top first, '#' solid.
std::filesystem::path write_world(const TempDir& dir, const std::vector<std::string>& rows,
                                  const std::string& resolution = "0.22") {
  std::string pixels;
  for (const std::string& r : rows) {
    for (const char ch : r) pixels.push_back(ch == '#' ? '\0' : '\xfe');
  }
  support::write_bytes(dir / "w.pgm", "P5\n" + std::to_string(rows.front().size()) + " " +
                                          std::to_string(rows.size()) + "\n255\n" + pixels);
  support::write_bytes(dir / "w.yaml", "image: w.pgm\nresolution: " + resolution +
                                           "\norigin: [0, 0, 0]\nnegate: 0\n"
                                           "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
  return dir.path() / "w.yaml";
}

std::string fmt_step(int n) {
  std::string s = std::to_string(n);
  return std::string(5 - s.size(), '0') + s;
}

const std::vector<std::string> kRoom = {"############", "#..........#", "#..........#",
                                        "#...##.....#", "#...##.....#", "#..........#",
                                        "#.....#....#", "#..........#", "############"};

TEST(CliBob, WritesMonitorMapAndReportForBothVariants) {
  TempDir dir;
  const auto world = write_world(dir, kRoom);
  for (const std::string variant : {"trail", "map-aware"}) {
    const auto out = dir.path() / ("out-" + variant);
    const support::CliRun run = run_cli("bob --world " + world.string() + " --variant " + variant +
                                        " --noise off --seed 3 --quiet --out " + out.string());
    ASSERT_EQ(run.exit_code, 0) << run.output;
    for (const char* f : {"monitor.png", "map.bob", "report.json"}) {
      EXPECT_TRUE(std::filesystem::exists(out / f)) << f;
    }
    const nlohmann::json report = nlohmann::json::parse(read_bytes(out / "report.json"));
    EXPECT_EQ(report["command"], "bob");
    EXPECT_EQ(report["seed"], 3);
    EXPECT_EQ(report["options"]["variant"], variant);
    EXPECT_EQ(report["world"]["width_cells"], 12);
    EXPECT_EQ(report["map_accuracy"]["cells"], 108);
    EXPECT_EQ(report["map_accuracy"]["empty_as_occupied"], 0);
    EXPECT_EQ(report["map_accuracy"]["occupied_as_empty"], 0);
    EXPECT_EQ(report["map_accuracy"]["success_rate"], 1.0);
    EXPECT_EQ(report["map_accuracy"]["free_reachable_c"], 65);
    EXPECT_GT(report["map_accuracy"]["path_cells"].get<int>(), 0);
    // map.bob: "BOB1", 12, 9, 220 mm, then 9 rows of 2 bytes; the bottom row is all wall.
    const std::string bob = read_bytes(out / "map.bob");
    ASSERT_EQ(bob.size(), 10u + 9u * 2u);
    EXPECT_EQ(bob.substr(0, 4), "BOB1");
    EXPECT_EQ(bob[4], 12);
    EXPECT_EQ(bob[6], 9);
    EXPECT_EQ(static_cast<unsigned char>(bob[8]), 220);
    EXPECT_EQ(static_cast<unsigned char>(bob[10]), 0xff);
    EXPECT_EQ(static_cast<unsigned char>(bob[11]), 0x0f);
  }
}

TEST(CliBob, ResenseOffIsRecordedInTheReportAndABadValueIsAUsageError) {
  TempDir dir;
  const auto world = write_world(dir, kRoom);
  const auto out = dir.path() / "out";
  const support::CliRun run = run_cli("bob --world " + world.string() +
                                      " --resense off --seed 3 --quiet --out " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const nlohmann::json report = nlohmann::json::parse(read_bytes(out / "report.json"));
  EXPECT_EQ(report["options"]["resense"], "off");
  EXPECT_EQ(report["map_accuracy"]["resensed_cells"], 0);
  const support::CliRun bad = run_cli("bob --world " + world.string() +
                                      " --resense maybe --quiet --out " + out.string() + "2");
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
}

TEST(CliBob, MapBobOpensInInfoAndRenderAndATruncatedOneIsAnInputError) {
  TempDir dir;
  const auto world = write_world(dir, kRoom);
  const auto out = dir.path() / "out";
  ASSERT_EQ(run_cli("bob --world " + world.string() + " --noise off --quiet --out " + out.string())
                .exit_code,
            0);
  const support::CliRun info = run_cli("info --json " + (out / "map.bob").string());
  ASSERT_EQ(info.exit_code, 0) << info.output;
  const nlohmann::json j = nlohmann::json::parse(info.output);
  EXPECT_EQ(j["format"], "bob");
  EXPECT_EQ(j["width_cells"], 12);
  EXPECT_EQ(j["height_cells"], 9);
  EXPECT_DOUBLE_EQ(j["resolution_m"].get<double>(), 0.22);
  // kRoom with noise off: mapped exactly, so the free cells are the room's 65.
  EXPECT_EQ(j["free_cells"], 65);
  const auto png = dir.path() / "map.png";
  const support::CliRun render =
      run_cli("render " + (out / "map.bob").string() + " --out " + png.string());
  ASSERT_EQ(render.exit_code, 0) << render.output;
  EXPECT_TRUE(std::filesystem::exists(png));
  const std::string bytes = read_bytes(out / "map.bob");
  support::write_bytes(dir / "short.bob", bytes.substr(0, bytes.size() - 1));
  const support::CliRun bad = run_cli("info " + (dir.path() / "short.bob").string());
  EXPECT_EQ(bad.exit_code, 3) << bad.output;
  EXPECT_THAT(bad.output, HasSubstr("short.bob"));
}

TEST(CliBob, MonitorDirHoldsOnePictureForTheStartAndOneForEveryMove) {
  TempDir dir;
  const auto world = write_world(dir, kRoom);
  const auto out = dir.path() / "out";
  const auto monitor = dir.path() / "monitor";
  const support::CliRun run = run_cli("bob --world " + world.string() + " --noise off --monitor-dir " +
                                      monitor.string() + " --quiet --out " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const nlohmann::json report = nlohmann::json::parse(read_bytes(out / "report.json"));
  const int moves = report["map_accuracy"]["path_cells"].get<int>();
  int frames = 0;
  for (const auto& e : std::filesystem::directory_iterator(monitor)) {
    EXPECT_EQ(e.path().extension(), ".png");
    ++frames;
  }
  EXPECT_EQ(frames, moves + 1);  // noise off: no bumps
  EXPECT_TRUE(std::filesystem::exists(monitor / "step_00000.png"));
  EXPECT_EQ(read_bytes(monitor / ("step_" + fmt_step(moves) + ".png")),
            read_bytes(out / "monitor.png"));
}

void expect_input_error(const TempDir& dir, const std::string& args, const std::string& problem) {
  const auto out = dir.path() / "out";
  const support::CliRun run = run_cli("bob " + args + " --quiet --out " + out.string());
  EXPECT_EQ(run.exit_code, 3) << run.output;
  EXPECT_EQ(count_lines(run.output), 1) << run.output;
  EXPECT_THAT(run.output, HasSubstr(problem));
  EXPECT_FALSE(std::filesystem::exists(out)) << "output folder left behind";
}

TEST(CliBob, UnreadableWorldIsAnInputError) {
  TempDir dir;
  expect_input_error(dir, "--world " + (dir.path() / "nope.yaml").string(), "nope.yaml");
}

TEST(CliBob, CellSmallerThanTheRobotIsAnInputError) {
  TempDir dir;
  const auto world = write_world(dir, kRoom);
  expect_input_error(dir, "--world " + world.string() + " --cell 0.1",
                     "w.yaml: cell 0.1 m does not fit the robot (0.16 x 0.15 m)");
}

TEST(CliBob, StartFacingAWallIsAnInputError) {
  TempDir dir;
  const auto world = write_world(dir, kRoom);
  // 1.43,0.33 m is the centre of cell (6, 1) at 0.22 m.
  expect_input_error(dir, "--world " + world.string() + " --start 1.43,0.33",
                     "w.yaml: start (6, 1): the cell in front must be free (BOBMapping 3.4)");
}

TEST(CliBob, GridLargerThanTheBuffersIsAnInputError) {
  TempDir dir;
  std::vector<std::string> rows(70, std::string(70, '.'));
  const auto world = write_world(dir, rows);
  expect_input_error(dir, "--world " + world.string(),
                     "w.yaml: world is 70 x 70 = 4900 cells, more than the robot's buffers hold "
                     "(4096)");
}

}  // namespace
}  // namespace tessera
