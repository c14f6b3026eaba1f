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

}  // namespace tessera::cli
