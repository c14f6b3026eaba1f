#pragma once
// Records a finished Fusion SLAM run (fusion/fusion_slam.hpp) as ROS 2 messages into a
// MessageSink, at the stamps of its pose-graph nodes: /tf (map -> robot0/base_link, the corrected
// pose) at every node; at the last stamp, /path (the corrected trajectory), /odometry_path (the
// same nodes by odometry alone), /truth_path (the ground truth, when given), /hex_cells
// (visualization_msgs/MarkerArray: the hexagonal cells' outlines, rotated with their lattice, and
// their centres) and /image_nodes (the stored image nodes at the poses they were taken from).
#include <span>

#include "tessera/core/result.hpp"
#include "tessera/core/stamped_pose2.hpp"
#include "tessera/fusion/fusion_slam.hpp"
#include "tessera/io/message_sink.hpp"

namespace tessera {

[[nodiscard]] Status record_fusion_run(MessageSink& sink, const fusion::FusionSlam& slam,
                                       std::span<const StampedPose2> truth = {});

}  // namespace tessera
