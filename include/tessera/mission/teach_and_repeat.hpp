#pragma once
// The two-stage experiment of the Fusion SLAM thesis (../shared/seeds/002, section 5.1.1, Table
// 5.1) in the simulator, with the thesis' weaknesses fixed (section 6.2):
//  TEACH (Table 5.1 steps 1-7): the robot is driven open loop (a perfect operator on the true pose)
//    along a route from the start to the goal, stopped in a firing field at the goal to capture the
//    goal image node (its true pose is the "taught goal pose"), and driven back to the start, where
//    it turns to face the route again; all the while the Fusion SLAM (fusion/fusion_slam.hpp) maps
//    cells and image nodes from drifting wheel odometry (sensors/thesis_odometry.hpp).
//  REPEAT (steps 8-9): from the start the robot confirms the start node (an image-node search),
//    then navigates by itself to the goal cell: the wavefront over the learned cells' traversed
//    adjacency (nav/wavefront.hpp), shortened to a polyline that does not zigzag
//    (nav/cell_polyline.hpp) and followed by pure pursuit (nav/path_follower.hpp) on the SLAM's
//    drift-corrected estimate, replanned after each correction; in the goal cell the image-node
//    search drives to the goal node's pose, turns the neck to its angle and confirms by matching,
//    driving again onto the node when the match shows an offset (6.2 item 4).
// Frames are rendered only where the SLAM asks for one (firing fields) and for the search.
// Deterministic for a seed. No I/O.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "tessera/core/pose2.hpp"
#include "tessera/core/result.hpp"
#include "tessera/core/rng.hpp"
#include "tessera/core/stamped_pose2.hpp"
#include "tessera/core/vec2.hpp"
#include "tessera/fusion/fusion_slam.hpp"
#include "tessera/mission/teach_and_repeat_setup.hpp"
#include "tessera/nav/detour_planner.hpp"
#include "tessera/nav/path_follower.hpp"
#include "tessera/nav/reactive_avoidance.hpp"
#include "tessera/nav/sonar_grid.hpp"
#include "tessera/sensors/odometry_model.hpp"
#include "tessera/sensors/thesis_odometry.hpp"
#include "tessera/sim/p3dx_body.hpp"
#include "tessera/sim/poster.hpp"
#include "tessera/sim/rgbd_camera.hpp"
#include "tessera/sim/wall_faces.hpp"
#include "tessera/sim/world.hpp"

namespace tessera {

/// How the repeat stage drives to the goal cell.
enum class RepeatNavigation {
  kPolyline,      // ours: the non-zigzag cell polyline, pure pursuit (thesis 6.2 item 3)
  kThesisGreedy,  // the thesis as written (4.3.5): re-decide the best neighbour at every border
};

/// The obstacle course of thesis chapter 5 (Figure 5.1: obstacles along the route) with the
/// reactive avoidance of section 4.3.4 in the navigation loop (issue 18 item 9): the robot gets a
/// P3DX body (it stops against what it drives into), 8 sonars and 10 bumpers
/// (sim/p3dx_body.hpp), and boxes are put on the taught route after the teach stage, where the
/// taught cells run through them. docs/fusion-navigation.md has the figures.
struct ObstacleCourseOptions {
  P3dxBodyOptions body;
  /// The avoidance in the navigation loop; the strip rule (path_half_width_m) is ours, see
  /// nav/reactive_avoidance.hpp. avoid = false drives without it (the boxes then stop the robot).
  ReactiveAvoidanceOptions avoidance = strip_avoidance();
  bool avoid = true;
  /// Ours: the avoidance hears only echoes from where the robot drove while teaching (within the
  /// body's radius of the taught path, as the pose graph now places it): something new on the
  /// route. Walls keep the route's clearance from the taught path and are never obstacles, so
  /// the robot passes doors and corners as it was taught. false: every echo counts (the thesis).
  bool only_new_obstacles = true;
  /// Boxes on the route (mission/teach_and_repeat_setup.hpp place_route_obstacles).
  int obstacles = 2;
  double obstacle_side_m = 0.3;
  double min_end_distance_m = 1.5;
  /// Open floor round each box: two route clearances, so that a route keeping the clearance
  /// passes on either side (decision 0028).
  double free_around_m = 0.6;
  /// The drives onto a point (the goal cell's centre for the goal capture, a node in the
  /// image-node search: centimetres, without the avoidance) end where the robot stands once a
  /// contact has stopped its wheels this long: the bumpers say it cannot get closer, and the
  /// capture is taken there. A cell's centre can lie closer to a wall than the body's radius
  /// (the taught route keeps the clearance, the cells around it need not). 0: never. Ours.
  double stop_when_blocked_s = 1.0;
  /// Ours: the sonar sweeps are remembered in an occupancy grid (nav/sonar_grid.hpp), and when an
  /// occupied cell new on the taught route (as only_new_obstacles reads it) blocks the path ahead,
  /// the robot plans a route round it on that grid (nav/detour_planner.hpp) instead of relying on
  /// the avoidance's turns alone; the avoidance still filters every command. Only with the
  /// polyline navigation. false: the reactive avoidance alone (decision 0028).
  bool detours = true;
  /// The memory's sonars sit where the body's do: its sensor_radius_m is set from
  /// body.sonar_radius_m.
  SonarGridOptions sonar_grid;
  DetourOptions detour;
  /// Ours: a SLAM correction that moves the estimate further than this from where odometry alone
  /// would have put it forgets the sonar memory. Its cells were placed by the old estimate, so
  /// after such a jump they stand where nothing is (a door post remembered in the doorway); the
  /// sweeps rebuild what is around the robot within seconds.
  double forget_memory_jump_m = 0.15;

  /// The thesis' avoidance with our strip and straight-on rules: obstacles count within the
  /// body's width plus 0.1 m of the line ahead, ranges start at the P3DX sonars' 0.2 m from the
  /// centre, and a turn away is followed by 2 s (0.2 m at 0.1 m/s) straight on.
  [[nodiscard]] static ReactiveAvoidanceOptions strip_avoidance() {
    ReactiveAvoidanceOptions o;
    o.path_half_width_m = 0.35;
    o.sensor_radius_m = 0.2;
    o.straight_after_turn_s = 2.0;
    return o;
  }
};

struct TeachAndRepeatOptions {
  fusion::FusionSlamOptions slam;
  /// Wheel odometry drift: the thesis' (Table 5.4) by default.
  OdometryErrorOptions odometry = thesis_fusion_odometry();
  /// The taught route's clearance from walls (robot radius plus margin).
  double clearance_m = 0.3;
  /// Driving limits for the operator (teach) and the navigation (repeat).
  double max_speed_m_per_s = 0.3;
  double max_turn_rate_rad_per_s = 0.5;
  /// Simulation step and how many steps between two SLAM updates (odometry events).
  double control_period_s = 0.01;
  int steps_per_update = 10;
  /// The neck's pan angle while driving (0: the camera looks ahead).
  double neck_pan_rad = 0.0;
  /// At each capture the neck pans to these angles and a frame is taken at each (the thesis'
  /// robot has a pan neck, section 3.1.3): with 57-degree views, -1, 0 and +1 rad would see about
  /// 170 degrees, so a poster beside the route is in some view; five angles 0.7 rad apart see about
  /// 220 degrees with overlapping views. Ours.
  std::vector<double> capture_neck_angles_rad = {-1.4, -0.7, 0.0, 0.7, 1.4};
  /// Navigation (repeat): pure pursuit limits and gains.
  PathFollowerOptions follower;
  /// Image-node search: the robot counts as on the node once a confirming match shows it within
  /// this distance of the node's pose; it drives onto the node again at most max_search_drives
  /// times.
  double search_tolerance_m = 0.03;
  int max_search_drives = 3;
  /// A drive that lasts longer than this fails the run (runtime error).
  double max_drive_s = 600.0;
  /// A frame the SLAM asks for is lost with this probability (a dropped USB frame, a busy link);
  /// the SLAM asks again at the next update while it is still in the firing field. For the thesis'
  /// claim that the map survives dropped frames (issue 18 item 11). The operator's goal capture and
  /// the image-node search are never dropped.
  double frame_drop_probability = 0.0;
  RepeatNavigation navigation = RepeatNavigation::kPolyline;
  /// Off by default: the robot then has no body (it drives through anything) and no sonars or
  /// bumpers; the taught route keeps clearance_m from every wall.
  std::optional<ObstacleCourseOptions> obstacle_course;
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const TeachAndRepeatOptions& o);

/// Per run, the figures of the thesis' Tables 5.2-5.4 and the bars.
struct TeachAndRepeatRun {
  std::uint64_t seed = 0;
  Pose2 start;
  Vec2 goal_m;
  std::vector<Vec2> route_m;  // the taught route, start to goal
  double taught_route_length_m = 0.0;
  Pose2 taught_goal_pose;  // true pose at the goal node's capture
  std::size_t goal_node = 0;
  std::size_t goal_cell = 0;
  std::size_t start_cell = 0;
  std::size_t goal_cell_image_nodes = 0;  // image nodes stored in the goal cell at the end (App. B)
  int frames_dropped = 0;                 // frames_drop_probability's losses, both stages
  // Repeat.
  bool reached_goal_cell = false;
  double goal_cell_distance_m = 0.0;  // true distance to the goal cell's true centre at arrival
  Pose2 final_pose;                   // true pose at the end of the search
  double final_error_x_m = 0.0;       // final_pose - taught_goal_pose, map (= world) frame
  double final_error_y_m = 0.0;
  double final_error_m = 0.0;
  double final_heading_error_rad = 0.0;
  double navigation_path_m = 0.0;  // driven from the start until the goal cell was reached
  double navigation_time_s = 0.0;
  int heading_reversals =
      0;  // while navigating, true heading (eval/heading_reversals.hpp, 0.1 rad)
  // The obstacle course (options.obstacle_course): the boxes (lo, hi corners), the updates the
  // avoidance turned the robot away from a sonar echo, bumper hits (a bumper newly pressed) and
  // control steps the body was stopped by a contact, all while navigating; and the detours planned
  // round remembered obstacles (ObstacleCourseOptions::detours).
  std::vector<std::pair<Vec2, Vec2>> obstacles_m;
  int avoidance_updates = 0;
  int detours = 0;
  int bumper_hits = 0;
  int blocked_steps = 0;
  double shortest_cell_path_m = 0.0;  // wavefront path over the learned cells, centre to centre
  double path_ratio = 0.0;
  double odometry_error_at_goal_m = 0.0;  // |odometry - truth| at the end (uncorrected)
  double estimate_error_at_goal_m = 0.0;  // |estimate - truth| at the end
  // Drift correction: ATE (aligned, TUM evaluate_ate.py) of the pose-graph trajectory after the
  // last optimisation and of odometry alone, against the truth at the same stamps.
  double ate_corrected_m = 0.0;
  double ate_odometry_m = 0.0;
  double ate_ratio = 0.0;  // odometry / corrected (eval/drift_correction.hpp); 0: none
  // Loop closures against the truth: every accepted match (the node search's included) as the
  // motion it claims, scored on the true path (eval/relation_metric.hpp); wrong ones are off by
  // more than 0.2 m or 0.1 rad (relations_off_by_more_than).
  int wrong_matches = 0;
  double max_match_error_m = 0.0;
  // Image-node search.
  int search_trials = 0;
  int search_successes = 0;
  int search_captures = 0;  // confirmation captures, all searches
  struct Search {
    std::size_t node = 0;
    bool confirmed = false;
    int captures = 0;
    std::string last_reason;     // the last confirmation's matcher reason
    double offset_m = 0.0;       // the last confirming match's distance to the node pose
    double true_offset_m = 0.0;  // the robot's true distance to the node's true pose
    // Thesis Appendix C: the first confirming match's distance to the node pose (where the robot
    // stood when it first arrived by its estimate; 0 when none confirmed) and the dead-reckoning
    // error |odometry - truth| when the search began.
    double first_offset_m = 0.0;
    double odometry_error_m = 0.0;
  };
  std::vector<Search> searches;
  // The map.
  std::size_t cells = 0;
  std::size_t image_nodes = 0;
  std::size_t pose_nodes = 0;
  fusion::FusionStatistics slam;
  fusion::FusionStatistics slam_after_teach;  // the statistics when the teach stage ended
  double duration_s = 0.0;                    // simulated time, both stages
  // Paths for pictures (map frame): estimates while teaching and repeating, and the truth.
  std::vector<Vec2> taught_path_m;
  std::vector<Vec2> repeated_path_m;
  std::vector<Vec2> true_path_m;
  std::vector<StampedPose2> corrected_trajectory;  // pose-graph nodes after the last optimisation
};

struct TeachAndRepeatResult {
  TeachAndRepeatRun run;
  /// The SLAM at the end (its map and image nodes, for pictures).
  fusion::FusionSlam slam;
};

/// The experiment's stages, in order (Table 5.1).
enum class TeachAndRepeatStage {
  kTeachToGoal,       // steps 1-5: the operator drives the route to the goal
  kCaptureGoalNode,   // step 6: into the firing field, look round, store the best view
  kTeachBack,         // step 7: back to the start, facing the route again
  kConfirmStartNode,  // step 8: image-node search in the start cell
  kNavigate,          // step 8: wavefront + polyline + pure pursuit to the goal cell
  kFindGoalNode,      // step 8: image-node search for the goal node; step 9: the figures
  kDone,
};

/// What the stage does, for a progress line ("teach: driving to the goal").
[[nodiscard]] const char* describe(TeachAndRepeatStage stage);

class TeachAndRepeatSimulation;  // the simulated robot, camera and SLAM (internal)

/// One run of the experiment as a step machine: step() runs the current stage to its end and
/// moves to the next; the figures fill in as the stages end and are complete at kDone. The world
/// comes from outside: `camera` (which holds it) renders the frames and must outlive the object.
/// A stage is the unit of stepping; a mission driven by messages from another process (a real
/// robot) needs steps of one control period, which this class does not offer yet (decision 0016).
class TeachAndRepeat {
 public:
  /// Input errors: invalid options ("teach and repeat: ..."), no route from start to goal, no
  /// place for the obstacle course's boxes.
  [[nodiscard]] static Result<TeachAndRepeat> create(const RgbdCamera& camera,
                                                     const TeachAndRepeatOptions& options,
                                                     const Pose2& start, Vec2 goal_m,
                                                     std::uint64_t seed);
  TeachAndRepeat(TeachAndRepeat&&) noexcept;
  TeachAndRepeat& operator=(TeachAndRepeat&&) noexcept;
  ~TeachAndRepeat();

  /// Runs the current stage. Runtime errors: no view at the goal makes an image node, the
  /// wavefront finds no path, a drive exceeds max_drive_s; the object is then finished (kDone)
  /// with the figures it had. Precondition: !done().
  Status step();

  [[nodiscard]] bool done() const { return stage_ == TeachAndRepeatStage::kDone; }
  [[nodiscard]] TeachAndRepeatStage stage() const { return stage_; }
  /// The figures so far (complete once done()).
  [[nodiscard]] const TeachAndRepeatRun& run() const { return run_; }
  [[nodiscard]] const fusion::FusionSlam& slam() const;
  /// The run and the SLAM, leaving the object empty. Precondition: done().
  [[nodiscard]] TeachAndRepeatResult take_result() &&;

 private:
  TeachAndRepeat(const RgbdCamera& camera, const TeachAndRepeatOptions& options,
                 std::vector<Vec2> route, std::optional<RouteObstacles> obstacles,
                 const Pose2& start, Vec2 goal_m, std::uint64_t seed);
  Status teach_to_goal();
  Status capture_goal_node();
  Status teach_back();
  Status confirm_start_node();
  Status navigate();
  Status find_goal_node();
  Status search(std::size_t node_id);
  void finish();

  TeachAndRepeatOptions options_;
  std::unique_ptr<TeachAndRepeatSimulation> sim_;
  std::unique_ptr<World> repeat_world_;  // the world with the boxes (obstacle course only)
  std::size_t teach_graph_nodes_ = 0;    // pose-graph nodes when the teach stage ended
  TeachAndRepeatRun run_;
  TeachAndRepeatStage stage_ = TeachAndRepeatStage::kTeachToGoal;
};

/// Runs the experiment once in `camera`'s world from `start` to `goal_m`: TeachAndRepeat stepped to
/// the end. Errors: TeachAndRepeat's. `progress` (optional) gets describe(stage) before each
/// stage. Deterministic for (camera, options, start, goal, seed).
[[nodiscard]] Result<TeachAndRepeatResult> run_teach_and_repeat(
    const RgbdCamera& camera, const TeachAndRepeatOptions& options, const Pose2& start, Vec2 goal_m,
    std::uint64_t seed, const std::function<void(const std::string&)>& progress = {});

/// Several runs at a glance: how many reached the goal cell, the worst final error, path ratio
/// and ATE ratio, and the image-node searches.
struct TeachAndRepeatSummary {
  int runs = 0;
  int reached_goal_cell = 0;
  double max_final_error_m = 0.0;
  double max_path_ratio = 0.0;
  double min_ate_ratio = 0.0;  // 1e300 when there are no runs
  int search_trials = 0;
  int search_successes = 0;
};
[[nodiscard]] TeachAndRepeatSummary summarize(const std::vector<TeachAndRepeatRun>& runs);

}  // namespace tessera
