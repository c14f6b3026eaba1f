// The live SLAM node (nodes/slam_node.hpp): topics in, LaserSlam in the middle, map, pose and
// map -> odom out.
#include "tessera/nodes/slam_node.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <deque>
#include <limits>
#include <vector>

#include "tessera/core/pose_interpolation.hpp"
#include "tessera/io/robot_bag.hpp"
#include "tessera/io/ros_message_encoders.hpp"
#include "tessera/io/tf_tree.hpp"
#include "tessera/net/ros_names.hpp"
#include "tessera/record/ros_conversions.hpp"

namespace tessera::nodes {
namespace {

using net::Qos;
using net::Transport;
using SteadyClock = std::chrono::steady_clock;

double seconds(std::int64_t ns) { return 1e-9 * static_cast<double>(ns); }

bool finite(const RosTransform& t) {
  for (const double v : {t.x_m, t.y_m, t.z_m, t.qx, t.qy, t.qz, t.qw}) {
    if (!std::isfinite(v)) return false;
  }
  return true;
}

}  // namespace

struct SlamNode::State {
  struct PendingScan {
    std::int64_t t_ns = 0;
    std::string frame;
    RangeScan scan;
    // An odometry message at or after t_ns arrived after this scan did: the odometry around it
    // is in. (A log's stamps may go backwards, so older odometry with later stamps says nothing.)
    bool odometry_passed = false;
    SteadyClock::time_point received{};  // when it came off the transport
  };

  SlamNodeOptions options;
  Transport& transport;
  slam::LaserSlam slam;
  SlamNodeStats stats;
  std::deque<PendingScan> pending;
  std::vector<PoseAtNs>
      odometry;  // T_odom_base  // by stamp; entries older than the last added scan are pruned
  std::string odom_frame, base_frame;
  TfTree tf;
  Transport::WriterId map_writer = 0, tf_writer = 0, pose_writer = 0;
  SteadyClock::time_point last_map{};
  std::int64_t last_map_stamp_ns = 0;
  bool started = false;
  std::optional<OccupancyGrid> last_map_grid;
  // Receipt times of the scans added since the last map, and per scan the wall time from its
  // receipt to the publication of the first map that holds it (the first kLatenciesKept).
  static constexpr std::size_t kLatenciesKept = 1'000'000;
  std::vector<SteadyClock::time_point> unmapped;
  std::vector<double> map_latencies_s;
  Pose2 T_map_odom;

  State(const SlamNodeOptions& o, Transport& t) : options(o), transport(t), slam(o.slam) {}

  Status connect() {
    Result<std::string> scan_topic = net::resolve_topic_name("scan", options.ns);
    if (!scan_topic.ok()) return scan_topic.error();
    const std::string odom_topic = *net::resolve_topic_name("odom", options.ns);
    const std::string map_topic = *net::resolve_topic_name("map", options.ns);
    // Best effort matches any driver's publisher; the deep queue holds what SLAM has not read.
    const Qos sensors{Qos::Reliability::kBestEffort, Qos::Durability::kVolatile,
                      options.queue_depth};
    if (Status s = transport.listen({*scan_topic, std::string(kRos2LaserScan), sensors},
                                    [this](auto cdr) { on_scan(cdr); });
        !s.ok()) {
      return s;
    }
    if (Status s = transport.listen({odom_topic, std::string(kRos2Odometry), sensors},
                                    [this](auto cdr) { on_odom(cdr); });
        !s.ok()) {
      return s;
    }
    if (Status s = transport.listen({"/tf_static", std::string(kRos2TfMessage), Qos::tf_static()},
                                    [this](auto cdr) { on_tf(cdr, true); });
        !s.ok()) {
      return s;
    }
    if (Status s = transport.listen({"/tf", std::string(kRos2TfMessage), Qos::tf()},
                                    [this](auto cdr) { on_tf(cdr, false); });
        !s.ok()) {
      return s;
    }
    const std::string pose_topic = *net::resolve_topic_name("pose", options.ns);
    for (Status st :
         {transport.advertise({map_topic, std::string(kRos2OccupancyGrid), Qos::map()}, map_writer),
          transport.advertise({"/tf", std::string(kRos2TfMessage), Qos::tf()}, tf_writer),
          transport.advertise(
              {pose_topic, std::string(kRos2PoseWithCovarianceStamped), Qos::reliable(10)},
              pose_writer)}) {
      if (!st.ok()) return st;
    }
    return Ok{};
  }

  void on_scan(std::span<const std::uint8_t> cdr) {
    ++stats.scans_received;
    Result<LaserScanMessage> m = decode_laser_scan(cdr, RosEncoding::kCdr);
    int no_return = 0;
    Result<RangeScan> scan = m.ok() ? range_scan_of(*m, no_return) : Result<RangeScan>(m.error());
    if (!scan.ok()) {
      ++stats.scans_dropped_invalid;
      return;
    }
    // REP-117: +inf (and beyond range_max) is "nothing seen", a no-return that clears free space;
    // NaN is an erroneous reading and a negative range is none at all. Those are not used (a range
    // of 0 is below every minimum range) and are counted; a scan with nothing else is dropped.
    std::size_t erroneous = 0;
    for (std::size_t i = 0; i < m->ranges_m.size(); ++i) {
      const float r = m->ranges_m[i];
      if (std::isnan(r) || r < 0.0F) {
        scan->ranges_m[i] = 0.0;
        ++erroneous;
      }
    }
    stats.readings_dropped_invalid += erroneous;
    if (erroneous == m->ranges_m.size()) {
      ++stats.scans_dropped_invalid;
      return;
    }
    if (pending.size() >= options.queue_depth) {
      pending.pop_front();
      ++stats.scans_dropped_overflow;
    }
    pending.push_back({m->header.stamp_ns, std::string(tf_frame_name(m->header.frame_id)),
                       std::move(*scan), false, SteadyClock::now()});
  }

  void on_odom(std::span<const std::uint8_t> cdr) {
    Result<OdometryMessage> m = decode_odometry(cdr, RosEncoding::kCdr);
    if (!m.ok() || !finite(m->pose)) {
      ++stats.odometry_dropped_invalid;
      return;
    }
    ++stats.odometry_received;
    if (odom_frame.empty()) {
      odom_frame = tf_frame_name(m->header.frame_id);
      base_frame = tf_frame_name(m->child_frame_id);
    }
    const PoseAtNs o{m->header.stamp_ns, planar_pose(m->pose)};
    for (PendingScan& p : pending) p.odometry_passed = p.odometry_passed || o.t_ns >= p.t_ns;
    // Messages arrive in stamp order from one publisher; an older one is put in its place.
    const auto at = std::upper_bound(odometry.begin(), odometry.end(), o.t_ns,
                                     [](std::int64_t t, const PoseAtNs& x) { return t < x.t_ns; });
    odometry.insert(at, o);
    prune_odometry();
  }

  void on_tf(std::span<const std::uint8_t> cdr, bool is_static) {
    Result<TfMessage> m = decode_tf_message(cdr, RosEncoding::kCdr);
    if (!m.ok()) return;
    for (const TransformStampedMessage& t : m->transforms) {
      if (finite(t.transform)) tf.add(t, is_static);
    }
  }

  [[nodiscard]] bool has_odometry_at(std::int64_t t_ns) const {
    return std::binary_search(odometry.begin(), odometry.end(), PoseAtNs{t_ns, {}},
                              [](const PoseAtNs& a, const PoseAtNs& b) { return a.t_ns < b.t_ns; });
  }

  // T_base_laser of a scan frame, if the tf tree knows it.
  [[nodiscard]] std::optional<Pose2> laser_in_robot(const PendingScan& s) const {
    if (s.frame == base_frame) return Pose2{};
    Result<RosTransform> T = tf.lookup(base_frame, s.frame, s.t_ns);
    if (!T.ok()) return std::nullopt;
    return planar_pose(*T);
  }

  // Adds the oldest pending scan if its odometry has arrived (or `flush`); false otherwise.
  Result<bool> add_next(bool flush) {
    if (pending.empty()) return false;
    const PendingScan& s = pending.front();
    const bool odometry_known =
        !odometry.empty() && (flush || s.odometry_passed || has_odometry_at(s.t_ns));
    if (!odometry_known) {
      if (!flush) return false;
      ++stats.scans_dropped_no_pose;
      pending.pop_front();
      return true;
    }
    const std::optional<Pose2> laser = laser_in_robot(s);
    if (!laser) {
      if (!flush && pending.size() < options.queue_depth) return false;  // tf may come
      ++stats.scans_dropped_no_pose;
      pending.pop_front();
      return true;
    }
    StampedScan scan{seconds(s.t_ns), pose_at(odometry, s.t_ns), *laser, s.scan};
    if (Status added = slam.add_scan(scan); !added.ok()) return added.error();
    ++stats.scans_added;
    started = true;
    unmapped.push_back(s.received);
    if (Status p = publish_pose(s.t_ns, scan.odometry); !p.ok()) return p.error();
    prune_odometry();
    pending.pop_front();
    return true;
  }

  // Odometry goes once no waiting scan can need it: older than every pending scan and than the
  // newest message by kOdometryKept_ns (a log's stamps go backwards by up to about a second, so a
  // scan still to come may need a message older than the scan just added). Memory stays bounded
  // by the wait queue and that window, however far SLAM falls behind.
  void prune_odometry() {
    constexpr std::int64_t kOdometryKept_ns = 10'000'000'000;
    std::int64_t oldest = 0;  // a peer's stamps may be anything: no signed overflow
    if (__builtin_sub_overflow(odometry.back().t_ns, kOdometryKept_ns, &oldest)) {
      oldest = std::numeric_limits<std::int64_t>::min();
    }
    for (const PendingScan& p : pending) oldest = std::min(oldest, p.t_ns);
    const auto keep =
        std::lower_bound(odometry.begin(), odometry.end(), oldest,
                         [](const PoseAtNs& o, std::int64_t v) { return o.t_ns < v; });
    if (keep - odometry.begin() > 1) odometry.erase(odometry.begin(), keep - 1);
  }

  Status publish_pose(std::int64_t stamp_ns, const Pose2& T_odom_base) {
    const Pose2 T_map_base = slam.latest_pose();
    PoseWithCovarianceStampedMessage pose;
    pose.header = {stamp_ns, options.map_frame};
    pose.pose = planar_transform(T_map_base.x, T_map_base.y, T_map_base.theta);
    if (Status s = transport.publish(pose_writer, encode_cdr(pose)); !s.ok()) return s;
    T_map_odom = T_map_base * T_odom_base.inverse();
    TfMessage map_to_odom;
    map_to_odom.transforms.push_back(
        planar_transform_stamped(T_map_odom, stamp_ns, options.map_frame, odom_frame));
    return transport.publish(tf_writer, encode_cdr(map_to_odom));
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
    return transport.publish(map_writer, encode_cdr(occupancy_grid_message(*last_map_grid, stamp_ns,
                                                                           options.map_frame)));
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
  auto state = std::make_unique<State>(options, transport);
  if (Status s = state->connect(); !s.ok()) return s.error();
  return std::unique_ptr<SlamNode>(new SlamNode(std::move(state)));
}

Result<int> SlamNode::spin_once() {
  State& s = *state_;
  s.transport.poll();
  int added = 0;
  std::int64_t last_stamp = 0;
  for (;;) {
    const std::int64_t stamp = s.pending.empty() ? 0 : s.pending.front().t_ns;
    Result<bool> progressed = s.add_next(false);
    if (!progressed.ok()) return progressed.error();
    if (!*progressed) break;
    last_stamp = stamp;
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
  if (!s.started) return input_error("slam node: no scan with odometry arrived");
  Result<slam::LaserSlamResult> result = s.slam.finish();
  if (!result.ok()) return result;
  const std::int64_t stamp = result->trajectory.empty() ? 0 : to_ns(result->trajectory.back().t_s);
  if (Status m = s.publish_map(stamp, result->map); !m.ok()) return m.error();
  return result;
}

const SlamNodeStats& SlamNode::stats() const { return state_->stats; }
bool SlamNode::started() const { return state_->started; }
const OccupancyGrid* SlamNode::map() const {
  return state_->last_map_grid ? &*state_->last_map_grid : nullptr;
}
Pose2 SlamNode::T_map_odom() const { return state_->T_map_odom; }
const std::vector<double>& SlamNode::map_latencies_s() const { return state_->map_latencies_s; }
std::optional<PoseAtNs> SlamNode::latest_odometry() const {
  if (state_->odometry.empty()) return std::nullopt;
  return state_->odometry.back();
}

}  // namespace tessera::nodes
