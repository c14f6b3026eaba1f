#pragma once
// The report.json blocks and output files of tessera slam (cmd_slam.cpp).
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tessera/core/pose2.hpp"
#include "tessera/core/result.hpp"
#include "tessera/core/stamped_pose2.hpp"
#include "tessera/eval/drift_correction.hpp"
#include "tessera/eval/map_accuracy.hpp"
#include "tessera/eval/relation_metric.hpp"
#include "tessera/io/robot_bag.hpp"
#include "tessera/sensors/laser_log.hpp"
#include "tessera/sim/laser_run.hpp"
#include "tessera/sim/world.hpp"
#include "tessera/slam/laser_slam.hpp"

namespace tessera::cli {

/// Stamps may go backwards in real logs: the span is max - min.
double data_duration_s(const LaserLog& log);
/// The scans' odometry poses as a trajectory.
std::vector<StampedPose2> odometry_trajectory(const LaserLog& log);

nlohmann::json slam_options_json(const slam::LaserSlamOptions& options,
                                 const std::string& input_kind, const std::string& input_name);
nlohmann::json slam_stats_json(const slam::LaserSlamResult& r, const LaserLog& log);
/// --bag: the topics and frames read.
nlohmann::json bag_json(const RobotBag& bag);
nlohmann::json simulation_json(const SimulatedLaserRun& run, const World& world,
                               const LaserRunOptions& options);
nlohmann::json ate_json(const DriftCorrectionScore& score);
nlohmann::json map_accuracy_json(const MapAccuracy& m, const Pose2& T_truth_map);

/// "relations: N scored; translation ... m, rotation ... deg" on stdout.
void print_relations_summary(const RelationMetric& metric);

/// map.yaml + map.pgm, map.png (map errors in colour when `world` is given, the map placed by
/// T_truth_map), trajectory.txt, graph.g2o, report.json, and for a simulated run truth.txt and
/// odometry.txt; each file atomically.
Status write_laser_slam_outputs(const std::filesystem::path& out, const slam::LaserSlamResult& r,
                                const nlohmann::json& report, const World* world,
                                const Pose2& T_truth_map, const SimulatedLaserRun* simulated);

}  // namespace tessera::cli
