// A robot's scans and odometry from topics, paired (nodes/scan_input.hpp).
#include "tessera/nodes/scan_input.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <vector>

#include "tessera/io/robot_bag.hpp"
#include "tessera/io/ros_message_encoders.hpp"
#include "tessera/io/tf_tree.hpp"
#include "tessera/net/ros_names.hpp"
#include "tessera/record/ros_conversions.hpp"
#include "tessera/sensors/range_scan.hpp"
#include "tessera/sensors/scan_sweep.hpp"

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

struct ScanInput::State {
  struct PendingScan {
    std::int64_t t_ns = 0;
    std::string frame;
    RangeScan scan;
    // An odometry message at or after its last beam's time arrived after this scan did: the
    // odometry around it is in. (A log's stamps may go backwards, so older odometry with later
    // stamps says nothing.)
    bool odometry_passed = false;
    std::int64_t last_beam_ns = 0;  // t_ns, or later when its beams were swept one by one
    SteadyClock::time_point received{};
  };

  std::uint32_t queue_depth;
  bool use_odometry;
  ScanInputStats stats;
  std::deque<PendingScan> pending;
  std::vector<PoseAtNs> odometry;  // T_odom_base by stamp, pruned (prune_odometry)
  std::string odom_frame, base_frame;
  TfTree tf;

  explicit State(const ScanInputOptions& o)
      : queue_depth(o.queue_depth), use_odometry(o.use_odometry), base_frame(o.base_frame) {}

  Status connect(const std::string& ns, Transport& transport) {
    Result<std::string> scan_topic = net::resolve_topic_name("scan", ns);
    if (!scan_topic.ok()) return scan_topic.error();
    const std::string odom_topic = *net::resolve_topic_name("odom", ns);
    // Best effort matches any driver's publisher; the deep queue holds what the caller has not
    // read.
    const Qos sensors{Qos::Reliability::kBestEffort, Qos::Durability::kVolatile, queue_depth};
    for (Status s : {transport.listen({*scan_topic, std::string(kRos2LaserScan), sensors},
                                      [this](auto cdr) { on_scan(cdr); }),
                     transport.listen({"/tf_static", std::string(kRos2TfMessage), Qos::tf_static()},
                                      [this](auto cdr) { on_tf(cdr, true); }),
                     transport.listen({"/tf", std::string(kRos2TfMessage), Qos::tf()},
                                      [this](auto cdr) { on_tf(cdr, false); })}) {
      if (!s.ok()) return s;
    }
    if (!use_odometry) return Ok{};
    return transport.listen({odom_topic, std::string(kRos2Odometry), sensors},
                            [this](auto cdr) { on_odom(cdr); });
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
    if (pending.size() >= queue_depth) {
      pending.pop_front();
      ++stats.scans_dropped_overflow;
    }
    const std::size_t last = scan->ranges_m.size() - 1;  // not empty: it has a usable reading
    const double last_beam_s = std::max({0.0, beam_time_s(*scan, 0), beam_time_s(*scan, last)});
    const std::int64_t stamp_ns = m->header.stamp_ns;
    pending.push_back({stamp_ns, std::string(tf_frame_name(m->header.frame_id)), std::move(*scan),
                       false, stamp_ns + std::llround(last_beam_s * 1e9), SteadyClock::now()});
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
    for (PendingScan& p : pending) {
      p.odometry_passed = p.odometry_passed || o.t_ns >= p.last_beam_ns;
    }
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

  // The robot frame of a scan: the odometry's child frame; without odometry the one asked for,
  // or the laser's own.
  [[nodiscard]] const std::string& robot_frame(const PendingScan& s) const {
    return !use_odometry && base_frame.empty() ? s.frame : base_frame;
  }

  // T_base_laser of a scan frame (and whether the laser is upside down), if the tf tree knows it.
  [[nodiscard]] std::optional<PlanarLaser> laser_in_robot(const PendingScan& s) const {
    const std::string& base = robot_frame(s);
    if (s.frame == base) return PlanarLaser{};
    Result<RosTransform> T = tf.lookup(base, s.frame, s.t_ns);
    if (!T.ok()) return std::nullopt;
    return planar_laser(*T);
  }

  // Odometry goes once no waiting scan can need it: older than every pending scan and than the
  // newest message by kOdometryKept_ns (a log's stamps go backwards by up to about a second, so a
  // scan still to come may need a message older than the scan just taken). Memory stays bounded
  // by the wait queue and that window, however far the caller falls behind.
  void prune_odometry() {
    if (odometry.empty()) return;
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
};

ScanInput::ScanInput(std::unique_ptr<State> state) : state_(std::move(state)) {}
ScanInput::~ScanInput() = default;

Result<std::unique_ptr<ScanInput>> ScanInput::create(const std::string& ns,
                                                     const ScanInputOptions& options,
                                                     net::Transport& transport) {
  auto state = std::make_unique<State>(options);
  if (Status s = state->connect(ns, transport); !s.ok()) return s.error();
  return std::unique_ptr<ScanInput>(new ScanInput(std::move(state)));
}

std::optional<ReadyScan> ScanInput::next(bool flush) {
  State& s = *state_;
  while (!s.pending.empty()) {
    const State::PendingScan& p = s.pending.front();
    const bool odometry_known =
        !s.use_odometry ||
        (!s.odometry.empty() && (flush || p.odometry_passed || s.has_odometry_at(p.last_beam_ns)));
    if (!odometry_known && !flush) return std::nullopt;
    const std::optional<PlanarLaser> laser = odometry_known ? s.laser_in_robot(p) : std::nullopt;
    if (odometry_known && !laser && !flush && s.pending.size() < s.queue_depth) {
      return std::nullopt;  // the laser's transform may still come
    }
    if (!laser) {
      ++s.stats.scans_dropped_no_pose;
      s.pending.pop_front();
      continue;
    }
    if (!s.use_odometry) s.odom_frame = s.robot_frame(p);
    const Pose2 T_odom_base = s.use_odometry ? pose_at(s.odometry, p.t_ns) : Pose2{};
    const Twist2 velocity = !s.use_odometry ? Twist2{} : sweep_velocity(p.scan, [&](double dt_s) {
      return pose_at(s.odometry, p.t_ns + std::llround(dt_s * 1e9));
    });
    ReadyScan ready{StampedScan{seconds(p.t_ns), T_odom_base, laser->T_base_laser,
                                laser->upside_down ? mirrored(p.scan) : p.scan, velocity},
                    p.t_ns, p.received};
    s.prune_odometry();  // while this scan still waits: it keeps the odometry around it
    s.pending.pop_front();
    return ready;
  }
  return std::nullopt;
}

const ScanInputStats& ScanInput::stats() const { return state_->stats; }
const std::string& ScanInput::odom_frame() const { return state_->odom_frame; }
std::optional<PoseAtNs> ScanInput::latest_odometry() const {
  if (state_->odometry.empty()) return std::nullopt;
  return state_->odometry.back();
}

}  // namespace tessera::nodes
