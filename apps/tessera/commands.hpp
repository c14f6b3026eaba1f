#pragma once
// The subcommands. Each registers its options with CLI11 in its constructor and runs with run(),
// which returns the process exit code (0 ok, 2 usage, 3 input, 4 runtime).
#include <CLI/CLI.hpp>
#include <cstdint>
#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "laser_input.hpp"
#include "recording.hpp"
#include "simulated_laser_input.hpp"
#include "slam_live.hpp"
#include "tessera/core/relation.hpp"
#include "tessera/eval/trajectory_error.hpp"
#include "tessera/io/session_file.hpp"
#include "tessera/mission/bob_mission.hpp"
#include "tessera/mission/exploration_mission.hpp"
#include "tessera/sensors/laser_log.hpp"
#include "tessera/slam/laser_slam.hpp"
#include "tessera/slam/localizer.hpp"
#include "tessera/slam/submap_trimmer.hpp"

namespace tessera::cli {

class Command {
 public:
  [[nodiscard]] bool parsed() const { return sub_->parsed(); }

 protected:
  CLI::App* sub_ = nullptr;
};

/// tessera explore: a simulated robot team explores a world with the frontier algorithm.
class ExploreCommand : public Command {
 public:
  explicit ExploreCommand(CLI::App& app);
  [[nodiscard]] int run() const;

 private:
  // The defaults are the library's (ExplorationMissionOptions and its LidarOptions), read here
  // so that --help and --print-config show them; none is written twice.
  static inline const ExplorationMissionOptions kDefaults{};
  WorldSource world_;
  std::string strategy_ =
      kDefaults.strategy == FrontierStrategy::kPriority ? "priority" : "nearest";
  std::string sensor_ = kDefaults.sensor == RobotKind::kLidar ? "lidar" : "cells";
  int robots_ = kDefaults.robots;
  std::uint64_t seed_ = kDefaults.seed;
  std::filesystem::path out_ = "out/explore";
  double resolution_m_ = 0.1;  // the CLI's own: the grid the built-in worlds are drawn at
  std::optional<std::string> start_;
  double lidar_range_m_ = kDefaults.lidar.max_range_m;
  int lidar_beams_ = kDefaults.lidar.beams;
  double range_noise_m_ = kDefaults.lidar.range_noise_stddev_m;
  double low_ = kDefaults.low;
  std::int64_t max_steps_ = kDefaults.max_steps;
  OutputStreams streams_;  // --record, --serve
  bool quiet_ = false;
  // --ros: one explorer robot of a team on Cyclone DDS (cmd_explore_ros.cpp).
  void add_ros_options();
  [[nodiscard]] int run_ros() const;
  bool ros_ = false;
  std::string ns_ = "r1";
  std::vector<std::string> team_starts_;  // "X,Y[,THETA]" per robot, r1 first
  int team_size_ = 0;                     // --team N: starts unknown
  bool exit_when_finished_ = false;
  std::uint32_t domain_ = 0;
  bool network_ = false;
};

/// tessera render: draws a map file (and optionally trajectories and ground-truth errors) as PNG.
class RenderCommand : public Command {
 public:
  explicit RenderCommand(CLI::App& app);
  [[nodiscard]] int run() const;

 private:
  std::filesystem::path map_;
  std::filesystem::path out_;
  std::optional<double> map_resolution_m_;
  std::vector<std::filesystem::path> trajectories_;
  std::optional<std::filesystem::path> truth_;
  int pixels_per_cell_ = 0;
};

/// tessera gridmatch: one step of the lecture's grid-matching SLAM drawn for a student
/// (cmd_gridmatch.cpp).
class GridmatchCommand : public Command {
 public:
  explicit GridmatchCommand(CLI::App& app);
  [[nodiscard]] int run() const;

 private:
  WorldSource world_;
  double cell_m_ = 0.3;
  std::optional<std::string> before_, odometry_, actual_;  // "X,Y,THETA"
  int range_cells_ = 5;
  std::filesystem::path out_ = "out/gridmatch";
  bool quiet_ = false;
};

/// tessera info: describes a map file, or a ROS bag (topics, types, counts, rates, duration).
class InfoCommand : public Command {
 public:
  explicit InfoCommand(CLI::App& app);
  [[nodiscard]] int run() const;

 private:
  [[nodiscard]] int run_bag() const;
  [[nodiscard]] int run_session() const;  // cmd_session.cpp

  std::filesystem::path file_;
  std::optional<double> map_resolution_m_;
  bool json_ = false;
};

/// tessera convert: between map formats (any readable map -> ROS map_server YAML+PGM or PNG).
class ConvertCommand : public Command {
 public:
  explicit ConvertCommand(CLI::App& app);
  [[nodiscard]] int run() const;

 private:
  std::filesystem::path in_;
  std::filesystem::path out_;
  std::optional<double> map_resolution_m_;
};

/// tessera bob: the BOBMapping robot (one-cell moves, five IR sensors) maps a world.
class BobCommand : public Command {
 public:
  explicit BobCommand(CLI::App& app);
  [[nodiscard]] int run() const;

 private:
  static inline const BobMissionOptions kDefaults{};  // the library's defaults, written once
  WorldSource world_{std::nullopt, "labyrinth", std::nullopt, std::nullopt};
  double cell_m_ = kDefaults.cell_m;
  std::string variant_ = kDefaults.variant == BobVariant::kMapAware ? "map-aware" : "trail";
  std::string noise_ = kDefaults.noise ? "on" : "off";
  std::string resense_ = kDefaults.resense ? "on" : "off";
  std::string localisation_ = kDefaults.perfect_localisation ? "perfect" : "beacons";
  std::uint64_t seed_ = kDefaults.seed;
  std::optional<std::string> start_;
  std::filesystem::path out_ = "out/bob";
  bool quiet_ = false;
  std::optional<std::filesystem::path> firmware_;
  OutputStreams streams_;  // --record, --serve
  std::optional<std::filesystem::path> monitor_dir_;
  std::string qemu_ = "qemu-system-arm";
  double firmware_timeout_s_ = 20.0;
};

/// tessera eval relations | ate: scores a trajectory against ground-truth relations (Kummerle et
/// al. 2009) or a reference trajectory (TUM ATE and RPE, Sturm et al. 2012).
class EvalCommand : public Command {
 public:
  explicit EvalCommand(CLI::App& app);
  [[nodiscard]] int run() const;

 private:
  [[nodiscard]] int run_relations() const;
  [[nodiscard]] int run_ate() const;

  CLI::App* relations_ = nullptr;
  CLI::App* ate_ = nullptr;
  std::filesystem::path trajectory_;
  std::filesystem::path relations_file_;
  std::filesystem::path reference_;
  double time_offset_s_ = 0.0;
  double snap_s_ = 0.0;  // > 0: relations take the nearest scans within this, not interpolation
  TrajectoryErrorOptions options_;
  std::optional<std::filesystem::path> out_;
};

/// tessera posegraph optimize: least-squares optimisation of a g2o pose graph (slam::optimize),
/// written back as g2o with a report.json.
class PosegraphCommand : public Command {
 public:
  explicit PosegraphCommand(CLI::App& app);
  [[nodiscard]] int run() const;

 private:
  CLI::App* optimize_ = nullptr;
  std::filesystem::path in_;
  std::filesystem::path out_;
  std::optional<std::filesystem::path> report_;
  int iterations_ = 0;  // set from posegraph::OptimizeOptions in the constructor
  bool quiet_ = false;
};

/// tessera slam: laser SLAM on a 2D laser log (slam/laser_slam.hpp); writes map, trajectory, pose
/// graph and report.json, and scores the trajectory when given relations.
class SlamCommand : public Command {
 public:
  explicit SlamCommand(CLI::App& app);
  [[nodiscard]] int run() const;

 private:
  LaserInput input_;  // --log or --bag; neither: a simulated run in world_
  WorldSource world_;
  SimulatedLaserInput simulated_input_;  // neither: the simulated run's options
  std::filesystem::path out_ = "out/slam";
  std::optional<std::filesystem::path> relations_;
  double time_offset_s_ = 0.0;
  std::optional<double> cell_m_;  // default: 0.05 m for a log, the world's cell for a simulated run
  bool no_loop_closure_ = false;
  bool manhattan_ = false;     // Manhattan heading priors (issue 18 item 7)
  bool no_whole_map_ = false;  // no final pass of every scan against the whole map (0037)
  bool no_odometry_calibration_ = false;  // the odometry as it reads (decisions 0039, 0040)
  /// The method's settings the flags choose (loop closure, Manhattan priors, the whole-map pass,
  /// the odometry's calibration), the same offline and live.
  [[nodiscard]] slam::LaserSlamOptions method_options() const;
  OutputStreams streams_;  // --record, --serve
  bool quiet_ = false;
  // --ros: the live SLAM node on Cyclone DDS (cmd_slam_ros.cpp).
  void add_ros_options();
  [[nodiscard]] int run_ros() const;
  bool ros_ = false;
  std::string ns_;
  std::uint32_t domain_ = 0;
  bool network_ = false;
  double idle_exit_s_ = 0.0;
  // --save FILE.tsm: the session; --resume FILE.tsm: continue one (cmd_session.cpp).
  void add_session_options();
  /// Usage errors for --resume without a log, --initial-pose without --resume, --autosave-s
  /// without --save.
  [[nodiscard]] Status check_session_options() const;
  /// Writes the session of `scans` (the trajectories that start among them) and `r` to --save;
  /// `options` are the run's (loop closure and odometry: a resumed run takes the session's,
  /// whatever its flags; odometry is off also for a log that has none).
  [[nodiscard]] Status save_session(const std::vector<StampedScan>& scans,
                                    const std::vector<slam::TrajectoryStart>& starts,
                                    const slam::LaserSlamOptions& options,
                                    const slam::LaserSlamResult& r) const;
  /// --autosave-s: saves the session so far every that many seconds of the log's data (not
  /// while a resumed session's own scans are replayed); empty without it.
  [[nodiscard]] slam::AfterScan autosaver(const LaserLog& log,
                                          const std::vector<slam::TrajectoryStart>& starts,
                                          const slam::LaserSlamOptions& options) const;
  double autosave_s_ = 0.0;
  /// The resumed session's scans with `log` after them as a new trajectory, started where the
  /// session's map places the log (--initial-pose, or found by relocalization), and the
  /// session's SLAM settings in `options`. `report` gets what was resumed and how it was placed.
  struct Resumed {
    LaserLog log;
    std::vector<slam::TrajectoryStart> starts;
  };
  [[nodiscard]] Result<Resumed> resume_session(LaserLog log, slam::LaserSlamOptions& options,
                                               nlohmann::json& report) const;
  /// What --resume --save keeps (bounded lifelong mapping, decision 0029): the run `r` of `log`
  /// trimmed and replayed (slam::trim_and_replay). Empty when nothing is trimmed (or
  /// --keep-all-passes). `report` gets what was trimmed.
  [[nodiscard]] Result<std::optional<slam::TrimmedRun>> trim_session(
      const LaserLog& log, const std::vector<slam::TrajectoryStart>& starts,
      slam::LaserSlamOptions options, const slam::LaserSlamResult& r, nlohmann::json& report) const;
  /// The poses a resumed run's relations are scored on: at a stamp that several trajectories
  /// cover (a log resumed again), the newest trajectory's, as the robot's estimate now.
  [[nodiscard]] static std::vector<StampedPose2> newest_poses(
      const std::vector<StampedPose2>& trajectory,
      const std::vector<slam::TrajectoryStart>& starts);
  std::optional<std::filesystem::path> save_;
  std::optional<std::filesystem::path> resume_;
  std::optional<std::string> initial_pose_;  // --resume: "X,Y,THETA" of the log's first scan
  bool keep_all_passes_ = false;             // --resume --save: trim nothing
};

/// tessera session export: a saved session's map, pose graph and trajectory as files
/// (cmd_session.cpp).
class SessionCommand : public Command {
 public:
  explicit SessionCommand(CLI::App& app);
  [[nodiscard]] int run() const;

 private:
  CLI::App* export_ = nullptr;
  std::filesystem::path file_;
  std::filesystem::path out_ = "out/session";
  bool quiet_ = false;
};

/// tessera localize: a robot's pose in a saved session's map, tracked and relocalized without
/// mapping (cmd_localize.cpp; slam/localizer.hpp).
class LocalizeCommand : public Command {
 public:
  explicit LocalizeCommand(CLI::App& app);
  [[nodiscard]] int run() const;

 private:
  std::filesystem::path session_;
  LaserInput input_;
  std::optional<std::string> initial_pose_;  // "X,Y,THETA"
  std::filesystem::path out_ = "out/localize";
  std::optional<std::filesystem::path> relations_;
  double time_offset_s_ = 0.0;
  bool quiet_ = false;
  // --ros: the live localization node on Cyclone DDS (cmd_localize_ros.cpp).
  void add_ros_options();
  [[nodiscard]] int run_ros() const;
  bool ros_ = false;
  std::string ns_;
  std::uint32_t domain_ = 0;
  bool network_ = false;
  double idle_exit_s_ = 0.0;
  /// What both modes read before they localize: --time-offset checked, --initial-pose parsed,
  /// the session (holding scans) and the relations file.
  struct Setup {
    Session session;
    std::optional<Pose2> initial_pose;
    std::optional<std::vector<Relation>> relations;
  };
  [[nodiscard]] Result<Setup> read_setup() const;
  /// Scores, reports and writes a run's outputs (poses.csv, trajectory.txt, localization.png,
  /// report.json with `ros`'s counts when given) and prints its summary; the exit code. `input`
  /// names where the scans came from, `odometry` where their odometry did.
  [[nodiscard]] int write_outputs(const std::vector<slam::LocalizedScan>& scans,
                                  const slam::Localizer& localizer, const std::string& input,
                                  const std::string& odometry, double wall_s, double duration_s,
                                  const std::optional<std::vector<Relation>>& relations,
                                  const nlohmann::json* ros) const;
};

/// tessera fusion: the thesis' Fusion SLAM on RGB-D data (fusion/). One mode per input: --pair DIR
/// (one frame pair's motion or the reason it is refused), --sequence DIR (a TUM RGB-D folder),
/// --world FILE (a simulated run) and --teach-and-repeat --world FILE (thesis Table 5.1).
class FusionCommand : public Command {
 public:
  explicit FusionCommand(CLI::App& app);
  [[nodiscard]] int run() const;

 private:
  enum class Mode { kNone, kPair, kWorld, kTeachAndRepeat, kSequence };
  struct Options {
    std::optional<std::filesystem::path> pair;  // --pair: a frame pair folder
    std::string features = "orb";               // parsed in run(): unknown names are exit 3
    std::string pair_method = "auto";           // --pair: auto, features or depth-icp
    std::filesystem::path out = "out/fusion";
    std::uint64_t seed = 1;
    bool quiet = false;
    // --world / --teach-and-repeat: simulated runs in a floor plan (mission/teach_and_repeat).
    bool teach_and_repeat = false;
    std::optional<std::filesystem::path> sequence;  // --sequence: a TUM RGB-D folder
    int runs = 1;
    std::optional<std::filesystem::path>
        textures;                      // default: <data>/rgbd/rtabmap_loop_samples/images
    std::optional<std::string> start;  // "x,y" metres; default: chosen by --seed
    std::optional<std::string> goal;
    double route_length_m = 9.7;  // the thesis' route: 7.4 m + 2.3 m
    // --teach-and-repeat: the obstacle course (boxes on the route, P3DX body, avoidance) and the
    // repeat stage's navigation.
    int obstacles = 0;
    double drop_frames = 0.0;         // the probability that a frame the SLAM asks for is lost
    std::string navigation = "ours";  // ours (polyline + pure pursuit) or thesis (greedy)
    std::string avoidance = "strip";  // strip (ours), thesis or off
    // The ablation of the cells' claim (issue 18 item 11): where match candidates come from and
    // whether a match must agree with the graph (fusion/fusion_slam.hpp).
    std::string candidates = "cells";  // cells (the thesis) or whole-map (Endres et al. 2014)
    std::string match_gate = "on";     // on (ours) or off (the thesis)
    double duration_s = 600.0;        // --world: the mapping run's time limit
    std::optional<std::filesystem::path> save_sequence;  // --world: the run as a TUM folder
    OutputStreams streams;                               // --world, --sequence: --record, --serve
    // --world: the neck sweeps while the robot drives, fast enough that a firing-field visit
    // (0.3 m at 0.3 m/s) sees several directions, as wide as the teach stage's five capture
    // angles (mission/teach_and_repeat.hpp). Ours; the period is measured in decision 0010.
    double neck_sweep_rad = 1.4;
    double neck_period_s = 3.0;
  };
  struct SimulatedSetup;
  [[nodiscard]] Mode mode() const;
  [[nodiscard]] int run_pair() const;
  [[nodiscard]] Result<SimulatedSetup> load_simulated_setup() const;
  [[nodiscard]] std::string world_label() const;
  [[nodiscard]] nlohmann::json simulated_options_json(const SimulatedSetup& setup,
                                                      const std::string& mode) const;
  [[nodiscard]] nlohmann::json world_json(const World& world) const;
  [[nodiscard]] int run_teach_and_repeat_table() const;
  [[nodiscard]] int run_mapping() const;
  [[nodiscard]] int run_sequence() const;

  Options options_;
  WorldSource world_;
};

/// tessera sim: the simulator as a ROS 2 node over Cyclone DDS (nodes/sim_node.hpp): robots with
/// a lidar and drifting odometry that publish /rN/scan, /rN/odom, /tf, /clock and obey
/// /rN/cmd_vel, paced against the wall clock by --rate.
class SimCommand : public Command {
 public:
  explicit SimCommand(CLI::App& app);
  [[nodiscard]] int run() const;

 private:
  WorldSource world_;
  double resolution_m_ = 0.05;  // the grid the built-in worlds are drawn at
  int robots_ = 1;
  std::vector<std::string> starts_;  // "X,Y[,THETA]" per robot; empty: drawn from --seed
  std::uint64_t seed_ = 1;
  double rate_ = 1.0;        // simulated seconds per wall second; 0: as fast as possible
  double duration_s_ = 0.0;  // simulated; 0: until Ctrl-C or SIGTERM
  std::uint32_t domain_ = 0;
  bool network_ = false;  // all interfaces and multicast discovery instead of loopback only
  bool quiet_ = false;
};

/// tessera team: a team of explorer robots and the simulator as separate processes over DDS
/// (cmd_team.cpp).
class TeamCommand : public Command {
 public:
  explicit TeamCommand(CLI::App& app);
  [[nodiscard]] int run() const;

 private:
  WorldSource world_;
  double resolution_m_ = 0.05;
  int robots_ = 3;
  std::uint64_t seed_ = 1;
  double rate_ = 2.0;
  double max_s_ = 1800.0;
  std::optional<int> kill_robot_;  // 1-based
  std::optional<double> kill_at_coverage_;
  std::optional<double> kill_at_s_;
  std::optional<double> restart_after_s_;
  std::filesystem::path out_ = "out/team";
  std::uint32_t domain_ = 0;
  bool network_ = false;
  bool unknown_starts_ = false;  // robots find each other by map matching
  bool quiet_ = false;
};

/// tessera play: a laser log played as ROS 2 topics over Cyclone DDS (nodes/log_player.hpp),
/// paced by its stamps and --rate, after the first subscriber of the scans has appeared.
class PlayCommand : public Command {
 public:
  explicit PlayCommand(CLI::App& app);
  [[nodiscard]] int run() const;

 private:
  std::filesystem::path log_;
  double rate_ = 1.0;       // 0: as fast as possible
  std::string scan_topic_;  // a bag's topics; empty: its only one
  std::string odom_topic_;
  std::string ns_;
  std::uint32_t domain_ = 0;
  bool network_ = false;
  double wait_s_ = 30.0;  // for the first subscriber
  std::int64_t max_scans_ = 0;
  std::optional<double> from_s_, to_s_;
  bool quiet_ = false;
};

}  // namespace tessera::cli
