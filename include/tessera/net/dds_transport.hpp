#pragma once
// The transport between processes: Eclipse Cyclone DDS (Debian's cyclonedds-dev), with ROS 2's
// names and layouts on the wire, so that ROS 2 nodes (rmw_cyclonedds, rmw_fastrtps) and tessera's
// nodes read each other's topics without ROS 2 being installed. Topic /r1/scan is DDS topic
// rt/r1/scan of type sensor_msgs::msg::dds_::LaserScan_, XCDR1 little endian; the types are the
// IDL files in src/net/idl, compiled by Cyclone's idlc. Decision 0021 says why messages cross this
// interface as CDR bytes.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "tessera/core/result.hpp"
#include "tessera/net/transport.hpp"

namespace tessera::net {

struct DdsOptions {
  /// The DDS domain (ROS_DOMAIN_ID): 0..232. Participants on different domains never meet.
  std::uint32_t domain_id = 0;
  /// Loopback only: the 127.0.0.1 interface, no multicast, discovery by unicast to the
  /// participant ports on 127.0.0.1. For tests, CI and several nodes on one machine; false uses
  /// Cyclone's defaults (multicast discovery on the machine's network interface), as ROS 2 does.
  bool loopback_only = true;
  /// With loopback_only: how many participants one machine may hold on the domain (Cyclone's
  /// MaxAutoParticipantIndex + 1; discovery probes each one's port).
  std::uint32_t max_participants = 32;
};

/// A participant on `options.domain_id`. kInput for a domain id out of range; kRuntime when DDS
/// cannot start (no loopback interface, every participant index taken).
[[nodiscard]] Result<std::unique_ptr<Transport>> make_dds_transport(const DdsOptions& options);

/// The ROS 2 types ("sensor_msgs/msg/LaserScan") the DDS transport carries, sorted.
[[nodiscard]] std::vector<std::string> dds_transport_types();

}  // namespace tessera::net
