// The thesis' two-stage experiment (Table 5.1) in the simulator: a short teach-and-repeat run in
// the built-in office with real photographs as posters meets the bars; routes and
// start/goal choice; bad options.
#include "tessera/mission/teach_and_repeat.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "support/data.hpp"
#include "tessera/render/wall_textures.hpp"
#include "tessera/sim/builtin_world.hpp"
#include "tessera/sim/poster.hpp"
#include "tessera/sim/wall_faces.hpp"

namespace tessera {
namespace {

const std::filesystem::path kPhotos = "rgbd/rtabmap_loop_samples/images";

/// The office with posters from RTAB-Map's loop-closure photos on most walls (seeded).
Result<RgbdCamera> office_camera(std::uint64_t poster_seed) {
  const World world = builtin_world("office", 0.05);
  const Result<std::vector<std::filesystem::path>> files =
      list_texture_images(support::data_path(kPhotos));
  if (!files) return files.error();
  const std::vector<std::filesystem::path> some(
      files->begin(), files->begin() + std::min<std::ptrdiff_t>(40, std::ssize(*files)));
  Result<std::vector<WallTexture>> textures = read_wall_textures(some);
  if (!textures) return textures.error();
  const std::vector<WallFace> faces = find_wall_faces(world).faces;
  PosterPlacementOptions placement;
  placement.probability = 0.9;
  std::vector<Poster> posters = place_poster_layers(faces, *textures, placement, poster_seed, 3);
  return RgbdCamera::create(world, RgbdCameraOptions{}, std::move(*textures), std::move(posters));
}

/// A start and goal about 7 m apart along a route keeping 0.3 m (seeded).
Result<StartAndGoal> seven_metre_route(const RgbdCamera& camera) {
  Rng rng(11);
  return choose_start_and_goal(camera.world(), 0.3, /*route_length_m=*/7.0, rng);
}

TEST(TeachAndRepeat, ShortRunInTheOfficeMeetsTheBars) {
  TESSERA_REQUIRE_DATA(support::data_path(kPhotos));
  const Result<RgbdCamera> camera = office_camera(7);
  ASSERT_TRUE(camera) << camera.error().message;
  const Result<StartAndGoal> sg = seven_metre_route(*camera);
  ASSERT_TRUE(sg) << sg.error().message;
  TeachAndRepeatOptions options;
  options.capture_neck_angles_rad = {-1.0, 0.0,
                                     1.0};  // three views per capture keep the test short
  // Stepped stage by stage, as a caller that watches the mission would.
  Result<TeachAndRepeat> mission =
      TeachAndRepeat::create(*camera, options, sg->start, sg->goal_m, /*seed=*/3);
  ASSERT_TRUE(mission) << mission.error().message;
  std::vector<TeachAndRepeatStage> stages;
  while (!mission->done()) {
    stages.push_back(mission->stage());
    const Status s = mission->step();
    ASSERT_TRUE(s) << s.error().message;
    if (mission->stage() == TeachAndRepeatStage::kConfirmStartNode) {
      EXPECT_GT(mission->slam().image_nodes().size(), 0u);
    }
  }
  EXPECT_EQ(stages, (std::vector<TeachAndRepeatStage>{
                        TeachAndRepeatStage::kTeachToGoal, TeachAndRepeatStage::kCaptureGoalNode,
                        TeachAndRepeatStage::kTeachBack, TeachAndRepeatStage::kConfirmStartNode,
                        TeachAndRepeatStage::kNavigate, TeachAndRepeatStage::kFindGoalNode}));
  const std::optional<TeachAndRepeatResult> r = std::move(*mission).take_result();
  const TeachAndRepeatRun& run = r->run;
  std::cout << "route " << run.taught_route_length_m << " m, cells " << run.cells << ", nodes "
            << run.image_nodes << ", matches " << run.slam.matches_accepted << "/"
            << run.slam.matches_tried << ", final error " << run.final_error_m << " m, ratio "
            << run.path_ratio << ", ATE " << run.ate_corrected_m << " vs " << run.ate_odometry_m
            << ", search " << run.search_successes << "/" << run.search_trials << ", time "
            << run.duration_s << " s simulated, wrong matches " << run.wrong_matches << " (max "
            << run.max_match_error_m << " m)\n";
  EXPECT_TRUE(run.reached_goal_cell);
  EXPECT_LE(run.final_error_m, 0.1);
  EXPECT_LE(run.path_ratio, 1.15);
  EXPECT_GT(run.path_ratio, 0.5);
  EXPECT_LE(5.0 * run.ate_corrected_m, run.ate_odometry_m);
  EXPECT_DOUBLE_EQ(run.ate_ratio, run.ate_odometry_m / run.ate_corrected_m);
  EXPECT_FALSE(run.taught_path_m.empty());
  EXPECT_FALSE(run.repeated_path_m.empty());
  EXPECT_EQ(run.search_successes, run.search_trials);
  EXPECT_GE(run.search_trials, 2);
  EXPECT_GT(run.slam.matches_accepted, 0);
  EXPECT_GT(run.image_nodes, 5u);
  EXPECT_EQ(run.corrected_trajectory.size(), r->slam.graph_nodes());
  // Every accepted match is scored against the true path: nearly all are right (wrong: over
  // 0.2 m or 0.1 rad off), and none far off, since the gate refuses what moves the graph > 1 m.
  EXPECT_GT(run.max_match_error_m, 0.0);
  EXPECT_LT(run.max_match_error_m, 1.5);
  EXPECT_LE(50 * run.wrong_matches, run.slam.matches_accepted);
}

// The obstacle course (thesis chapter 5, issue 18 item 9): boxes on the taught route after the
// teach stage, the P3DX's sonars and bumpers, the reactive avoidance in the navigation loop.
struct CourseRun {
  std::optional<TeachAndRepeatRun> run;
  std::string error;
};
CourseRun run_course(const RgbdCamera& camera, const StartAndGoal& sg, bool avoid,
                     RepeatNavigation navigation, double max_drive_s) {
  TeachAndRepeatOptions options;
  options.capture_neck_angles_rad = {-1.0, 0.0, 1.0};
  options.navigation = navigation;
  options.max_drive_s = max_drive_s;
  ObstacleCourseOptions course;
  course.avoid = avoid;  // blind: neither the avoidance nor the detours
  course.detours = avoid;
  options.obstacle_course = course;
  Result<TeachAndRepeatResult> r =
      run_teach_and_repeat(camera, options, sg.start, sg.goal_m, /*seed=*/3);
  if (!r) return {std::nullopt, r.error().message};
  return {r->run, ""};
}

// Distance from p to the box [lo, hi] (0 inside).
double distance_to_box(Vec2 p, const std::pair<Vec2, Vec2>& box) {
  const double dx = std::max({box.first.x - p.x, 0.0, p.x - box.second.x});
  const double dy = std::max({box.first.y - p.y, 0.0, p.y - box.second.y});
  return std::hypot(dx, dy);
}

TEST(TeachAndRepeat, ObstacleCourseTheRobotGoesRoundTheBoxesAndStillReachesTheGoal) {
  TESSERA_REQUIRE_DATA(support::data_path(kPhotos));
  const Result<RgbdCamera> camera = office_camera(7);
  ASSERT_TRUE(camera) << camera.error().message;
  const Result<StartAndGoal> sg = seven_metre_route(*camera);
  ASSERT_TRUE(sg) << sg.error().message;

  {
    const CourseRun c =
        run_course(*camera, *sg, /*avoid=*/true, RepeatNavigation::kPolyline, 600.0);
    ASSERT_TRUE(c.run) << c.error;
    const TeachAndRepeatRun& run = *c.run;
    std::cout << "obstacle course: reversals " << run.heading_reversals << ", avoidance updates "
              << run.avoidance_updates << ", detours " << run.detours << ", bumper hits "
              << run.bumper_hits << ", blocked " << run.blocked_steps << ", path "
              << run.navigation_path_m << " m in " << run.navigation_time_s << " s, final error "
              << run.final_error_m << " m\n";
    ASSERT_EQ(run.obstacles_m.size(), 2u);
    EXPECT_TRUE(run.reached_goal_cell);
    EXPECT_LE(run.final_error_m, 0.1);
    // The boxes were in the way: the robot planned routes round them from its sonar memory.
    EXPECT_GT(run.detours, 0);
    // It went round the boxes: the repeated path (estimates, a few cm off the truth) keeps about
    // the body's radius from them.
    const double radius = ObstacleCourseOptions{}.body.body_radius_m;
    double closest = 1e9;
    for (const Vec2 p : run.repeated_path_m) {
      for (const auto& box : run.obstacles_m) closest = std::min(closest, distance_to_box(p, box));
    }
    std::cout << "closest approach to a box " << closest << " m\n";
    EXPECT_GE(closest, radius - 0.05);
  }

  // Without the avoidance and the detours the first box stops the robot: the drive runs out of
  // time.
  const CourseRun blind = run_course(*camera, *sg, /*avoid=*/false, RepeatNavigation::kPolyline,
                                     /*max_drive_s=*/120.0);
  EXPECT_FALSE(blind.run);
  EXPECT_NE(blind.error.find("navigation exceeded max_drive_s"), std::string::npos) << blind.error;
}

TEST(TeachAndRepeat, InvalidOptionsNameTheField) {
  TeachAndRepeatOptions o;
  EXPECT_FALSE(validate(o));
  o.neck_pan_rad = 2.0;
  ASSERT_TRUE(validate(o));
  EXPECT_NE(validate(o)->find("neck_pan_rad"), std::string::npos);
  o = {};
  o.slam.max_candidates = 0;
  ASSERT_TRUE(validate(o));
  EXPECT_NE(validate(o)->find("max_candidates"), std::string::npos);
  o = {};
  o.frame_drop_probability = 1.0;  // every frame lost: no map
  ASSERT_TRUE(validate(o));
  EXPECT_NE(validate(o)->find("frame_drop_probability"), std::string::npos);
  o = {};
  o.obstacle_course = ObstacleCourseOptions{};
  o.obstacle_course->body.body_radius_m = o.clearance_m;  // the taught route would touch walls
  ASSERT_TRUE(validate(o));
  EXPECT_NE(validate(o)->find("body_radius_m"), std::string::npos);
  o.obstacle_course = ObstacleCourseOptions{};
  o.obstacle_course->stop_when_blocked_s = -1.0;
  ASSERT_TRUE(validate(o));
  EXPECT_NE(validate(o)->find("stop_when_blocked_s"), std::string::npos);
  o.obstacle_course = ObstacleCourseOptions{};
  o.obstacle_course->detour.corridor_m = -1.0;
  ASSERT_TRUE(validate(o));
  EXPECT_NE(validate(o)->find("obstacle_course.detour: corridor_m"), std::string::npos);
  o.obstacle_course = ObstacleCourseOptions{};
  o.obstacle_course->forget_memory_jump_m = 0.0;
  ASSERT_TRUE(validate(o));
  EXPECT_NE(validate(o)->find("forget_memory_jump_m"), std::string::npos);
  o.obstacle_course = ObstacleCourseOptions{};
  o.obstacle_course->sonar_grid.resolution_m = 0.0;
  ASSERT_TRUE(validate(o));
  EXPECT_NE(validate(o)->find("obstacle_course.sonar_grid: resolution_m"), std::string::npos);
}

}  // namespace
}  // namespace tessera
