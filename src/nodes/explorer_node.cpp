// The exploring robot of a team (nodes/explorer_node.hpp): SLAM, the team's map, frontier routes,
// the path follower and the team's messages.
#include "tessera/nodes/explorer_node.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <string_view>

#include "tessera/core/angle.hpp"
#include "tessera/io/ros_message_encoders.hpp"
#include "tessera/io/tf_tree.hpp"
#include "tessera/net/ros_names.hpp"
#include "tessera/record/ros_conversions.hpp"
#include "tessera/team/map_merge.hpp"

namespace tessera::nodes {
namespace {

using net::Qos;
using net::Transport;
using RobotState = RobotStatusMessage;  // its state constants
using SteadyClock = std::chrono::steady_clock;

constexpr double kProgressStep_m = 0.1;    // progress that resets the stuck timer
constexpr double kTargetResolved_m = 0.2;  // a target with no frontier this close is explored
constexpr double kPlanningMargin_m = 1.0;  // the planning grid reaches this far past the maps

double seconds(std::int64_t ns) { return 1e-9 * static_cast<double>(ns); }

// Claims and the team's status: every robot's latest, also for a robot that joins later.
constexpr Qos kTeamQos{Qos::Reliability::kReliable, Qos::Durability::kTransientLocal, 1};
// Readers of topics with one writer per robot keep one message per robot between polls.
constexpr Qos kTeamReaderQos{Qos::Reliability::kReliable, Qos::Durability::kTransientLocal, 64};

}  // namespace

std::optional<std::string> validate(const ExplorerNodeOptions& o) {
  if (!net::check_topic_name("/" + o.name).ok()) return "name must be a ROS 2 name, e.g. r1";
  bool found = false;
  for (const TeamMember& m : o.team) {
    found = found || m.name == o.name;
    if (m.T_team_map.has_value() != o.team.front().T_team_map.has_value()) {
      return "give every robot's start pose or none";
    }
  }
  if (!found) return "the team must include this robot (" + o.name + ")";
  if (auto p = team::validate(o.match)) return "match: " + *p;
  if (o.match_confirmations < 1) return "match_confirmations must be >= 1";
  if (auto p = team::validate(o.route)) return "route: " + *p;
  if (auto p = validate(o.follower)) return "follower: " + *p;
  for (const double v : {o.plan_period_s, o.team_map_period_wall_s, o.stuck_s, o.finish_after_s,
                         o.status_period_s, o.match_period_s}) {
    if (!(v > 0.0) || !std::isfinite(v)) return "periods and times must be > 0";
  }
  return std::nullopt;
}

struct ExplorerNode::State {
  struct Claim {
    Vec2 target_m;
    bool active = false;
  };
  struct Teammate {
    Vec2 position_m;
    double stamp_s = 0.0;
    bool exploring = false;
  };
  // A teammate whose start is unknown and that map matching has not placed yet.
  struct Unplaced {
    OccupancyGridMessage latest;  // its newest map
    bool fresh = false;           // not matched since it came
    std::optional<Pose2> candidate;
    int agreeing = 0;  // accepted matches in a row that agree with the candidate
  };

  ExplorerNodeOptions options;
  Transport& transport;
  std::unique_ptr<SlamNode> slam;
  ExplorerNodeStats stats;
  Pose2 T_team_map;  // this robot's map frame (its start) in the team frame
  bool starts_known = true;
  team::MapMerger direct;     // this robot's and its teammates' own maps
  team::MapMerger team_maps;  // teammates' merged maps: cells no live map knows
  std::map<std::string, std::optional<Pose2>> T_team_teammate;  // nullopt: not placed yet
  std::map<std::string, Unplaced> unplaced;
  std::vector<TeammatePlacement> placements;
  double last_match_s = -1e9;
  std::map<std::string, Claim> claims;
  std::map<std::string, Teammate> teammates;
  std::uint64_t merged_inputs = 0, planned_inputs = ~0ULL, own_map_revision = 0;
  OccupancyGrid direct_map;  // this robot's and its placed teammates' own maps, merged
  OccupancyGrid team_map;    // direct_map, unknown cells filled from teammates' team maps
  std::optional<team::DrivableMap> drivable;
  Transport::WriterId cmd_writer = 0, claim_writer = 0, status_writer = 0, team_map_writer = 0;

  std::uint8_t state = RobotState::kStarting;
  std::string reason;
  std::optional<PathFollower> follower;
  std::optional<Vec2> target_m;  // frontier target (exploring) or home (returning)
  std::vector<Vec2> given_up_m;
  std::uint32_t claim_id = 0;
  std::int64_t last_odometry_ns = -1;
  double now_s = 0.0;  // robot time: the newest odometry stamp
  double progress_best_m = 0.0, progress_at_s = 0.0;
  double no_frontier_since_s = -1.0;
  double last_status_s = -1e9;
  double last_plan_s = -1e9;
  SteadyClock::time_point last_team_map{};

  State(const ExplorerNodeOptions& o, Transport& t)
      : options(o),
        transport(t),
        direct(o.slam.slam.map_resolution_m),
        team_maps(o.slam.slam.map_resolution_m) {}

  Status connect() {
    starts_known = options.team.front().T_team_map.has_value();
    for (const TeamMember& m : options.team) {
      if (m.name == options.name) {
        T_team_map = m.T_team_map.value_or(Pose2{});
        continue;
      }
      T_team_teammate[m.name] = m.T_team_map;
      if (!starts_known) unplaced[m.name];
      if (Status s =
              transport.listen({"/" + m.name + "/map", std::string(kRos2OccupancyGrid), Qos::map()},
                               [this, name = m.name](auto cdr) { on_teammate_map(name, cdr); });
          !s.ok()) {
        return s;
      }
    }
    const std::string ns = "/" + options.name;
    for (Status s : {transport.advertise(
                         {ns + "/cmd_vel", std::string(kRos2Twist), Qos::reliable(10)}, cmd_writer),
                     transport.advertise(
                         {"/team/claims", std::string(kRos2FrontierClaim), kTeamQos}, claim_writer),
                     transport.advertise({"/team/status", std::string(kRos2RobotStatus), kTeamQos},
                                         status_writer),
                     transport.advertise({"/team/map", std::string(kRos2OccupancyGrid), Qos::map()},
                                         team_map_writer)}) {
      if (!s.ok()) return s;
    }
    for (Status s :
         {transport.listen({"/team/claims", std::string(kRos2FrontierClaim), kTeamReaderQos},
                           [this](auto c) { on_claim(c); }),
          transport.listen({"/team/map", std::string(kRos2OccupancyGrid), kTeamReaderQos},
                           [this](auto c) { on_team_map(c); }),
          transport.listen({"/team/status", std::string(kRos2RobotStatus), kTeamReaderQos},
                           [this](auto c) { on_status(c); }),
          transport.listen({"/team/command", std::string(kRos2TeamCommand), Qos::reliable(10)},
                           [this](auto c) { on_command(c); })}) {
      if (!s.ok()) return s;
    }
    return Ok{};
  }

  // Where a teammate's team frame lies in ours: the same frame when the starts are known; its
  // map frame, once placed, when they are not. nullopt: not placed (or not of the team).
  [[nodiscard]] std::optional<Pose2> T_team_their_team(const std::string& robot) const {
    if (starts_known) return Pose2{};
    const auto it = T_team_teammate.find(robot);
    return it == T_team_teammate.end() ? std::nullopt : it->second;
  }

  void on_teammate_map(const std::string& name, std::span<const std::uint8_t> cdr) {
    Result<OccupancyGridMessage> m = decode_cdr_occupancy_grid(cdr);
    if (!m.ok()) {
      ++stats.teammate_maps_dropped;
      return;
    }
    if (const std::optional<Pose2>& T = T_team_teammate.at(name); !T) {
      // Checked now as the merge would check it, kept for the next match.
      if (!direct.check(name, *m, Pose2{}).ok()) {
        ++stats.teammate_maps_dropped;
        return;
      }
      Unplaced& u = unplaced.at(name);
      u.latest = std::move(*m);
      u.fresh = true;
    } else if (!direct.update(name, *m, *T).ok()) {
      ++stats.teammate_maps_dropped;
      return;
    }
    ++stats.teammate_maps_received;
    ++merged_inputs;
  }

  // Unknown start poses: matches the newest map of each unplaced teammate against the team map,
  // and places a teammate once match_confirmations accepted matches in a row agree.
  void place_teammates() {
    if (starts_known || unplaced.empty() || team_map.geometry().size() == 0) return;
    if (now_s - last_match_s < options.match_period_s) return;
    last_match_s = now_s;
    for (auto it = unplaced.begin(); it != unplaced.end();) {
      it = try_to_place(it);
    }
  }

  // Matches the teammate at `it` if its map is new, and places it when the matches confirm;
  // returns the unplaced teammate after it.
  std::map<std::string, Unplaced>::iterator try_to_place(
      std::map<std::string, Unplaced>::iterator it) {
    Unplaced& u = it->second;
    if (!u.fresh) return std::next(it);
    u.fresh = false;
    team::MapMerger as_grid(options.slam.slam.map_resolution_m);
    (void)as_grid.update(it->first, u.latest, Pose2{});  // checked when it came
    ++stats.map_matches_tried;
    Result<std::optional<team::MapMatch>> m =
        team::match_maps(team_map, as_grid.merged(), options.match);
    if (!m.ok() || !m->has_value() || !(*m)->accepted) {
      u.candidate.reset();
      u.agreeing = 0;
      return std::next(it);
    }
    ++stats.map_matches_accepted;
    const Pose2 T = (*m)->T_fixed_moving;
    const bool agrees =
        u.candidate &&
        std::hypot(T.x - u.candidate->x, T.y - u.candidate->y) <= kPlacementAgreement_m &&
        std::abs(normalize_angle(T.theta - u.candidate->theta)) <= kPlacementAgreement_rad;
    u.agreeing = agrees ? u.agreeing + 1 : 1;
    u.candidate = T;
    if (u.agreeing < options.match_confirmations) return std::next(it);
    placements.push_back({it->first, T, now_s, **m});
    T_team_teammate[it->first] = T;
    (void)direct.update(it->first, u.latest, T);  // checked when it came
    ++merged_inputs;
    return unplaced.erase(it);
  }

  void on_team_map(std::span<const std::uint8_t> cdr) {
    Result<OccupancyGridMessage> m = decode_cdr_occupancy_grid(cdr);
    if (!m.ok()) {
      ++stats.teammate_maps_dropped;
      return;
    }
    // Frame "<robot>/team": whose merged map it is. This robot's own comes back too: skipped.
    const std::string_view frame = tf_frame_name(m->header.frame_id);
    constexpr std::string_view kSuffix = "/team";
    const std::string robot(
        frame.ends_with(kSuffix) ? frame.substr(0, frame.size() - kSuffix.size()) : frame);
    if (robot == options.name) return;
    const std::optional<Pose2> T = T_team_their_team(robot);
    if (!T) return;  // not placed yet: it comes again
    if (!team_maps.update(robot, *m, *T).ok()) {
      ++stats.teammate_maps_dropped;
      return;
    }
    ++stats.team_maps_received;
    ++merged_inputs;
  }

  void on_claim(std::span<const std::uint8_t> cdr) {
    Result<FrontierClaimMessage> m = decode_cdr_frontier_claim(cdr);
    if (!m.ok() || !std::isfinite(m->target.x_m) || !std::isfinite(m->target.y_m)) {
      ++stats.claims_dropped;
      return;
    }
    const std::optional<Pose2> T = T_team_their_team(m->robot_id);
    if (m->robot_id == options.name || !T) return;
    ++stats.claims_received;
    claims[m->robot_id] = {*T * Vec2{m->target.x_m, m->target.y_m}, m->active};
  }

  void on_status(std::span<const std::uint8_t> cdr) {
    Result<RobotStatusMessage> m = decode_cdr_robot_status(cdr);
    if (!m.ok() || m->robot_id == options.name || !T_team_teammate.contains(m->robot_id)) return;
    const std::optional<Pose2> T = T_team_their_team(m->robot_id);
    if (!T) return;
    const Pose2 p = *T * planar_pose(m->pose);
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return;
    teammates[m->robot_id] = {
        {p.x, p.y},
        seconds(m->header.stamp_ns),
        m->state == RobotState::kExploring || m->state == RobotState::kStarting};
  }

  void on_command(std::span<const std::uint8_t> cdr) {
    Result<TeamCommandMessage> m = decode_cdr_team_command(cdr);
    if (!m.ok() || m->command > TeamCommandMessage::kReturnHome) {
      ++stats.commands_dropped;
      return;
    }
    if (!m->robot_id.empty() && m->robot_id != options.name) return;
    ++stats.commands_received;
    drop_route();
    no_frontier_since_s = -1.0;
    if (m->command == TeamCommandMessage::kStart) {
      set_state(RobotState::kExploring, "");
    } else if (m->command == TeamCommandMessage::kStop) {
      set_state(RobotState::kStopped, kReasonStoppedByCommand);
    } else {
      set_state(RobotState::kReturningHome, "");
    }
    last_status_s = -1e9;  // say so at once
  }

  void set_state(std::uint8_t s, std::string why) {
    state = s;
    reason = std::move(why);
  }

  [[nodiscard]] std::optional<Pose2> pose() const {
    const std::optional<PoseAtNs> odom = slam->latest_odometry();
    if (!slam->started() || !odom) return std::nullopt;
    return T_team_map * slam->T_map_odom() * odom->pose;
  }

  void drop_route() {
    follower.reset();
    target_m.reset();
  }

  void give_up_target() {
    if (target_m && state == RobotState::kExploring) {
      given_up_m.push_back(*target_m);
      ++stats.targets_given_up;
    }
    drop_route();
  }

  // The merged map and its drivable cells, when an input changed.
  void merge() {
    const OccupancyGrid* own = slam->map();
    if (own == nullptr) return;
    if (slam->map_revision() != own_map_revision) {
      own_map_revision = slam->map_revision();
      // The robot's own map cannot have another resolution: the merger was made with its own.
      (void)direct.update(options.name, occupancy_grid_message(*own, 0, "map"), T_team_map);
      ++merged_inputs;
    }
    if (merged_inputs == planned_inputs) return;
    planned_inputs = merged_inputs;
    GridGeometry g = direct.extent(kPlanningMargin_m);
    const GridGeometry from_team = team_maps.extent();
    if (from_team.size() > 0) {
      // Both extents on one grid: the union, on the direct maps' cell boundaries.
      const double r = g.resolution_m();
      const double x0 = std::min(g.origin().x, from_team.origin().x - kPlanningMargin_m);
      const double y0 = std::min(g.origin().y, from_team.origin().y - kPlanningMargin_m);
      const double x1 = std::max(g.origin().x + g.width() * r,
                                 from_team.origin().x + from_team.width() * r + kPlanningMargin_m);
      const double y1 = std::max(g.origin().y + g.height() * r,
                                 from_team.origin().y + from_team.height() * r + kPlanningMargin_m);
      const Vec2 origin{g.origin().x - std::ceil((g.origin().x - x0) / r) * r,
                        g.origin().y - std::ceil((g.origin().y - y0) / r) * r};
      g = GridGeometry(origin, r, static_cast<int>(std::ceil((x1 - origin.x) / r)),
                       static_cast<int>(std::ceil((y1 - origin.y) / r)));
    }
    direct_map = direct.merged(g);
    team_map = direct_map;
    if (from_team.size() > 0) {
      const OccupancyGrid fill = team_maps.merged(g);
      for (std::size_t i = 0; i < g.size(); ++i) {
        const Cell c = g.cell_of(i);
        if (!team_map.known(c) && fill.known(c)) {
          team_map.set_probability(c, probability(fill.log_odds_at(c)));
        }
      }
    }
    drivable = team::drivable_map(team_map, options.route);
  }

  // Teammates that are exploring and were heard from lately: a robot that died or has finished
  // no longer holds a share of the frontier.
  std::vector<Vec2> active_teammates() const {
    constexpr double kSilent_s = 5.0;
    std::vector<Vec2> out;
    for (const auto& [robot, t] : teammates) {
      if (t.exploring && now_s - t.stamp_s <= kSilent_s) out.push_back(t.position_m);
    }
    return out;
  }

  std::vector<Vec2> teammate_claims() const {
    std::vector<Vec2> out;
    for (const auto& [robot, claim] : claims) {
      if (claim.active) out.push_back(claim.target_m);
    }
    return out;
  }

  Status publish_claim(bool active, double length_m) {
    FrontierClaimMessage m;
    m.header = {static_cast<std::int64_t>(std::llround(now_s * 1e9)), "team"};
    m.robot_id = options.name;
    m.claim_id = ++claim_id;
    if (target_m) m.target = {target_m->x, target_m->y, 0.0};
    m.radius_m = static_cast<float>(options.route.claim_radius_m);
    m.path_length_m = static_cast<float>(length_m);
    m.active = active;
    return transport.publish(claim_writer, encode_cdr(m));
  }

  void start_route(std::vector<Vec2> waypoints, Vec2 target) {
    follower.emplace(std::move(waypoints), options.follower);
    target_m = target;
    progress_best_m = 0.0;
    progress_at_s = now_s;
    ++stats.routes_planned;
  }

  // Re-plans when the route is gone, done, blocked or its target explored.
  Status plan(const Pose2& T_team_robot) {
    if (!drivable) return Ok{};
    const Vec2 robot{T_team_robot.x, T_team_robot.y};
    if (state == RobotState::kReturningHome) {
      if (follower && follower->arrived()) {
        drop_route();
        set_state(RobotState::kFinished, kReasonAtHome);
        return Ok{};
      }
      if (!follower || !team::route_still_drivable(*drivable, follower->waypoints(), 0)) {
        drop_route();
        const Vec2 home{T_team_map.x, T_team_map.y};
        if (auto route = team::plan_drivable_route(*drivable, robot, home)) {
          start_route(std::move(*route), home);
        }
      }
      return Ok{};
    }
    const bool exploring = state == RobotState::kStarting || state == RobotState::kExploring ||
                           (state == RobotState::kFinished && reason == kReasonNoFrontier);
    if (!exploring) return Ok{};
    if (follower) {
      const bool explored = !team::frontier_near(*drivable, *target_m, kTargetResolved_m);
      if (follower->arrived() && !explored) {
        give_up_target();
      } else if (explored || !team::route_still_drivable(*drivable, follower->waypoints(), 0)) {
        drop_route();
      }
    }
    if (follower) return Ok{};
    const std::vector<Vec2> others = teammate_claims();
    std::optional<team::FrontierRoute> route = team::plan_frontier_route(
        *drivable, robot, active_teammates(), others, given_up_m, options.route);
    if (!route) {
      if (no_frontier_since_s < 0.0) no_frontier_since_s = now_s;
      if (state != RobotState::kFinished && now_s - no_frontier_since_s >= options.finish_after_s) {
        set_state(RobotState::kFinished, kReasonNoFrontier);
        last_status_s = -1e9;
        return publish_claim(false, 0.0);
      }
      return Ok{};
    }
    no_frontier_since_s = -1.0;
    set_state(RobotState::kExploring, "");
    const double length = route->length_m;
    start_route(std::move(route->waypoints_m), route->target_m);
    return publish_claim(true, length);
  }

  Status drive(const Pose2& T_team_robot) {
    TwistMessage cmd;
    if (follower && (state == RobotState::kExploring || state == RobotState::kReturningHome)) {
      const VelocityCommand v = follower->command(T_team_robot);
      cmd.linear_x_mps = v.v_m_per_s;
      cmd.angular_z_radps = v.omega_rad_per_s;
      if (follower->progress_m() >= progress_best_m + kProgressStep_m) {
        progress_best_m = follower->progress_m();
        progress_at_s = now_s;
      } else if (now_s - progress_at_s > options.stuck_s) {
        give_up_target();
      }
    }
    return transport.publish(cmd_writer, encode_cdr(cmd));
  }

  Status publish_status(const std::optional<Pose2>& T_team_robot) {
    RobotStatusMessage m;
    m.header = {static_cast<std::int64_t>(std::llround(now_s * 1e9)), "team"};
    m.robot_id = options.name;
    m.state = state;
    m.reason = reason;
    if (T_team_robot) {
      m.pose = planar_transform(T_team_robot->x, T_team_robot->y, T_team_robot->theta);
    }
    if (const OccupancyGrid* own = slam->map()) {
      const float free = log_odds(options.route.free_below);
      std::size_t n = 0;
      for (std::size_t i = 0; i < own->geometry().size(); ++i) {
        n += own->is_free_below(own->geometry().cell_of(i), free) ? 1 : 0;
      }
      const double r = own->geometry().resolution_m();
      m.explored_area_m2 = static_cast<float>(static_cast<double>(n) * r * r);
    }
    for (const auto& [topic, t] : transport.traffic()) {
      m.messages_sent += t.messages_sent;
      m.bytes_sent += t.bytes_sent;
    }
    const SlamNodeStats& s = slam->stats();
    m.messages_dropped = stats.teammate_maps_dropped + stats.claims_dropped +
                         stats.commands_dropped + s.scans_dropped_invalid +
                         s.odometry_dropped_invalid;
    last_status_s = now_s;
    return transport.publish(status_writer, encode_cdr(m));
  }

  // The first-hand part of the team map (this robot's map and its placed teammates' own maps,
  // without the cells filled from teammates' team maps) cut to its known cells. Team maps never
  // feed back into each other (decision 0022): with unknown starts every round trip would shift
  // an echo by the placement error, and the echoes crept over the frontier until the robots
  // stopped with 8 % of the office unseen. The planning margin is not sent either.
  Status publish_team_map() {
    last_team_map = SteadyClock::now();
    const std::optional<CellBox> known = known_box(direct_map);
    if (!known) return Ok{};
    ++stats.team_maps_published;
    return transport.publish(team_map_writer, encode_cdr(occupancy_grid_message(
                                                  direct_map, *known, std::llround(now_s * 1e9),
                                                  options.name + "/team")));
  }

  Status spin() {
    if (Result<int> added = slam->spin_once(); !added.ok()) return added.error();
    const std::optional<PoseAtNs> odom = slam->latest_odometry();
    if (odom) now_s = seconds(odom->t_ns);
    const std::optional<Pose2> T_team_robot = pose();
    const auto wall = SteadyClock::now();
    if (T_team_robot && now_s - last_plan_s >= options.plan_period_s) {
      last_plan_s = now_s;
      merge();
      place_teammates();
      merge();
      if (Status s = plan(*T_team_robot); !s.ok()) return s;
    }
    if (wall - last_team_map >= std::chrono::duration<double>(options.team_map_period_wall_s)) {
      if (Status s = publish_team_map(); !s.ok()) return s;
    }
    if (odom && odom->t_ns != last_odometry_ns && T_team_robot) {
      last_odometry_ns = odom->t_ns;
      if (Status s = drive(*T_team_robot); !s.ok()) return s;
    }
    if (now_s - last_status_s >= options.status_period_s) return publish_status(T_team_robot);
    return Ok{};
  }
};

ExplorerNode::ExplorerNode(std::unique_ptr<State> state) : state_(std::move(state)) {}
ExplorerNode::~ExplorerNode() = default;

Result<std::unique_ptr<ExplorerNode>> ExplorerNode::create(const ExplorerNodeOptions& options,
                                                           Transport& transport) {
  if (auto problem = validate(options)) return usage_error("explorer node: " + *problem);
  ExplorerNodeOptions o = options;
  o.slam.ns = "/" + o.name;
  auto state = std::make_unique<State>(o, transport);
  Result<std::unique_ptr<SlamNode>> slam = SlamNode::create(o.slam, transport);
  if (!slam.ok()) return slam.error();
  state->slam = std::move(*slam);
  if (Status s = state->connect(); !s.ok()) return s.error();
  return std::unique_ptr<ExplorerNode>(new ExplorerNode(std::move(state)));
}

Status ExplorerNode::spin_once() { return state_->spin(); }

Result<slam::LaserSlamResult> ExplorerNode::finish() {
  State& s = *state_;
  s.drop_route();
  if (s.state != RobotState::kFinished) s.set_state(RobotState::kStopped, kReasonShutDown);
  for (Status st : {s.transport.publish(s.cmd_writer, encode_cdr(TwistMessage{})),
                    s.publish_claim(false, 0.0), s.publish_status(s.pose())}) {
    if (!st.ok()) return st.error();
  }
  return s.slam->finish();
}

std::uint8_t ExplorerNode::state() const { return state_->state; }
const std::string& ExplorerNode::reason() const { return state_->reason; }
const OccupancyGrid& ExplorerNode::team_map() const { return state_->team_map; }
std::optional<Pose2> ExplorerNode::pose() const { return state_->pose(); }
const ExplorerNodeStats& ExplorerNode::stats() const { return state_->stats; }
const std::vector<TeammatePlacement>& ExplorerNode::placements() const {
  return state_->placements;
}
const SlamNodeStats& ExplorerNode::slam_stats() const { return state_->slam->stats(); }
const std::vector<double>& ExplorerNode::map_latencies_s() const {
  return state_->slam->map_latencies_s();
}

}  // namespace tessera::nodes
