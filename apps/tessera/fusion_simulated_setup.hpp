#pragma once
// What tessera fusion --world and --teach-and-repeat share (cmd_fusion_world.cpp,
// cmd_fusion_teach.cpp).
#include <cstddef>
#include <filesystem>

#include "commands.hpp"
#include "tessera/core/pose2.hpp"
#include "tessera/core/vec2.hpp"
#include "tessera/fusion/feature_type.hpp"
#include "tessera/mission/teach_and_repeat.hpp"
#include "tessera/sim/rgbd_camera.hpp"

namespace tessera::cli {

// Everything a simulated run needs, read and checked before anything runs or is written.
struct FusionCommand::SimulatedSetup {
  fusion::FeatureType type;
  std::filesystem::path texture_folder;
  std::size_t textures_loaded = 0;
  std::size_t posters = 0;
  RgbdCamera camera;  // holds the world
  Pose2 start;
  Vec2 goal;
  TeachAndRepeatOptions options;
};

}  // namespace tessera::cli
