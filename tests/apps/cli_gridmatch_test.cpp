// tessera gridmatch (issue 18, item 6): the lecture's numerical SLAM example as a command a student
// runs. The default is the lecture's situation; the S table, the pictures and report.json say the
// robot is in the intended cell turned 15 degrees clockwise, as the lecture concludes. Bad poses
// and a world without a pose are usage errors that write nothing.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "cli_run.hpp"
#include "support/temp_dir.hpp"

namespace tessera {
namespace {

using support::read_bytes;
using support::run_cli;
using support::TempDir;
using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::StartsWith;

TEST(CliGridmatch, TheLecturesExampleChoosesTheIntendedCellTurned15DegreesClockwise) {
  const TempDir dir;
  const auto r = run_cli("gridmatch --out " + dir.path().string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("chosen: intended position, 15 deg CW (S = 34"));
  // The table in the lecture's layout, ours beside the lecture's: the same winner.
  const std::string md = read_bytes(dir.path() / "similarity.md");
  EXPECT_THAT(md, HasSubstr("| Intended position | 28 (lecture 22) | **34** (lecture 32) |"));
  const nlohmann::json report = nlohmann::json::parse(read_bytes(dir.path() / "report.json"));
  EXPECT_EQ(report["command"], "gridmatch");
  const nlohmann::json& g = report["gridmatch"];
  EXPECT_EQ(g["chosen"], "intended position, 15 deg CW");
  EXPECT_EQ(g["candidates"].size(), 15U);
  EXPECT_EQ(g["margin"], 5);
  EXPECT_LT(g["error_m"].get<double>(), 1e-9);
  EXPECT_EQ(g["lecture_table"][0][1], 32);
  // A picture per test pose with its S, and the whole step on one sheet.
  int pictures = 0;
  for (const auto& f : std::filesystem::directory_iterator(dir.path() / "candidates")) {
    EXPECT_THAT(read_bytes(f.path()), StartsWith("<svg"));
    ++pictures;
  }
  EXPECT_EQ(pictures, 15);
  EXPECT_THAT(read_bytes(dir.path() / "candidates" / "01_dx+0_dy+0_turn-1.svg"),
              HasSubstr("intended position, 15 deg CW: S = 34 (best)"));
  const std::string sheet = read_bytes(dir.path() / "gridmatch.svg");
  EXPECT_THAT(sheet, StartsWith("<svg"));
  EXPECT_THAT(sheet, HasSubstr(">S = 34<"));
}

TEST(CliGridmatch, AnotherPoseErrorIsCorrectedToo) {
  // The robot slipped sideways instead: it is one cell to the right of where odometry says.
  const TempDir dir;
  const auto r = run_cli("gridmatch --actual 1.35,1.35,1.5707963 --out " + dir.path().string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("chosen: right one cell"));
  const nlohmann::json report = nlohmann::json::parse(read_bytes(dir.path() / "report.json"));
  EXPECT_LT(report["gridmatch"]["error_m"].get<double>(), 1e-6);
  EXPECT_FALSE(report["gridmatch"].contains("lecture_table"));
  EXPECT_THAT(read_bytes(dir.path() / "similarity.md"), Not(HasSubstr("lecture")));
}

TEST(CliGridmatch, AFloorPlanIsResampledToRobotSizedCells) {
  // A 6 x 4.5 m room drawn at 0.1 m (a map_server file), matched in 0.3 m cells.
  const TempDir dir;
  std::string pgm = "P5\n60 45\n255\n";
  for (int y = 0; y < 45; ++y) {
    for (int x = 0; x < 60; ++x) {
      const bool wall = x < 3 || y < 3 || y >= 42 || (x >= 3 && x < 6 && y >= 15 && y < 21);
      pgm += static_cast<char>(wall ? 0 : 254);
    }
  }
  support::write_bytes(dir.path() / "room.pgm", pgm);
  support::write_bytes(dir.path() / "room.yaml",
                       "image: room.pgm\nresolution: 0.1\norigin: [0.0, 0.0, 0.0]\nnegate: 0\n"
                       "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
  const auto r = run_cli("gridmatch --world " + (dir.path() / "room.yaml").string() +
                         " --before 1.05,3.45,1.5707963 --out " + (dir.path() / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("chosen: intended position, 15 deg CW"));
  const nlohmann::json report =
      nlohmann::json::parse(read_bytes(dir.path() / "out" / "report.json"));
  EXPECT_DOUBLE_EQ(report["options"]["resolution_m"].get<double>(), 0.3);
}

TEST(CliGridmatch, BadPosesAndWorldsWithoutAPoseAreUsageErrors) {
  const TempDir dir;
  const auto out = (dir.path() / "out").string();
  const auto in_wall = run_cli("gridmatch --actual 0.15,1.05,0 --out " + out);
  EXPECT_EQ(in_wall.exit_code, 2);
  EXPECT_THAT(in_wall.output, HasSubstr("--actual 0.15,1.05 is not in free space"));
  const auto no_pose = run_cli("gridmatch --builtin office --out " + out);
  EXPECT_EQ(no_pose.exit_code, 2);
  EXPECT_THAT(no_pose.output, HasSubstr("--before is needed"));
  const auto malformed = run_cli("gridmatch --before 1,x --out " + out);
  EXPECT_EQ(malformed.exit_code, 2);
  EXPECT_THAT(malformed.output, HasSubstr("--before"));
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace tessera
