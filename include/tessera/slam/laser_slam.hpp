#pragma once
// Laser SLAM over a 2D laser log: local SLAM (every scan matched against the active submap,
// odometry increments as the prior), submaps, a pose graph of submaps and scan nodes, loop closure
// by branch and bound, and Ceres optimisation (Hess et al. 2016, "Real-time loop closure in 2D
// LIDAR SLAM" (Cartographer), Sec. IV-V; Olson 2009 for the correlative search; Konolige et al.
// 2010 (Karto) for the graph of scans; the lecture's grid-matching SLAM for the idea of matching a
// scan against the map built so far). docs/decisions/0007-laser-slam-design.md records the choices.
//
// Everything runs on the calling thread, in input order: the result depends only on the log and
// the options.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tessera/core/result.hpp"
#include "tessera/core/stamped_pose2.hpp"
#include "tessera/grid/occupancy_grid.hpp"
#include "tessera/posegraph/pose_graph.hpp"
#include "tessera/sensors/laser_log.hpp"
#include "tessera/slam/correlative_scan_matcher.hpp"
#include "tessera/slam/loop_closer.hpp"
#include "tessera/slam/motion_filter.hpp"
#include "tessera/slam/odometry_calibration.hpp"
#include "tessera/slam/scan_points.hpp"
#include "tessera/slam/scan_refiner.hpp"
#include "tessera/slam/submap.hpp"
#include "tessera/slam/wall_direction.hpp"

namespace tessera::slam {

/// How stiff a kind of pose-graph constraint is: standard deviations of its translation (each
/// axis) and heading. The information matrix is diag(1/s_t^2, 1/s_t^2, 1/s_r^2).
struct ConstraintSigmas {
  double translation_m = 0.02;
  double rotation_rad = 0.01;
};

/// Where a run is, for a progress display.
struct SlamProgress {
  int scans_done = 0;
  int scans_total = 0;  // 0 when unknown (scans fed one by one)
  int nodes = 0;
  int submaps = 0;
  int loop_closures = 0;
};

/// What an unknown cell reads in laser SLAM's refinements
/// (ScanRefinerOptions::unknown_probability): about what a free cell of a submap reads after the
/// twenty or so misses it gets there (0.49 per miss), so that the edge of the known part of a
/// submap neither pulls a scan's returns in nor pushes them out. Cartographer's kMinProbability
/// shortened local SLAM's steps by 0.1 % in simulation with exact odometry (decision 0039).
inline constexpr double kSlamUnknownProbability = 0.3;

struct LaserSlamOptions {
  /// Returns beyond 20 m only clear free space. Decision 0009 had 8 m (a heading error of 0.2 deg
  /// moves a return 8 m away by 2.8 cm), tuned on the Intel lab's narrow rooms; in large halls
  /// (FHW, ACES) most walls are further away and an 8 m scan holds too little to match, so local
  /// SLAM drifted (decision 0013). The scan's own no-return threshold still applies.
  ScanPointsOptions points{.min_range_m = 0.1, .max_range_m = 20.0, .missing_ray_length_m = 5.0};
  /// Voxel size of the points used for local matching (0: every point).
  double matching_voxel_m = 0.0;
  /// Points for the branch-and-bound search of loop closure: few and spread evenly (at least 40,
  /// in voxels of up to 0.5 m). The search cost is linear in them; the refinement after it uses
  /// every point. On Intel, 40 points instead of 100 halve the search time and leave a quarter
  /// as many wrong matches (the refined score, over all points, must pass the threshold too).
  /// Returns beyond 10 m are left out of the search points (the refinement still uses every
  /// point): the search's angle step is set by its farthest point, and 20 m points cost 2.5x the
  /// angles of 8 m ones (decision 0013).
  AdaptiveVoxelFilterOptions loop_points{0.5, 40, 10.0};
  /// Submaps of 90 scans or 15 m of travel, whichever comes first (decision 0013: with a scan
  /// every metre, 90 scans made 180-metre submaps whose walls no longer agreed).
  SubmapOptions submaps;
  /// Which scans become pose-graph nodes and go into submaps; the others are matched and placed
  /// relative to the last node.
  MotionFilterOptions motion_filter;
  /// Correlative search before refinement (Olson 2009); off: refine from the odometry prior alone.
  bool real_time_search = true;
  RealTimeMatcherOptions real_time;
  /// false: the scans carry no odometry (a bag of scans alone, or odometry not to be trusted) and
  /// their `odometry` is ignored. Each scan is then predicted one more step of the last scan's
  /// motion on (constant velocity per scan, in file order: stamps are not used, as real logs'
  /// jitter and step back), searched in the wider real_time_without_odometry window, and refined
  /// with its position tied to the prediction and its heading to the search's result. This
  /// needs the scans to come faster than the motion changes: the window holds a change of 0.3 m
  /// and 0.5 rad per scan (docs/bags.md, "Scans alone").
  bool use_odometry = true;
  RealTimeMatcherOptions real_time_without_odometry{.linear_window_m = 0.3,
                                                    .angular_window_rad = 0.5};
  /// Refinement after the search: weak ties to the odometry prediction, 3/m in translation and
  /// 5/rad in heading. Decision 0007 had 10/m and 0 (40 spiralled the Intel map); with scans a
  /// metre apart both were wrong (decision 0013). A heading left free slides into the wrong
  /// optimum where a scan's far points meet known walls (7-10 deg jumps at turns even from a
  /// perfect prior). A translation tied at 10/m carries the odometry's scale error (2 % in the
  /// test protocol) along corridors, where the walls pin the pose only across them, and the loops
  /// then close only by bending the corridors: Intel corrected 0.17-0.21 m ATE at 10/m, 0.07-0.09
  /// m at 3/m. The Intel raw relations improve too (0.0173 m at 5/m, 0.0189 m at 10/m, 0.0168 m at
  /// 3/m, with the rest of decision 0013).
  /// Unknown cells read kSlamUnknownProbability (decision 0039).
  ScanRefinerOptions refiner{1.0, 3.0, 5.0, 20, kSlamUnknownProbability};
  /// The odometry's translation and rotation scales and its drift per metre, estimated from local
  /// SLAM's matches and taken out of its steps before they predict the next scan
  /// (odometry_calibration.hpp): the refinement's tie to the prediction (3/m, 5/rad) otherwise
  /// carries them into every step the walls do not pin. With kSlamUnknownProbability, local SLAM
  /// then follows the true scale whatever the odometry's (decision 0039).
  OdometryCalibrationOptions odometry_calibration;

  bool loop_closure = true;
  /// LoopCloserOptions' defaults, with unknown cells at kSlamUnknownProbability (decision 0039).
  LoopCloserOptions loop_closer = [] {
    LoopCloserOptions o;
    o.refiner.unknown_probability = kSlamUnknownProbability;
    return o;
  }();
  /// A (node, finished submap) pair is searched only when at least this share of the node's loop
  /// points, placed at the current estimate, fall on cells the submap knows.
  double loop_min_overlap = 0.5;
  /// Share of the (node, finished submap) pairs in range that are searched, per submap, chosen by
  /// a deterministic counter (Cartographer's FixedRatioSampler).
  double loop_sampling_ratio = 0.3;
  /// A pair whose search in loop_closer.window failed is searched again in this wider window
  /// (a full turn by default) for this share of such pairs, per submap: it finds loops after a
  /// drift larger than the window, at about 10x the cost of a search (0: never).
  SearchWindow global_window{5.0, 3.14159265358979323846};
  double global_sampling_ratio = 0.01;
  /// The score a match in the global window must reach: a wide window holds more look-alikes.
  double global_min_score = 0.72;
  /// The loop search window grows with the path along which local SLAM's drift between a node
  /// and a submap can have grown: the shortest way between them through the path and the loop
  /// closures accepted so far (Karto's idea of searching by graph distance). Window =
  /// loop_closer.window plus these per metre of that path, up to loop_window_max. After metres of
  /// drift the window still holds the true pose, and a whole building can be searched (branch and
  /// bound prunes); where loops were closed nearby it stays small.
  double loop_window_growth_m_per_m = 0.05;
  double loop_window_growth_rad_per_m = 0.01;
  SearchWindow loop_window_max{30.0, 3.14159265358979323846};
  /// A match found in a window wider than verify_beyond x loop_closer.window is only a candidate:
  /// it is trusted when another candidate of a node within verify_span_nodes agrees with it on the
  /// correction it implies (within verify_tolerance), as wrong matches in look-alike places do
  /// not agree with each other (the idea of Olson's single-cluster test, in its simplest form).
  double verify_beyond = 1.5;
  int verify_span_nodes = 30;
  SearchWindow verify_tolerance{0.3, 0.05};
  /// After the final optimisation, loop constraints whose whitened residual is larger than this
  /// are switched off (counted in LaserSlamStats::loop_rejected) and the graph is optimised again:
  /// a wrong closure must not bend the map (0: never). Only after the final one: earlier, a correct
  /// closure after a long drift can still be far from a graph that has not yet taken it in (a gate
  /// after every optimisation took FHW from 0.17 to 0.38 m ATE). 50 sigmas is 1 m at the loop
  /// sigma of 2 cm; 30 also took out a correct closure on Intel corrected (decision 0013). With
  /// 30 % of Intel raw's closures replaced by wrong ones, the relations stay at 0.0167 m.
  double loop_outlier_sigmas = 50.0;
  /// For robustness tests only (issue 17): this share of the accepted loop constraints is
  /// replaced by a constraint to a wrong place (the match moved by 1-4 m and 0.2-1 rad in a random
  /// direction, drawn from wrong_closure_seed), so that the back end's defences can be measured.
  double wrong_closure_share = 0.0;
  std::uint64_t wrong_closure_seed = 1;
  /// The lecture's "mapping using knowledge of the environment" (issue 18 item 7; off by
  /// default). The building's axis is where the first scan with a dominant wall direction
  /// (wall_direction.hpp) puts its walls. Then, for every scan that shows one:
  ///  - local SLAM: when the heading that puts the scan's walls along the axis (or across it) is
  ///    within manhattan_gate_rad of the search's result, the refinement is also pulled towards
  ///    it with manhattan_rotation_weight (per radian, the units of refiner.rotation_weight);
  ///  - the pose graph: every node gets a heading prior (posegraph::HeadingPrior, sigma
  ///    manhattan_sigma_rad under a Cauchy loss), the axis estimated with the poses; the graph is
  ///    then optimised at the end even without loop closures.
  /// Measured in docs/slam-manhattan.md.
  bool manhattan = false;
  double manhattan_rotation_weight = 20.0;
  double manhattan_gate_rad = 0.05;
  double manhattan_sigma_rad = 0.05;
  WallDirectionOptions wall_direction;
  /// Optimise the graph after this many new nodes when new loop constraints came in.
  int optimize_every_n_nodes = 60;
  int optimizer_iterations = 30;
  /// Consecutive nodes: their relative pose from local SLAM.
  ConstraintSigmas local_sigmas{0.02, 0.01};
  /// A node in the submaps it was inserted into.
  ConstraintSigmas submap_sigmas{0.02, 0.01};
  /// Both grow by this for every metre between the node and the one before it: local SLAM's
  /// error over a metre between scans is larger than over 0.2 m, and a graph that holds sparse
  /// scans as stiffly as dense ones cannot take a loop closure's correction (decision 0013).
  ConstraintSigmas local_sigmas_per_m{0.03, 0.01};
  /// A node matched into an older submap (robust): fixed sigmas, or (when loop_hessian_scale > 0)
  /// the refinement's J^T J times loop_hessian_scale, so a match along a corridor constrains only
  /// across it (the idea of Olson 2009 Sec. IV and Karto's response covariance). A scale of 80
  /// gives a typical Intel match about 2 cm across its best-fixed direction; on Intel it scores
  /// the same as fixed sigmas, so the simpler one is the default.
  ConstraintSigmas loop_sigmas{0.02, 0.01};
  double loop_hessian_scale = 0.0;
  /// Huber scale of robust constraints, in units of the whitened residual.
  double huber_scale = 1.0;
  /// The first node of a new trajectory (start_trajectory) in the nearest node of the earlier
  /// ones: where relocalization placed it, held loosely so that the loop closures that follow
  /// decide the fine placement, but firmly enough that the trajectory never floats free of the
  /// map before they come.
  ConstraintSigmas start_sigmas{0.1, 0.05};

  /// At the end of the run (finish()), this many passes of matching every node's scan against the
  /// map of all nodes (GMapping's lesson: its particles match each scan against their whole map,
  /// where tessera's local SLAM sees only the current submap, so drift inside a submap and
  /// disagreements between overlapping submaps are left for the pose graph). A pass refines each
  /// node's scan in the final map at the current poses (final_map_refiner, tied loosely to where
  /// it is), ties the node to the refined pose with information final_map_hessian_scale x the
  /// refinement's J^T J (+ identity, a 1 m / 1 rad floor), so a scan along a corridor is tied
  /// only across it, and optimises the graph with those ties. One pass brings the trajectory
  /// closer to the truth on every simulated building and on most real logs (decisions 0037 and
  /// 0038). Not run without loop_closure: local SLAM alone stays local.
  int final_map_passes = 1;
  double final_map_hessian_scale = 80.0;
  ScanRefinerOptions final_map_refiner{.occupied_space_weight = 1.0,
                                       .translation_weight = 0.1,
                                       .rotation_weight = 0.4,
                                       .max_iterations = 5,
                                       .unknown_probability = kSlamUnknownProbability};

  /// The final map: every node's scan at its optimised pose.
  double map_resolution_m = 0.05;
  RangeInsertOptions map_insert{.hit_probability = 0.55,
                                .miss_probability = 0.49,
                                .insert_free_space = true,
                                .miss_margin_m = 0.03,
                                .miss_inset_m = 0.005};

  /// Called after every scan (on the calling thread).
  std::function<void(const SlamProgress&)> progress;
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const LaserSlamOptions& o);

struct LaserSlamStats {
  int scans = 0;
  int nodes = 0;
  int submaps = 0;
  int loop_searches = 0;    // (node, submap) pairs searched
  int global_searches = 0;  // of which also searched in the global window
  int loop_closures = 0;    // accepted constraints to submaps the node was not inserted into
  int loop_candidates = 0;  // wide-window matches held for verification
  int loop_unverified = 0;  // candidates dropped because no other agreed
  int loop_rejected = 0;    // accepted constraints switched off after an optimisation
  int loop_wrong_injected = 0;  // constraints replaced by wrong ones (wrong_closure_share)
  int optimizations = 0;
  int manhattan_priors = 0;  // nodes with a Manhattan heading prior (options.manhattan)
  int manhattan_pulls = 0;   // scans whose refinement was pulled towards the building's axis
  /// The largest difference between an accepted loop match and the estimate it started from.
  double max_loop_correction_m = 0.0;
  double max_loop_correction_rad = 0.0;
  int backward_stamps = 0;  // scans stamped earlier than the scan before them
  /// The odometry's errors as estimated at the end (odometry_calibration.hpp; 1, 1 and 0: not
  /// estimated, or none found).
  double odometry_translation_scale = 1.0;
  double odometry_rotation_scale = 1.0;
  double odometry_drift_rad_per_m = 0.0;
  double matching_s = 0.0;  // local SLAM: matching and submap insertion
  double loop_search_s = 0.0;
  double optimization_s = 0.0;
  double whole_map_s = 0.0;  // final_map_passes: the map and the matches (their optimisation is
                             // in optimization_s)
  double map_s = 0.0;
};

struct LaserSlamResult {
  /// The robot pose at every input scan, in input order with the scans' stamps (map frame).
  std::vector<StampedPose2> trajectory;
  /// The same from local SLAM alone (scan-to-submap matching, before the pose graph).
  std::vector<StampedPose2> local_trajectory;
  /// Vertices: submaps and nodes in creation order; ids equal vertex indices.
  posegraph::PoseGraph graph;
  /// For every vertex of `graph`: the scan index of a node, or -1 for a submap.
  std::vector<int> vertex_scan;
  OccupancyGrid map;
  LaserSlamStats stats;
};

/// Where a trajectory begins (LaserSlam::start_trajectory): the index of its first scan in the
/// input and that scan's T_map_robot.
struct TrajectoryStart {
  int first_scan = 0;
  Pose2 T_map_robot;
};

/// How many trajectories a run with these starts has: one more than the starts, unless one is at
/// scan 0 (it begins the first).
[[nodiscard]] inline int trajectory_count(const std::vector<TrajectoryStart>& starts) {
  const bool first_placed = !starts.empty() && starts.front().first_scan == 0;
  return static_cast<int>(starts.size()) + (first_placed ? 0 : 1);
}

/// The pipeline, fed one scan at a time (any source of StampedScan: a log file, the simulator).
class LaserSlam {
 public:
  /// Precondition: validate(options) is empty.
  explicit LaserSlam(const LaserSlamOptions& options);
  ~LaserSlam();
  LaserSlam(const LaserSlam&) = delete;
  LaserSlam& operator=(const LaserSlam&) = delete;

  /// Processes the next scan. `scans_total` only feeds the progress report (0: unknown).
  /// Runtime error if an optimisation fails.
  [[nodiscard]] Status add_scan(const StampedScan& scan, int scans_total = 0);

  /// Begins a new trajectory in the same graph (a resumed session, issue 16): the next scan is
  /// placed at T_map_robot in the map as optimised so far, with no odometry tie to the scan
  /// before it (a new log's odometry has its own origin). The trajectory before it ends as a run
  /// ends in finish(): its active submaps are finished and searched for loops, and the graph is
  /// optimised (so a session replayed from its scans is then exactly the saved one).
  /// The new trajectory's first node is tied to the nearest earlier node with start_sigmas and
  /// builds its own submaps; loop closures then join them to the old ones. Before any scan, it
  /// only sets the first scan's pose. Runtime error if the optimisation fails.
  [[nodiscard]] Status start_trajectory(const Pose2& T_map_robot);

  /// T_map_robot of the last scan added, under the graph as optimised so far (a live view's
  /// estimate; finish() optimises once more). Precondition: a scan was added.
  [[nodiscard]] Pose2 latest_pose() const;
  /// The map from every node so far at its current pose. Costs what finish()'s map costs
  /// (LaserSlamStats::map_s): for a live view now and then, not per scan.
  [[nodiscard]] OccupancyGrid current_map() const;

  /// The result so far, as the graph is now (no final optimisation): for saving a session while
  /// the run goes on. Costs what finish()'s trajectory and map cost. Precondition: a scan was
  /// added.
  [[nodiscard]] LaserSlamResult snapshot() const;

  /// Finishes the open submaps (searching them for loops with every older node), then the final
  /// optimisation, trajectory and map. Call once, after the last scan.
  [[nodiscard]] Result<LaserSlamResult> finish();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Called by run_laser_slam after every scan with the pipeline and the number of scans done (a
/// live view, an autosave); an error stops the run with it.
using AfterScan = std::function<Status(const LaserSlam& slam, int scans_done)>;

/// Runs the pipeline over a whole log, in file order, beginning a new trajectory at each of
/// `starts` (by increasing first_scan; a start at scan 0 only places the first scan, as a
/// trimmed session's first kept scan is placed) and calling `after_scan` after every scan. Usage
/// error for invalid options, input error for a log without scans or starts that are not scans
/// of the log in increasing order.
[[nodiscard]] Result<LaserSlamResult> run_laser_slam(
    const LaserLog& log, const LaserSlamOptions& options,
    const std::vector<TrajectoryStart>& starts = {}, const AfterScan& after_scan = {});

}  // namespace tessera::slam
