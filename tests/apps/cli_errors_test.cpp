// Bad input never crashes and never loses data: one clear line naming the file and the problem,
// exit code 3 (2 for usage), and no output left behind.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <string>

#include "cli_run.hpp"

namespace tessera {
namespace {

using support::count_lines;
using support::run_cli;
using support::TempDir;
using ::testing::HasSubstr;

std::string pgm(int width, int height, const std::string& pixels) {
  return "P5\n" + std::to_string(width) + " " + std::to_string(height) + "\n255\n" + pixels;
}

/// Runs explore on `world` into an output folder that must not appear; checks the message.
void expect_input_error(const TempDir& dir, const std::string& world_args,
                        const std::string& file_mentioned, const std::string& problem) {
  const auto out = dir.path() / "out";
  const support::CliRun run = run_cli("explore " + world_args + " --quiet --out " + out.string());
  EXPECT_EQ(run.exit_code, 3) << run.output;
  EXPECT_EQ(count_lines(run.output), 1) << run.output;
  EXPECT_THAT(run.output, HasSubstr(file_mentioned));
  EXPECT_THAT(run.output, HasSubstr(problem));
  EXPECT_FALSE(std::filesystem::exists(out)) << "output folder left behind";
}

TEST(CliErrors, MissingWorldFileIsAnInputError) {
  TempDir dir;
  const auto world = dir.path() / "nope.yaml";
  expect_input_error(dir, "--world " + world.string(), "nope.yaml", "no such file");
}

TEST(CliErrors, YamlWithNegativeResolutionIsRejected) {
  TempDir dir;
  support::write_bytes(dir / "m.pgm", pgm(4, 4, std::string(16, '\xfe')));
  support::write_bytes(dir / "m.yaml", "image: m.pgm\nresolution: -0.05\norigin: [0, 0, 0]\n");
  expect_input_error(dir, "--world " + (dir.path() / "m.yaml").string(), "m.yaml", "resolution");
}

TEST(CliErrors, YamlWithoutImageIsRejected) {
  TempDir dir;
  support::write_bytes(dir / "m.yaml", "resolution: 0.05\norigin: [0, 0, 0]\n");
  expect_input_error(dir, "--world " + (dir.path() / "m.yaml").string(), "m.yaml", "image");
}

TEST(CliErrors, TruncatedPgmIsRejected) {
  TempDir dir;
  support::write_bytes(dir / "m.pgm", pgm(10, 10, std::string(37, '\xfe')));
  support::write_bytes(dir / "m.yaml", "image: m.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n");
  expect_input_error(dir, "--world " + (dir.path() / "m.yaml").string(), "m.pgm", "100");
}

TEST(CliErrors, FileThatIsNotAPgmIsRejected) {
  TempDir dir;
  support::write_bytes(dir / "m.pgm", "hello, I am text\n");
  support::write_bytes(dir / "m.yaml", "image: m.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n");
  expect_input_error(dir, "--world " + (dir.path() / "m.yaml").string(), "m.pgm", "PGM");
}

TEST(CliErrors, MovingAiFileWithWrongSizeHeaderIsRejected) {
  TempDir dir;
  support::write_bytes(dir / "m.map", "type octile\nheight 4\nwidth 3\nmap\n...\n...\n...\n");
  expect_input_error(dir, "--world " + (dir.path() / "m.map").string(), "m.map", "height");
}

TEST(CliErrors, StartInsideAnObstacleIsRejected) {
  TempDir dir;
  // The built-in office has its outer wall at x < 0.2 m.
  const support::CliRun run =
      run_cli("explore --start 0.05,5 --quiet --out " + (dir.path() / "out").string());
  EXPECT_EQ(run.exit_code, 3) << run.output;
  EXPECT_EQ(count_lines(run.output), 1) << run.output;
  EXPECT_THAT(run.output, HasSubstr("inside an obstacle"));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "out"));
}

TEST(CliErrors, StartOutsideTheMapIsRejected) {
  TempDir dir;
  const support::CliRun run =
      run_cli("explore --start 100,5 --quiet --out " + (dir.path() / "out").string());
  EXPECT_EQ(run.exit_code, 3) << run.output;
  EXPECT_THAT(run.output, HasSubstr("outside the map"));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "out"));
}

TEST(CliErrors, WorldWithNoFreeCellIsRejected) {
  TempDir dir;
  support::write_bytes(dir / "m.map", "type octile\nheight 2\nwidth 3\nmap\n@@@\n@T@\n");
  expect_input_error(dir, "--world " + (dir.path() / "m.map").string(), "m.map", "no free cell");
}

TEST(CliErrors, UnknownOptionIsAUsageError) {
  const support::CliRun run = run_cli("explore --no-such-option");
  EXPECT_EQ(run.exit_code, 2) << run.output;
}

TEST(CliErrors, BadStrategyIsAUsageError) {
  const support::CliRun run = run_cli("explore --strategy random");
  EXPECT_EQ(run.exit_code, 2) << run.output;
}

TEST(CliErrors, EverySubcommandHasHelp) {
  for (const char* sub : {"explore", "render", "info", "convert"}) {
    const support::CliRun run = run_cli(std::string(sub) + " --help");
    EXPECT_EQ(run.exit_code, 0) << sub;
    EXPECT_THAT(run.output, HasSubstr("Usage")) << sub;
  }
}

TEST(CliErrors, InfoOnAMissingFileIsAnInputError) {
  const support::CliRun run = run_cli("info /nonexistent/tessera/map.yaml");
  EXPECT_EQ(run.exit_code, 3) << run.output;
  EXPECT_THAT(run.output, HasSubstr("map.yaml"));
}

}  // namespace
TEST(CliErrors, MalformedCropIsAUsageError) {
  TempDir dir;
  const auto out = dir.path() / "out";
  const support::CliRun run =
      run_cli("bob --builtin labyrinth --crop 1,2,3 --quiet --out " + out.string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_THAT(run.output, HasSubstr("--crop expects X0,Y0,X1,Y1"));
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(CliErrors, CropWithoutFreeSpaceIsAnInputError) {
  TempDir dir;
  support::write_bytes(dir / "m.pgm", pgm(4, 4, std::string(16, '\xfe')));
  support::write_bytes(dir / "m.yaml", "image: m.pgm\nresolution: 0.5\norigin: [0, 0, 0]\n");
  expect_input_error(dir, "--world " + (dir.path() / "m.yaml").string() + " --crop 5,5,6,6",
                     "m.yaml", "no free cell of the world inside it");
}

// Found by mutating real inputs: a number that overflows a double made nlohmann::json throw
// out_of_range, which escaped the reader and aborted the program (exit 134).
TEST(CliErrors, InfoOnHouseExpoWithAnOverflowingNumberIsOneInputErrorLine) {
  TempDir dir;
  support::write_bytes(dir / "plan.json",
                       "{\"id\": \"x\",\n \"verts\": [[0, 0], [-1e3085, 1], [1, 1]]}\n");
  const support::CliRun run = run_cli("info " + (dir.path() / "plan.json").string());
  EXPECT_EQ(run.exit_code, 3) << run.output;
  EXPECT_EQ(count_lines(run.output), 1) << run.output;
  EXPECT_THAT(run.output, HasSubstr("plan.json:2: JSON number out of range: '-1e3085'"));
}

}  // namespace tessera
