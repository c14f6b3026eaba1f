#include "tessera/report/bob_report.hpp"

#include <numbers>

namespace tessera {
namespace {

nlohmann::json localisation_json(const BobLocalisationStats& s) {
  return {{"fixes", s.fixes},
          {"failed_fixes", s.failed_fixes},
          {"repositionings", s.repositionings},
          {"unresolved_steps", s.unresolved_steps},
          {"bumps", s.bumps},
          {"collisions", s.collisions},
          {"mean_fix_error_m", s.mean_fix_error_m},
          {"max_drift_m", s.max_drift_m},
          {"max_position_error_m", s.max_position_error_m},
          {"max_heading_error_deg", s.max_heading_error_rad * 180.0 / std::numbers::pi}};
}

}  // namespace

const char* stop_reason_name(bob::StopReason reason) {
  switch (reason) {
    case bob::StopReason::kBackAtStart:
      return "back at start";
    case bob::StopReason::kAllSensed:
      return "all cells sensed";
    case bob::StopReason::kNoReachableTarget:
      return "no reachable target";
    case bob::StopReason::kNone:
      break;
  }
  return "none";
}

nlohmann::json bob_map_accuracy_json(const BobTableRow& r) {
  return {{"cells_compared", r.cells},
          {"correct", r.cells - r.empty_as_occupied - r.occupied_as_empty},
          {"empty_as_occupied", r.empty_as_occupied},
          {"occupied_as_empty", r.occupied_as_empty},
          {"success_rate", r.success_rate},
          // BOBMapping Table 1's own columns, beside DESIGN's keys:
          {"cells", r.cells},
          {"sensed_cells", r.sensed_cells},
          {"resensed_cells", r.resensed},
          {"ignored_readings", r.ignored_readings},
          {"empty_as_occupied_strict", r.empty_as_occupied_strict},
          {"occupied_as_empty_strict", r.occupied_as_empty_strict},
          {"success_rate_strict", r.success_rate_strict},
          {"path_cells", r.path_cells},
          {"turns", r.turns},
          {"visited_cells", r.visited_cells},
          {"path_share", r.path_share},
          {"visited_share", r.visited_share},
          {"free_reachable_c", r.free_reachable},
          {"boundary_edges_e", r.boundary_edges},
          {"path_per_c", r.path_per_c},
          {"path_per_smartdfs_bound", r.path_per_smartdfs}};
}

nlohmann::json bob_report(const BobResult& r, const BobTableRow& row,
                          const BobReportContext& context) {
  nlohmann::json j = core_report(context.run);
  j["world"] = {{"file", context.world_file},
                {"resolution_m", context.world_resolution_m},
                {"width_cells", r.width},
                {"height_cells", r.height}};
  j["map_accuracy"] = bob_map_accuracy_json(row);
  j["map_accuracy"]["stop_reason"] = stop_reason_name(r.stop_reason);
  j["map_accuracy"]["variant"] = context.variant;
  j["localisation"] = localisation_json(r.localisation);
  return j;
}

}  // namespace tessera
