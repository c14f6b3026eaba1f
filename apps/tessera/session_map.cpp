#include "session_map.hpp"

#include <fmt/format.h>

#include <cmath>

#include "tessera/core/angle.hpp"
#include "tessera/slam/laser_slam.hpp"

namespace tessera::cli {

Status check_same_laser(const Session& session, const LaserLog& log,
                        const std::string& session_name, const std::string& log_name) {
  const RangeScan& a = session.scans.front().scan;
  const RangeScan& b = log.scans.front().scan;
  const auto describe = [](const RangeScan& s) {
    return fmt::format("{} beams from {:.2f} deg every {:.3f} deg", s.ranges_m.size(),
                       rad_to_deg(s.angle_min_rad), rad_to_deg(s.angle_increment_rad));
  };
  if (a.ranges_m.size() != b.ranges_m.size() ||
      std::abs(a.angle_min_rad - b.angle_min_rad) > 1e-4 ||
      std::abs(a.angle_increment_rad - b.angle_increment_rad) > 1e-6) {
    return input_error(fmt::format("{}: its laser ({}) is not the session's ({}) in {}", log_name,
                                   describe(b), describe(a), session_name));
  }
  return Ok{};
}

Result<slam::ProbabilityGrid> session_frozen_map(const Session& session,
                                                 const slam::LocalizerOptions& options,
                                                 const std::string& session_name) {
  const slam::LaserSlamOptions slam_options;
  slam::ProbabilityGrid map =
      slam::frozen_map(session.scans, session.graph, session.vertex_scan, options.points,
                       slam_options.submaps.insert, session.map.geometry().resolution_m());
  if (!map.known_box()) return input_error(session_name + ": the session's map knows no cell");
  return map;
}

std::optional<FoundStart> find_log_start(slam::Localizer& localizer, const LaserLog& log) {
  for (const StampedScan& scan : log.scans) {
    const slam::LocalizedScan at = localizer.add_scan(scan);
    if (!at.confident) continue;
    const StampedScan& first = log.scans.front();
    return FoundStart{at.T_map_robot * between(scan.odometry, first.odometry),
                      scan.t_s - first.t_s};
  }
  return std::nullopt;
}

}  // namespace tessera::cli
