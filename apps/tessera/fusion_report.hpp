#pragma once
// The report.json blocks, pictures and summary lines of tessera fusion (cmd_fusion.cpp,
// cmd_fusion_world.cpp, cmd_fusion_sequence.cpp).
#include <Eigen/Geometry>
#include <cstddef>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tessera/core/pose2.hpp"
#include "tessera/core/result.hpp"
#include "tessera/core/stamped_pose2.hpp"
#include "tessera/fusion/feature_type.hpp"
#include "tessera/fusion/frame_pair_match.hpp"
#include "tessera/fusion/fusion_slam.hpp"
#include "tessera/fusion/image_node.hpp"
#include "tessera/fusion/node_matcher.hpp"
#include "tessera/io/rgbd_pair_folder.hpp"
#include "tessera/mission/teach_and_repeat.hpp"
#include "tessera/render/hex_map_svg.hpp"
#include "tessera/sim/world.hpp"

namespace tessera::cli {

nlohmann::json transform_json(const Eigen::Isometry3d& T);
nlohmann::json node_json(const fusion::NodeCreation& c);
nlohmann::json pose_json(const Pose2& p);
/// The SLAM's counters, as both the teach-and-repeat rows and the --world / --sequence reports give
/// them.
nlohmann::json statistics_json(const fusion::FusionStatistics& st);
/// One teach-and-repeat run's row.
nlohmann::json run_json(const TeachAndRepeatRun& r);
nlohmann::json summary_json(const TeachAndRepeatSummary& s);
HexMapPicture picture_of_slam(const fusion::FusionSlam& slam, const World* world);
HexMapPicture picture_of(const TeachAndRepeatResult& result, const World& world);
nlohmann::json slam_json(const fusion::FusionSlam& slam, std::size_t frames, int frames_loaded);
/// The ATE of the corrected trajectory and of odometry alone (eval/drift_correction.hpp).
nlohmann::json trajectory_json(const fusion::FusionSlam& slam,
                               const std::vector<StampedPose2>& truth);
/// The outputs of --world and --sequence: hex_map.svg and .png, trajectory.txt (the corrected
/// trajectory at the graph nodes), truth.txt when there is ground truth, and report.json last.
Status write_slam_outputs(const std::filesystem::path& out, const std::string& svg,
                          const HexMapPicture& picture, const fusion::FusionSlam& slam,
                          const std::vector<StampedPose2>& truth, const nlohmann::json& report);
void print_slam_summary(const std::string& what, fusion::FeatureType type,
                        const fusion::FusionSlam& slam, const nlohmann::json& trajectory,
                        const std::filesystem::path& out, bool wrote_truth);

/// --pair: the "pair" block, whether the pair was accepted, the reason and the summary line's
/// text.
struct PairReport {
  nlohmann::json pair;
  bool accepted = false;
  std::string reason;
  std::string summary;
};
PairReport pair_report(const std::filesystem::path& folder, const RgbdPair& pair,
                       const fusion::FramePairMatch& match);
nlohmann::json pair_options_json(const std::filesystem::path& folder, const RgbdPair& pair,
                                 const fusion::FramePairOptions& options);

}  // namespace tessera::cli
