#pragma once
// Records a finished Fusion SLAM run (fusion/fusion_slam.hpp) as ROS 2 messages into a
// MessageSink, at the stamps of its pose-graph nodes: /tf (map -> robot0/base_link, the corrected
// pose) at every node; at the last stamp, /path (the corrected trajectory), /odometry_path (the
// same nodes by odometry alone), /truth_path (the ground truth, when given), /hex_cells
// (visualization_msgs/MarkerArray: the hexagonal cells' outlines, rotated with their lattice, and
// their centres) and /image_nodes (the stored image nodes at the poses they were taken from).
// Teach-and-repeat runs add their stages' paths.
#include <span>

#include "tessera/core/result.hpp"
#include "tessera/core/stamped_pose2.hpp"
#include "tessera/fusion/fusion_slam.hpp"
#include "tessera/io/message_sink.hpp"
#include "tessera/mission/teach_and_repeat.hpp"

namespace tessera {

/// Every stamp is moved by `time_offset_ns` (runs recorded one after another).
[[nodiscard]] Status record_fusion_run(MessageSink& sink, const fusion::FusionSlam& slam,
                                       std::span<const StampedPose2> truth = {},
                                       std::int64_t time_offset_ns = 0);

/// One teach-and-repeat run (mission/teach_and_repeat.hpp) after it ended: its Fusion SLAM as
/// record_fusion_run gives it, then at the run's end /taught_path and /repeated_path (the
/// estimates while teaching and repeating), /truth_path (the true path of both stages) and /tf at
/// the true final pose. Stamps are moved by `time_offset_ns`.
[[nodiscard]] Status record_teach_and_repeat(MessageSink& sink, const TeachAndRepeatResult& result,
                                             std::int64_t time_offset_ns);

}  // namespace tessera
