#pragma once
// What `tessera team` writes at the end of a run: the merged map (map.yaml + map.pgm, map.png
// with the truth's errors and the robots' true paths), each robot's true and SLAM trajectory (TUM)
// and report.json (coverage over time, time to 90 and 99 %, map accuracy, per robot its state,
// stop reason, SLAM error against the truth and messages and bytes sent).
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "tessera/core/pose2.hpp"
#include "tessera/core/result.hpp"
#include "tessera/nodes/team_observer.hpp"
#include "tessera/sim/world.hpp"

namespace tessera::cli {

/// Coverage of the truth's reachable free cells at one simulated time.
struct CoverageSample {
  double t_s = 0.0;
  double known = 0.0;  // the merged map knows the cell (free or not)
  double free = 0.0;   // ... and shows it free
};

/// A robot process's story: when it was killed on purpose, restarted, or ended by itself
/// (simulated seconds).
struct RobotEvents {
  std::optional<double> killed_at_s;
  std::optional<double> restarted_at_s;
  std::optional<double> exited_at_s;
};

struct TeamRunRecord {
  const World* world = nullptr;
  std::vector<Pose2> starts;
  std::vector<CoverageSample> coverage;
  std::vector<RobotEvents> events;  // per robot
  /// Per robot, its own report.json (tessera explore --ros), or null when it wrote none.
  std::vector<nlohmann::json> robot_reports;
  double sim_s = 0.0;
  double wall_s = 0.0;
  std::string end;  // why the run ended
};

/// The merged map on the truth's grid and its coverage of the reachable free cells.
[[nodiscard]] CoverageSample team_coverage(const nodes::TeamObserver& observer, const World& world,
                                           const std::vector<std::uint8_t>& reachable, double t_s);

/// Writes every output into `out` (atomically, file by file). `report` holds the core keys.
[[nodiscard]] Status write_team_outputs(const std::filesystem::path& out,
                                        const nodes::TeamObserver& observer,
                                        const TeamRunRecord& run, nlohmann::json report);

}  // namespace tessera::cli
