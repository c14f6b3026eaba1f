#pragma once
// The subcommands. Each registers its options with CLI11 in its constructor and runs with run(),
// which returns the process exit code (0 ok, 2 usage, 3 input, 4 runtime).
#include <CLI/CLI.hpp>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "tessera/eval/trajectory_error.hpp"

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
  WorldSource world_;
  std::string strategy_ = "nearest";
  std::string sensor_ = "cells";
  int robots_ = 1;
  std::uint64_t seed_ = 1;
  std::filesystem::path out_ = "out/explore";
  double resolution_m_ = 0.1;
  std::optional<std::string> start_;
  double lidar_range_m_ = 8.0;
  int lidar_beams_ = 360;
  double range_noise_m_ = 0.01;
  double low_ = 0.5;
  std::int64_t max_steps_ = 0;
  bool quiet_ = false;
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

/// tessera info: describes a map file.
class InfoCommand : public Command {
 public:
  explicit InfoCommand(CLI::App& app);
  [[nodiscard]] int run() const;

 private:
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
  WorldSource world_{std::nullopt, "labyrinth", std::nullopt, std::nullopt};
  double cell_m_ = 0.22;
  std::string variant_ = "trail";
  std::string noise_ = "on";
  std::string localisation_ = "beacons";
  std::uint64_t seed_ = 1;
  std::optional<std::string> start_;
  std::filesystem::path out_ = "out/bob";
  bool quiet_ = false;
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
  int iterations_ = 0;  // set from slam::OptimizeOptions in the constructor
  bool quiet_ = false;
};

/// tessera slam: laser SLAM on a 2D laser log (slam/laser_slam.hpp); writes map, trajectory, pose
/// graph and report.json, and scores the trajectory when given relations.
class SlamCommand : public Command {
 public:
  explicit SlamCommand(CLI::App& app);
  [[nodiscard]] int run() const;

 private:
  std::optional<std::filesystem::path> log_;  // empty: a simulated run in world_
  WorldSource world_;
  std::uint64_t seed_ = 1;
  double duration_s_ = 300.0;
  std::optional<std::string> start_;  // "X,Y" in metres
  std::filesystem::path out_ = "out/slam";
  std::optional<std::filesystem::path> relations_;
  double time_offset_s_ = 0.0;
  std::optional<double> cell_m_;  // default: 0.05 m for a log, the world's cell for a simulated run
  bool no_loop_closure_ = false;
  bool quiet_ = false;
};

}  // namespace tessera::cli
