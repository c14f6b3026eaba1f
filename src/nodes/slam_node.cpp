// The live SLAM node (nodes/slam_node.hpp): paired scans in (nodes/scan_input.hpp), LaserSlam in
// the middle, map, pose and map -> odom out.
#include "tessera/nodes/slam_node.hpp"

#include <chrono>
#include <string>
#include <vector>

#include "tessera/nodes/pose_outputs.hpp"
#include "tessera/record/ros_conversions.hpp"

namespace tessera::nodes {
namespace {

using net::Transport;
using SteadyClock = std::chrono::steady_clock;

double seconds(std::int64_t ns) { return 1e-9 * static_cast<double>(ns); }

}  // namespace

struct SlamNode::State {
  SlamNodeOptions options;
  Transport& transport;
  std::unique_ptr<ScanInput> input;
  slam::LaserSlam slam;
  mutable SlamNodeStats stats;  // the input's part is copied in when asked
  PoseOutputs outputs;
  SteadyClock::time_point last_map{};
  std::int64_t last_map_stamp_ns = 0;
  bool started = false;
  std::int64_t last_added_stamp_ns = 0;
  std::optional<OccupancyGrid> last_map_grid;
  // Receipt times of the scans added since the last map, and per scan the wall time from its
  // receipt to the publication of the first map that holds it (the first kLatenciesKept).
  static constexpr std::size_t kLatenciesKept = 1'000'000;
  std::vector<SteadyClock::time_point> unmapped;
  std::vector<double> map_latencies_s;
  Pose2 T_map_odom;

  State(const SlamNodeOptions& o, Transport& t, std::unique_ptr<ScanInput> in, PoseOutputs out)
      : options(o), transport(t), input(std::move(in)), slam(o.slam), outputs(std::move(out)) {}

  // Adds the next scan whose odometry is known (all that wait, with `flush`); false when none.
  Result<bool> add_next(bool flush) {
    std::optional<ReadyScan> ready = input->next(flush);
    if (!ready) return false;
    if (Status added = slam.add_scan(ready->scan); !added.ok()) return added.error();
    ++stats.scans_added;
    last_added_stamp_ns = ready->stamp_ns;
    started = true;
    unmapped.push_back(ready->received);
    const Pose2 T_map_base = slam.latest_pose();
    T_map_odom = T_map_base * ready->scan.odometry.inverse();
    if (Status p = outputs.publish_pose(ready->stamp_ns, T_map_base, ready->scan.odometry,
                                        input->odom_frame());
        !p.ok()) {
      return p.error();
    }
    return true;
  }

  Status publish_map(std::int64_t stamp_ns, OccupancyGrid map) {
    last_map = SteadyClock::now();
    for (const SteadyClock::time_point t : unmapped) {
      if (map_latencies_s.size() < kLatenciesKept) {
        map_latencies_s.push_back(std::chrono::duration<double>(last_map - t).count());
      }
    }
    unmapped.clear();
    last_map_stamp_ns = stamp_ns;
    ++stats.maps_published;
    last_map_grid = std::move(map);
    return outputs.publish_map(*last_map_grid, stamp_ns);
  }

  [[nodiscard]] bool map_due(std::int64_t stamp_ns) const {
    if (options.map_period_stamp_s > 0.0 && started &&
        seconds(stamp_ns) - seconds(last_map_stamp_ns) >= options.map_period_stamp_s) {
      return true;
    }
    return started && (stats.maps_published == 0 ||
                       SteadyClock::now() - last_map >=
                           std::chrono::duration<double>(options.map_period_wall_s));
  }
};

SlamNode::SlamNode(std::unique_ptr<State> state) : state_(std::move(state)) {}
SlamNode::~SlamNode() = default;

Result<std::unique_ptr<SlamNode>> SlamNode::create(const SlamNodeOptions& options,
                                                   Transport& transport) {
  if (auto problem = slam::validate(options.slam)) return usage_error("slam node: " + *problem);
  if (!(options.map_period_wall_s > 0.0) || !(options.map_period_stamp_s >= 0.0) ||
      options.queue_depth == 0) {
    return usage_error(
        "slam node: map_period_wall_s and queue_depth must be > 0, map_period_stamp_s >= 0");
  }
  if (options.slam.use_odometry && !options.base_frame.empty()) {
    return usage_error(
        "slam node: base_frame is for scans alone; with odometry the robot frame is the "
        "odometry's child frame");
  }
  Result<std::unique_ptr<ScanInput>> input =
      ScanInput::create(options.ns,
                        {.queue_depth = options.queue_depth,
                         .use_odometry = options.slam.use_odometry,
                         .base_frame = options.base_frame},
                        transport);
  if (!input.ok()) return input.error();
  Result<PoseOutputs> outputs = PoseOutputs::advertise(transport, options.ns, options.map_frame);
  if (!outputs.ok()) return outputs.error();
  auto state = std::make_unique<State>(options, transport, std::move(input).value(),
                                       std::move(outputs).value());
  return std::unique_ptr<SlamNode>(new SlamNode(std::move(state)));
}

Result<int> SlamNode::spin_once() {
  State& s = *state_;
  s.transport.poll();
  int added = 0;
  std::int64_t last_stamp = 0;
  for (;;) {
    Result<bool> progressed = s.add_next(false);
    if (!progressed.ok()) return progressed.error();
    if (!*progressed) break;
    last_stamp = s.last_added_stamp_ns;
    ++added;
    if (s.map_due(last_stamp)) {
      if (Status m = s.publish_map(last_stamp, s.slam.current_map()); !m.ok()) return m.error();
    }
  }
  return added;
}

Result<slam::LaserSlamResult> SlamNode::finish() {
  State& s = *state_;
  s.transport.poll();
  for (;;) {
    Result<bool> progressed = s.add_next(true);
    if (!progressed.ok()) return progressed.error();
    if (!*progressed) break;
  }
  if (!s.started) {
    const ScanInputStats& in = s.input->stats();
    if (!s.options.slam.use_odometry) return input_error("slam node: no scan arrived");
    if (in.scans_received > 0 && in.odometry_received == 0) {
      return input_error("slam node: no scan with odometry arrived (" +
                         std::to_string(in.scans_received) +
                         " scans and no odometry: a robot without odometry is mapped from its "
                         "scans alone)");
    }
    return input_error("slam node: no scan with odometry arrived");
  }
  Result<slam::LaserSlamResult> result = s.slam.finish();
  if (!result.ok()) return result;
  const std::int64_t stamp = result->trajectory.empty() ? 0 : to_ns(result->trajectory.back().t_s);
  if (Status m = s.publish_map(stamp, result->map); !m.ok()) return m.error();
  return result;
}

const SlamNodeStats& SlamNode::stats() const {
  static_cast<ScanInputStats&>(state_->stats) = state_->input->stats();
  return state_->stats;
}
bool SlamNode::started() const { return state_->started; }
const OccupancyGrid* SlamNode::map() const {
  return state_->last_map_grid ? &*state_->last_map_grid : nullptr;
}
Pose2 SlamNode::T_map_odom() const { return state_->T_map_odom; }
const std::string& SlamNode::odom_frame() const { return state_->input->odom_frame(); }
const std::vector<double>& SlamNode::map_latencies_s() const { return state_->map_latencies_s; }
std::optional<PoseAtNs> SlamNode::latest_odometry() const {
  return state_->input->latest_odometry();
}

}  // namespace tessera::nodes
