// The evaluator's view of a team (nodes/team_observer.hpp).
#include "tessera/nodes/team_observer.hpp"

#include "tessera/io/ros_messages.hpp"
#include "tessera/io/tf_tree.hpp"
#include "tessera/team/map_merge.hpp"

namespace tessera::nodes {
namespace {

using net::Qos;

double seconds(std::int64_t ns) { return 1e-9 * static_cast<double>(ns); }

}  // namespace

struct TeamObserver::State {
  net::Transport& transport;
  team::MapMerger merger;
  std::map<std::string, TeamObserverRobot> robots;
  std::map<std::string, Pose2> T_team_map;
  std::uint64_t maps_dropped = 0;
  bool map_update = false;
  double sim_time_s = 0.0;

  State(net::Transport& t, double resolution_m) : transport(t), merger(resolution_m) {}

  Status connect(const std::vector<TeamMember>& team) {
    for (const TeamMember& m : team) {
      robots[m.name];
      if (!m.T_team_map) return usage_error("team observer: the start pose of " + m.name);
      T_team_map[m.name] = *m.T_team_map;
      const std::string ns = "/" + m.name;
      for (Status s : {transport.listen({ns + "/map", std::string(kRos2OccupancyGrid), Qos::map()},
                                        [this, n = m.name](auto c) { on_map(n, c); }),
                       transport.listen({ns + "/pose", std::string(kRos2PoseWithCovarianceStamped),
                                         Qos::reliable(100)},
                                        [this, n = m.name](auto c) { on_pose(n, c); }),
                       transport.listen({"/sim" + ns + "/ground_truth", std::string(kRos2Odometry),
                                         Qos::reliable(100)},
                                        [this, n = m.name](auto c) { on_truth(n, c); })}) {
        if (!s.ok()) return s;
      }
    }
    const Qos status_qos{Qos::Reliability::kReliable, Qos::Durability::kTransientLocal, 64};
    if (Status s = transport.listen({"/team/status", std::string(kRos2RobotStatus), status_qos},
                                    [this](auto c) { on_status(c); });
        !s.ok()) {
      return s;
    }
    return transport.listen({"/clock", std::string(kRos2Clock), Qos::clock()}, [this](auto c) {
      if (Result<ClockMessage> m = decode_cdr_clock(c); m.ok()) sim_time_s = seconds(m->clock_ns);
    });
  }

  void on_map(const std::string& robot, std::span<const std::uint8_t> cdr) {
    Result<OccupancyGridMessage> m = decode_cdr_occupancy_grid(cdr);
    if (!m.ok() || !merger.update(robot, *m, T_team_map.at(robot)).ok()) {
      ++maps_dropped;
      return;
    }
    TeamObserverRobot& r = robots.at(robot);
    ++r.maps_received;
    r.map_bytes_received += cdr.size();
    map_update = true;
  }

  void on_pose(const std::string& robot, std::span<const std::uint8_t> cdr) {
    Result<PoseWithCovarianceStampedMessage> m = decode_cdr_pose_with_covariance_stamped(cdr);
    if (!m.ok()) return;
    robots.at(robot).slam.push_back(
        {seconds(m->header.stamp_ns), T_team_map.at(robot) * planar_pose(m->pose)});
  }

  void on_truth(const std::string& robot, std::span<const std::uint8_t> cdr) {
    Result<OdometryMessage> m = decode_odometry(cdr, RosEncoding::kCdr);
    if (!m.ok()) return;
    robots.at(robot).truth.push_back({seconds(m->header.stamp_ns), planar_pose(m->pose)});
  }

  void on_status(std::span<const std::uint8_t> cdr) {
    Result<RobotStatusMessage> m = decode_cdr_robot_status(cdr);
    if (!m.ok()) return;
    const auto it = robots.find(m->robot_id);
    if (it != robots.end()) it->second.status = std::move(*m);
  }
};

TeamObserver::TeamObserver(std::unique_ptr<State> state) : state_(std::move(state)) {}
TeamObserver::~TeamObserver() = default;

Result<std::unique_ptr<TeamObserver>> TeamObserver::create(const std::vector<TeamMember>& team,
                                                           double resolution_m,
                                                           net::Transport& transport) {
  if (!(resolution_m > 0.0)) return usage_error("team observer: resolution_m must be > 0");
  auto state = std::make_unique<State>(transport, resolution_m);
  if (Status s = state->connect(team); !s.ok()) return s.error();
  return std::unique_ptr<TeamObserver>(new TeamObserver(std::move(state)));
}

std::size_t TeamObserver::spin_once() { return state_->transport.poll(); }
OccupancyGrid TeamObserver::merged(const GridGeometry& into) const {
  return state_->merger.merged(into);
}
bool TeamObserver::take_map_update() { return std::exchange(state_->map_update, false); }
double TeamObserver::sim_time_s() const { return state_->sim_time_s; }
const std::map<std::string, TeamObserverRobot>& TeamObserver::robots() const {
  return state_->robots;
}
std::uint64_t TeamObserver::maps_dropped() const { return state_->maps_dropped; }

}  // namespace tessera::nodes
