// tessera fusion --pair end to end: report.json's `pair` object on the real TUM fr1/xyz pairs, and
// bad input (exit 3, one line naming the file, nothing written).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "cli_run.hpp"
#include "support/data.hpp"

namespace tessera {
namespace {

using support::run_cli;
using support::TempDir;
using ::testing::HasSubstr;

const std::filesystem::path kPairs = "rgbd/tum_fr1_xyz_pairs";

nlohmann::json read_report(const std::filesystem::path& out) {
  return nlohmann::json::parse(support::read_bytes(out / "report.json"));
}

std::filesystem::path copy_case(const TempDir& dir, const char* name) {
  const auto to = dir.path() / name;
  std::filesystem::copy(support::data_path(kPairs / name), to);
  return to;
}

TEST(CliFusion, PairReportHasTheEstimateAndItsErrorAgainstGroundTruth) {
  TESSERA_REQUIRE_DATA(support::data_path(kPairs / "case_1"));
  TempDir dir;
  const auto out = dir.path() / "out";
  const support::CliRun run =
      run_cli("fusion --pair " + support::data_path(kPairs / "case_1").string() +
              " --features sift --seed 3 --out " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_THAT(run.output, HasSubstr("accepted"));
  const nlohmann::json report = read_report(out);
  EXPECT_EQ(report["command"], "fusion");
  EXPECT_EQ(report["seed"], 3);
  EXPECT_EQ(report["options"]["features"], "sift");
  const nlohmann::json& pair = report["pair"];
  EXPECT_EQ(pair["accepted"], true);
  EXPECT_EQ(pair["reason"], "accepted");
  EXPECT_EQ(pair["method"], "3d-3d");
  EXPECT_GE(pair["inliers"].get<int>(), 100);
  EXPECT_GE(pair["matches"].get<int>(), pair["inliers"].get<int>());
  EXPECT_LT(pair["translation_error_m"].get<double>(), 0.01);
  EXPECT_LT(pair["rotation_error_deg"].get<double>(), 0.5);
  // The estimate itself: case_1 moves 2.16 cm (pairs_gt.txt).
  const auto t = pair["T_prev_curr"]["translation_m"];
  ASSERT_EQ(t.size(), 3u);
  EXPECT_NEAR(std::hypot(t[0].get<double>(), t[1].get<double>(), t[2].get<double>()), 0.0216, 0.01);
  EXPECT_EQ(pair["T_prev_curr"]["matrix_3x4"].size(), 3u);
}

TEST(CliFusion, PairWithoutGroundTruthHasNoErrorKeys) {
  TESSERA_REQUIRE_DATA(support::data_path(kPairs / "case_1"));
  TempDir dir;
  const auto folder = copy_case(dir, "case_1");
  std::filesystem::remove(folder / "pose_prev.txt");
  std::filesystem::remove(folder / "pose_curr.txt");
  const auto out = dir.path() / "out";
  const support::CliRun run =
      run_cli("fusion --quiet --pair " + folder.string() + " --out " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_EQ(run.output, "");
  const nlohmann::json pair = read_report(out)["pair"];
  EXPECT_EQ(pair["accepted"], true);
  EXPECT_FALSE(pair.contains("translation_error_m"));
  EXPECT_FALSE(pair.contains("rotation_error_deg"));
}

// case_2's current depth is a copy of another frame's: never accepted with a wrong transform.
TEST(CliFusion, WrongDepthIsSolvedWithoutItOrRejectedWithAReason) {
  TESSERA_REQUIRE_DATA(support::data_path(kPairs / "case_2"));
  TempDir dir;
  const auto out = dir.path() / "out";
  const support::CliRun run = run_cli(
      "fusion --pair " + support::data_path(kPairs / "case_2").string() + " --out " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const nlohmann::json pair = read_report(out)["pair"];
  if (pair["accepted"].get<bool>()) {
    EXPECT_EQ(pair["reason"], "accepted by PnP");
    EXPECT_LT(pair["translation_error_m"].get<double>(), 0.02);
  } else {
    EXPECT_NE(pair["reason"], "accepted");
    EXPECT_THAT(pair["reason_text"].get<std::string>(), HasSubstr("3D-3D rejected"));
  }
}

// A frame that fails the node checks (thesis 4.3.1): here the current colour image is a plain grey
// wall (a binary PGM, which the reader decodes too). The thesis' method refuses with the reason;
// by default the depth images, which still show the desk, solve it (issue 18 item 10).
TEST(CliFusion, FrameFailingTheNodeChecksIsSolvedFromDepthOrRejectedWithTheReason) {
  TESSERA_REQUIRE_DATA(support::data_path(kPairs / "case_1"));
  TempDir dir;
  const auto folder = copy_case(dir, "case_1");
  support::write_bytes(folder / "img_curr.png",
                       "P5\n640 480\n255\n" + std::string(640 * 480, static_cast<char>(200)));
  const auto thesis = dir.path() / "thesis";
  const support::CliRun refused = run_cli("fusion --pair " + folder.string() +
                                          " --pair-method features --out " + thesis.string());
  ASSERT_EQ(refused.exit_code, 0) << refused.output;
  EXPECT_THAT(refused.output, HasSubstr("rejected"));
  const nlohmann::json pair = read_report(thesis)["pair"];
  EXPECT_EQ(pair["accepted"], false);
  EXPECT_EQ(pair["reason"], "current frame: too few features");
  EXPECT_EQ(pair["method"], "none");
  EXPECT_EQ(pair["nodes"]["prev"]["check"], "ok");
  EXPECT_FALSE(pair.contains("translation_error_m"));
  EXPECT_FALSE(pair.contains("depth_icp"));

  const auto out = dir.path() / "out";
  const support::CliRun solved =
      run_cli("fusion --pair " + folder.string() + " --out " + out.string());
  ASSERT_EQ(solved.exit_code, 0) << solved.output;
  EXPECT_THAT(solved.output, HasSubstr("accepted"));
  const nlohmann::json report = read_report(out);
  EXPECT_EQ(report["options"]["pair_method"], "auto");
  const nlohmann::json& by_depth = report["pair"];
  EXPECT_EQ(by_depth["accepted"], true);
  EXPECT_EQ(by_depth["reason"], "accepted by depth ICP");
  EXPECT_EQ(by_depth["features_reason"], "current frame: too few features");
  EXPECT_EQ(by_depth["method"], "depth-icp");
  EXPECT_EQ(by_depth["depth_icp"]["accepted"], true);
  EXPECT_LT(by_depth["translation_error_m"].get<double>(), 0.02);
  EXPECT_LT(by_depth["rotation_error_deg"].get<double>(), 1.0);
}

TEST(CliFusion, UnknownPairMethodIsAUsageErrorAndWritesNothing) {
  TESSERA_REQUIRE_DATA(support::data_path(kPairs / "case_1"));
  TempDir dir;
  const auto out = dir.path() / "out";
  const support::CliRun run =
      run_cli("fusion --pair " + support::data_path(kPairs / "case_1").string() +
              " --pair-method icp --out " + out.string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_THAT(run.output, HasSubstr("unknown pair method 'icp'"));
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(CliFusion, UnknownFeatureTypeIsAnInputErrorAndWritesNothing) {
  TESSERA_REQUIRE_DATA(support::data_path(kPairs / "case_1"));
  TempDir dir;
  const auto out = dir.path() / "out";
  const support::CliRun run =
      run_cli("fusion --pair " + support::data_path(kPairs / "case_1").string() +
              " --features surf --out " + out.string());
  EXPECT_EQ(run.exit_code, 3) << run.output;
  EXPECT_THAT(run.output, HasSubstr("unknown feature type 'surf'"));
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(CliFusion, BadPairFolderIsAnInputErrorNamingTheFileAndWritesNothing) {
  TESSERA_REQUIRE_DATA(support::data_path(kPairs / "case_1"));
  struct Case {
    const char* remove;
    const char* write_name;
    const char* write_bytes;
    const char* expected;
  };
  const Case cases[] = {
      {"dep_prev.png", nullptr, nullptr, "dep_prev.png: no such file"},
      {nullptr, "dep_curr.png", "not a png", "dep_curr.png: cannot decode image"},
      {nullptr, "pose_curr.txt", "1 2 3\n", "pose_curr.txt:1: expected 7 numbers"},
  };
  for (const Case& c : cases) {
    TempDir dir;
    const auto folder = copy_case(dir, "case_1");
    if (c.remove != nullptr) std::filesystem::remove(folder / c.remove);
    if (c.write_name != nullptr) support::write_bytes(folder / c.write_name, c.write_bytes);
    const auto out = dir.path() / "out";
    const support::CliRun run =
        run_cli("fusion --pair " + folder.string() + " --out " + out.string());
    EXPECT_EQ(run.exit_code, 3) << run.output;
    EXPECT_THAT(run.output, HasSubstr(c.expected));
    EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 1) << run.output;
    EXPECT_FALSE(std::filesystem::exists(out)) << c.expected;
  }
}

TEST(CliFusion, NoInputIsAUsageError) {
  TempDir dir;
  const support::CliRun run = run_cli("fusion --out " + (dir.path() / "out").string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "out"));
}

// --- tessera fusion --world / --teach-and-repeat (simulated runs, mission/teach_and_repeat) ---

const std::filesystem::path kPhotos = "rgbd/rtabmap_loop_samples/images";

TEST(CliFusion, TeachAndRepeatInTheOfficeWritesTheRunTableAndPictures) {
  TESSERA_REQUIRE_DATA(support::data_path(kPhotos));
  TempDir dir;
  const auto out = dir.path() / "out";
  const support::CliRun run =
      run_cli("fusion --teach-and-repeat --builtin office --route-length-m 4 --seed 4 --textures " +
              support::data_path(kPhotos).string() + " --out " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_THAT(run.output, HasSubstr("goal cell reached"));
  const nlohmann::json report = read_report(out);
  EXPECT_EQ(report["options"]["mode"], "teach-and-repeat");
  EXPECT_EQ(report["options"]["features"], "orb");
  const nlohmann::json& t = report["teach_and_repeat"];
  ASSERT_EQ(t["runs"].size(), 1u);
  const nlohmann::json& r = t["runs"][0];
  EXPECT_EQ(r["reached_goal_cell"], true);
  EXPECT_LE(r["final_error_m"].get<double>(), 0.1);
  EXPECT_LE(r["path_ratio"].get<double>(), 1.15);
  EXPECT_GE(r["ate_ratio"].get<double>(), 5.0);
  EXPECT_EQ(r["search_successes"], r["search_trials"]);
  EXPECT_EQ(t["summary"]["reached_goal_cell"], 1);
  EXPECT_GT(r["matches_accepted"].get<int>(), 0);
  EXPECT_TRUE(r["match_rejections"].is_object());
  for (const char* name : {"hex_map_run1.svg", "hex_map_run1.png", "trajectory_run1.txt"}) {
    EXPECT_TRUE(std::filesystem::exists(out / name)) << name;
  }
  // The trajectory is TUM: "t x y z qx qy qz qw" per pose.
  const std::string trajectory = support::read_bytes(out / "trajectory_run1.txt");
  ASSERT_FALSE(trajectory.empty());
  std::istringstream lines(trajectory);
  std::string first;
  while (std::getline(lines, first) && first.rfind('#', 0) == 0) {
  }
  EXPECT_EQ(std::count(first.begin(), first.end(), ' '), 7) << first;
}

// --world maps one simulated run (start -> goal -> start) and scores it; --save-sequence writes
// the run as a TUM folder, and --sequence on that folder takes the same path through the system.
TEST(CliFusion, WorldRunIsScoredAndReplaysTheSameAsItsSavedSequence) {
  TESSERA_REQUIRE_DATA(support::data_path(kPhotos));
  TempDir dir;
  const auto out = dir.path() / "out";
  const auto seq = dir.path() / "seq";
  const support::CliRun run =
      run_cli("fusion --builtin office --route-length-m 3 --seed 2 --textures " +
              support::data_path(kPhotos).string() + " --save-sequence " + seq.string() +
              " --out " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const nlohmann::json world = read_report(out);
  EXPECT_EQ(world["options"]["mode"], "world");
  EXPECT_EQ(world["run"]["completed"], true);
  const nlohmann::json& f = world["fusion"];
  EXPECT_GT(f["image_nodes"].get<int>(), 3);
  EXPECT_GT(f["matches_accepted"].get<int>(), 0);
  const nlohmann::json& t = world["trajectory"];
  // Drift corrected: the loop back to the start closes on the stored nodes.
  EXPECT_LT(t["ate_rmse_m"].get<double>(), 0.05);
  EXPECT_LT(t["ate_rmse_m"].get<double>(), t["ate_odometry_rmse_m"].get<double>());
  for (const char* name : {"hex_map.svg", "hex_map.png", "trajectory.txt", "truth.txt"}) {
    EXPECT_TRUE(std::filesystem::exists(out / name)) << name;
  }
  for (const char* name : {"rgb.txt", "depth.txt", "groundtruth.txt", "odometry.txt", "neck.txt"}) {
    EXPECT_TRUE(std::filesystem::exists(seq / name)) << name;
  }

  const auto replay_out = dir.path() / "replay";
  const support::CliRun replay =
      run_cli("fusion --sequence " + seq.string() + " --seed 2 --out " + replay_out.string());
  ASSERT_EQ(replay.exit_code, 0) << replay.output;
  const nlohmann::json again = read_report(replay_out);
  EXPECT_TRUE(std::filesystem::exists(replay_out / "truth.txt"));  // from groundtruth.txt
  // Same frames, same odometry, depth rounded to 0.2 mm by the PNG: the same cells, and the same
  // image nodes but for a frame at the edge of a node check (a feature whose depth the rounding
  // moves across a limit).
  EXPECT_EQ(again["fusion"]["frames_in_sequence"], f["frames_in_sequence"]);
  EXPECT_EQ(again["fusion"]["cells"], f["cells"]);
  EXPECT_NEAR(again["fusion"]["image_nodes"].get<double>(), f["image_nodes"].get<double>(),
              std::max(1.0, 0.05 * f["image_nodes"].get<double>()));
  EXPECT_NEAR(again["trajectory"]["ate_rmse_m"].get<double>(), t["ate_rmse_m"].get<double>(),
              0.005);
}

TEST(CliFusion, SaveSequenceOntoAFileIsARuntimeErrorBeforeTheRun) {
  TESSERA_REQUIRE_DATA(support::data_path(kPhotos));
  TempDir dir;
  const auto in_the_way = dir.path() / "seq";
  support::write_bytes(in_the_way, "not a folder\n");
  const auto out = dir.path() / "out";
  const support::CliRun run =
      run_cli("fusion --builtin office --textures " + support::data_path(kPhotos).string() +
              " --save-sequence " + in_the_way.string() + " --out " + out.string());
  EXPECT_EQ(run.exit_code, 4) << run.output;
  EXPECT_THAT(run.output, HasSubstr("a file is in the way"));
  EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 1) << run.output;
  EXPECT_FALSE(std::filesystem::exists(out));
  EXPECT_EQ(support::read_bytes(in_the_way), "not a folder\n");
}

TEST(CliFusion, WorldInputErrorsExitThreeWithOneLineAndWriteNothing) {
  TESSERA_REQUIRE_DATA(support::data_path(kPhotos));
  TempDir dir;
  const std::string photos = " --textures " + support::data_path(kPhotos).string();
  struct Case {
    std::string args;
    const char* expected;
  };
  const Case cases[] = {
      {"--builtin office --features surf" + photos, "unknown feature type 'surf'"},
      {"--world " + (dir.path() / "missing.yaml").string() + photos, "missing.yaml"},
      {"--builtin office --textures " + (dir.path() / "no_photos").string(), "no_photos"},
      {"--teach-and-repeat --builtin office --start 1.0,1.0 --goal -4,-4" + photos, "route:"},
      // Twenty boxes do not fit 1.5 m from both ends of a 4 m route.
      {"--teach-and-repeat --builtin office --route-length-m 4 --obstacles 20" + photos,
       "obstacles: the route"},
  };
  for (const Case& c : cases) {
    const auto out = dir.path() / "out";
    const support::CliRun run = run_cli("fusion " + c.args + " --out " + out.string());
    EXPECT_EQ(run.exit_code, 3) << c.args << "\n" << run.output;
    EXPECT_THAT(run.output, HasSubstr(c.expected));
    EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 1) << run.output;
    EXPECT_FALSE(std::filesystem::exists(out)) << c.args;
  }
}

TEST(CliFusion, UnknownNavigationOrAvoidanceIsAUsageErrorAndWritesNothing) {
  TESSERA_REQUIRE_DATA(support::data_path(kPhotos));
  TempDir dir;
  const auto out = dir.path() / "out";
  for (const std::string bad : {"--navigation zigzag", "--avoidance sometimes"}) {
    const support::CliRun run =
        run_cli("fusion --teach-and-repeat --builtin office --obstacles 1 " + bad + " --textures " +
                support::data_path(kPhotos).string() + " --out " + out.string());
    EXPECT_EQ(run.exit_code, 2) << bad << "\n" << run.output;
    EXPECT_THAT(run.output, HasSubstr(bad.substr(0, bad.find(' '))));
    EXPECT_FALSE(std::filesystem::exists(out));
  }
}

TEST(CliFusion, StartWithoutGoalIsAUsageError) {
  TESSERA_REQUIRE_DATA(support::data_path(kPhotos));
  TempDir dir;
  const auto out = dir.path() / "out";
  const support::CliRun run =
      run_cli("fusion --builtin office --start 2,2 --textures " +
              support::data_path(kPhotos).string() + " --out " + out.string());
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_FALSE(std::filesystem::exists(out));
}

// --- tessera fusion --sequence: a TUM folder made of the real fr1/xyz pair case_1 -------------

/// A two-frame TUM sequence from case_1 (fr1 intrinsics), with wheel odometry that moves the robot
/// 0.3 m north between the frames, so that the second frame falls in a new cell's firing field.
std::filesystem::path pair_sequence(const TempDir& dir, bool with_odometry) {
  const auto folder = dir.path() / "seq";
  std::filesystem::create_directories(folder);
  for (const char* f : {"img_prev.png", "img_curr.png", "dep_prev.png", "dep_curr.png"}) {
    std::filesystem::copy(support::data_path(kPairs / "case_1" / f), folder / f);
  }
  support::write_bytes(folder / "rgb.txt", "# colour\n1.000 img_prev.png\n2.000 img_curr.png\n");
  support::write_bytes(folder / "depth.txt", "1.001 dep_prev.png\n2.001 dep_curr.png\n");
  support::write_bytes(folder / "intrinsics.txt", "517.3 516.5 318.6 255.3\n");
  if (with_odometry) {
    support::write_bytes(folder / "odometry.txt", "1.000 0 0 0 0 0 0 1\n2.000 0 0.3 0 0 0 0 1\n");
  }
  return folder;
}

TEST(CliFusion, SequenceMapsAlongOdometryAndMatchesTheSecondFrame) {
  TESSERA_REQUIRE_DATA(support::data_path(kPairs / "case_1"));
  TempDir dir;
  const auto folder = pair_sequence(dir, true);
  const auto out = dir.path() / "out";
  const support::CliRun run =
      run_cli("fusion --sequence " + folder.string() + " --out " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const nlohmann::json report = read_report(out);
  EXPECT_EQ(report["options"]["mode"], "sequence");
  const nlohmann::json& f = report["fusion"];
  EXPECT_EQ(f["frames_in_sequence"], 2);
  EXPECT_EQ(f["frames_loaded"], 2);
  EXPECT_EQ(f["image_nodes"], 2);
  EXPECT_GE(f["cells"].get<int>(), 2);
  EXPECT_EQ(f["matches_accepted"], 1);
  for (const char* name : {"hex_map.svg", "hex_map.png", "trajectory.txt"}) {
    EXPECT_TRUE(std::filesystem::exists(out / name)) << name;
  }
  EXPECT_FALSE(std::filesystem::exists(out / "truth.txt"));  // no groundtruth.txt in the folder
}

TEST(CliFusion, SequenceInputErrorsExitThreeWithOneLineAndWriteNothing) {
  TESSERA_REQUIRE_DATA(support::data_path(kPairs / "case_1"));
  struct Case {
    bool odometry;
    const char* remove;
    const char* write_name;
    const char* write_bytes;
    const char* expected;
    const char* features = "orb";
    const char* copy_over = nullptr;  // a shared floor plan (400 x 300) copied over img_prev.png
  };
  const Case cases[] = {
      {true, nullptr, nullptr, nullptr, "unknown feature type 'surf'", "surf"},
      {true, nullptr, nullptr, nullptr, "img_prev.png", "orb",
       "maps/stage_bitmaps/simple_rooms.png"},
      {false, nullptr, nullptr, nullptr, "odometry.txt"},
      {true, "depth.txt", nullptr, nullptr, "depth.txt"},
      {true, nullptr, "depth.txt", "5.0 dep_prev.png\n6.0 dep_curr.png\n", "0.02"},
      {true, nullptr, "dep_prev.png", "P5\n640 480\n255\n", "dep_prev.png"},
  };
  for (const Case& c : cases) {
    TempDir dir;
    const auto folder = pair_sequence(dir, c.odometry);
    if (c.remove != nullptr) std::filesystem::remove(folder / c.remove);
    if (c.write_name != nullptr) {
      std::string bytes = c.write_bytes;
      if (std::string(c.write_name) == "dep_prev.png") bytes += std::string(640 * 480, '\x40');
      support::write_bytes(folder / c.write_name, bytes);
    }
    if (c.copy_over != nullptr) {
      std::filesystem::copy_file(support::data_path(c.copy_over), folder / "img_prev.png",
                                 std::filesystem::copy_options::overwrite_existing);
    }
    const auto out = dir.path() / "out";
    const support::CliRun run = run_cli("fusion --sequence " + folder.string() + " --features " +
                                        c.features + " --out " + out.string());
    EXPECT_EQ(run.exit_code, 3) << c.expected << "\n" << run.output;
    EXPECT_THAT(run.output, HasSubstr(c.expected));
    EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 1) << run.output;
    EXPECT_FALSE(std::filesystem::exists(out)) << c.expected;
  }
}

}  // namespace
}  // namespace tessera
