#pragma once
// The quality of service of a topic, the part of DDS's that ROS 2 exposes (rclcpp's QoS profiles):
// reliability, durability and a keep-last history depth. The presets are the ones ROS 2 nodes use
// for each kind of topic, so that tessera's readers and writers match theirs.
#include <cstdint>

namespace tessera::net {

struct Qos {
  enum class Reliability : std::uint8_t {
    kBestEffort,  // a lost sample is not resent (sensor data: the next scan replaces it)
    kReliable,    // every sample in the history is delivered to matched readers
  };
  enum class Durability : std::uint8_t {
    kVolatile,        // a reader gets only what is written after it matched
    kTransientLocal,  // a late reader also gets the writer's last `depth` samples
  };

  Reliability reliability = Reliability::kReliable;
  Durability durability = Durability::kVolatile;
  std::uint32_t depth = 10;  // keep-last history, at the writer and at each reader

  /// rclcpp::SensorDataQoS: best effort, volatile, keep last 5 (scans, odometry).
  static constexpr Qos sensor_data() {
    return {Reliability::kBestEffort, Durability::kVolatile, 5};
  }
  /// Maps as nav2's map_server and slam_toolbox publish them: reliable, transient local, depth 1,
  /// so that a node started later (RViz2, a teammate that rejoins) gets the current map.
  static constexpr Qos map() { return {Reliability::kReliable, Durability::kTransientLocal, 1}; }
  /// tf2_ros::DynamicBroadcasterQoS: reliable, volatile, depth 100.
  static constexpr Qos tf() { return {Reliability::kReliable, Durability::kVolatile, 100}; }
  /// tf2_ros::StaticBroadcasterQoS: reliable, transient local, depth 1.
  static constexpr Qos tf_static() {
    return {Reliability::kReliable, Durability::kTransientLocal, 1};
  }
  /// rclcpp::ClockQoS: best effort, volatile, keep last 1 (/clock: only the newest time counts).
  static constexpr Qos clock() { return {Reliability::kBestEffort, Durability::kVolatile, 1}; }
  /// rclcpp's default (rmw_qos_profile_default): reliable, volatile, keep last `depth`.
  static constexpr Qos reliable(std::uint32_t depth) {
    return {Reliability::kReliable, Durability::kVolatile, depth};
  }

  friend bool operator==(const Qos&, const Qos&) = default;
};

/// DDS's request-offered rule: a reader matches a writer when the writer offers at least what the
/// reader requests (a reliable reader needs a reliable writer; a transient-local reader needs a
/// transient-local writer). Unmatched pairs exchange nothing, in DDS as in the in-process bus.
[[nodiscard]] constexpr bool qos_compatible(const Qos& offered_by_writer,
                                            const Qos& requested_by_reader) {
  const bool reliability_ok = offered_by_writer.reliability == Qos::Reliability::kReliable ||
                              requested_by_reader.reliability == Qos::Reliability::kBestEffort;
  const bool durability_ok = offered_by_writer.durability == Qos::Durability::kTransientLocal ||
                             requested_by_reader.durability == Qos::Durability::kVolatile;
  return reliability_ok && durability_ok;
}

}  // namespace tessera::net
