// The live localization node (nodes/localizer_node.hpp): paired scans in (nodes/scan_input.hpp),
// the localizer in the middle, the frozen map once, pose with covariance and map -> odom out.
#include "tessera/nodes/localizer_node.hpp"

#include "tessera/nodes/pose_outputs.hpp"
#include "tessera/slam/scan_matched_odometry.hpp"

namespace tessera::nodes {
namespace {

using net::Transport;

/// ROS's 6x6 row-major pose covariance (x, y, z, roll, pitch, yaw) of a planar (x, y, yaw) one;
/// the three axes a planar robot does not move in stay 0, as AMCL leaves them.
RosCovariance ros_covariance(const Eigen::Matrix3d& planar) {
  RosCovariance out{};
  constexpr int kAxis[3] = {0, 1, 5};
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      out[static_cast<std::size_t>(kAxis[r] * 6 + kAxis[c])] = planar(r, c);
    }
  }
  return out;
}

}  // namespace

struct LocalizerNode::State {
  LocalizerNodeOptions options;
  Transport& transport;
  std::unique_ptr<ScanInput> input;
  slam::Localizer localizer;
  mutable LocalizerNodeStats stats;  // the input's part is copied in when asked
  std::vector<slam::LocalizedScan> scans;
  PoseOutputs outputs;
  std::unique_ptr<slam::ScanMatchedOdometry> scan_odometry;  // odometry_from_scans

  State(slam::ProbabilityGrid map, const LocalizerNodeOptions& o, Transport& t,
        std::unique_ptr<ScanInput> in, PoseOutputs out)
      : options(o),
        transport(t),
        input(std::move(in)),
        localizer(std::move(map), o.localizer),
        outputs(std::move(out)) {
    if (o.initial_pose) localizer.set_pose(*o.initial_pose);
    if (o.odometry_from_scans) scan_odometry = std::make_unique<slam::ScanMatchedOdometry>();
  }

  // Localizes the next scan whose odometry is known (all that wait, with `flush`); false when
  // none.
  Result<bool> take_next(bool flush) {
    std::optional<ReadyScan> ready = input->next(flush);
    if (!ready) return false;
    // Without odometry the scans make one, and map -> the robot frame is published: T_odom_base
    // is then the identity (the input's odom_frame() is the robot frame).
    Pose2 T_odom_base = ready->scan.odometry;
    if (scan_odometry) {
      Result<Pose2> made = scan_odometry->add(ready->scan);
      if (!made.ok()) return made.error();
      ready->scan.odometry = *made;
      T_odom_base = Pose2{};
    }
    const slam::LocalizedScan& s = scans.emplace_back(localizer.add_scan(ready->scan));
    if (s.state == slam::LocalizationState::kLost) {
      ++stats.scans_lost;
      return true;
    }
    ++stats.scans_localized;
    Eigen::Matrix3d covariance = s.covariance;
    if (!s.confident) {
      ++stats.poses_unsure;
      covariance += Eigen::Vector3d(options.unsure_variance_m2, options.unsure_variance_m2,
                                    options.unsure_variance_rad2)
                        .asDiagonal();
    }
    if (Status p = outputs.publish_pose(ready->stamp_ns, s.T_map_robot, T_odom_base,
                                        input->odom_frame(), ros_covariance(covariance));
        !p.ok()) {
      return p.error();
    }
    return true;
  }
};

LocalizerNode::LocalizerNode(std::unique_ptr<State> state) : state_(std::move(state)) {}
LocalizerNode::~LocalizerNode() = default;

Result<std::unique_ptr<LocalizerNode>> LocalizerNode::create(slam::ProbabilityGrid map,
                                                             const OccupancyGrid& picture,
                                                             const LocalizerNodeOptions& options,
                                                             Transport& transport) {
  if (auto problem = slam::validate(options.localizer)) {
    return usage_error("localizer node: " + *problem);
  }
  if (options.queue_depth == 0 || !(options.unsure_variance_m2 >= 0.0) ||
      !(options.unsure_variance_rad2 >= 0.0)) {
    return usage_error("localizer node: queue_depth must be > 0, unsure_variance_* >= 0");
  }
  if (!options.odometry_from_scans && !options.base_frame.empty()) {
    return usage_error(
        "localizer node: base_frame is for scans alone; with odometry the robot frame is the "
        "odometry's child frame");
  }
  Result<std::unique_ptr<ScanInput>> input =
      ScanInput::create(options.ns,
                        {.queue_depth = options.queue_depth,
                         .use_odometry = !options.odometry_from_scans,
                         .base_frame = options.base_frame},
                        transport);
  if (!input.ok()) return input.error();
  Result<PoseOutputs> outputs = PoseOutputs::advertise(transport, options.ns, options.map_frame);
  if (!outputs.ok()) return outputs.error();
  // Transient local: published once, kept for every reader that joins later.
  if (Status s = outputs->publish_map(picture, 0); !s.ok()) return s.error();
  auto state = std::make_unique<State>(std::move(map), options, transport, std::move(input).value(),
                                       std::move(outputs).value());
  return std::unique_ptr<LocalizerNode>(new LocalizerNode(std::move(state)));
}

Result<int> LocalizerNode::spin_once() {
  state_->transport.poll();
  int taken = 0;
  for (;;) {
    Result<bool> progressed = state_->take_next(false);
    if (!progressed.ok()) return progressed.error();
    if (!*progressed) return taken;
    ++taken;
  }
}

Status LocalizerNode::finish() {
  state_->transport.poll();
  for (;;) {
    Result<bool> progressed = state_->take_next(true);
    if (!progressed.ok()) return progressed.error();
    if (!*progressed) return Ok{};
  }
}

const std::vector<slam::LocalizedScan>& LocalizerNode::scans() const { return state_->scans; }
const LocalizerNodeStats& LocalizerNode::stats() const {
  static_cast<ScanInputStats&>(state_->stats) = state_->input->stats();
  return state_->stats;
}
const slam::Localizer& LocalizerNode::localizer() const { return state_->localizer; }

}  // namespace tessera::nodes
