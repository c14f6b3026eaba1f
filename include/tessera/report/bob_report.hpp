#pragma once
// report.json of a BOB run (mission/bob_mission.hpp): the core keys (report/core_report.hpp; a
// BOB run is counted in moves and has no data clock, so data_duration_s is null), "world", and
// BOBMapping Table 1's figures under DESIGN's "map_accuracy" {cells_compared, correct,
// empty_as_occupied, occupied_as_empty, success_rate} with the row's own keys beside them (cells,
// sensed_cells, resensed_cells, the strict scores, path_cells, turns, C, E, the SmartDFS ratio,
// stop_reason, variant), and "localisation" (beacon fixes, repositionings, bumps, errors).
#include <nlohmann/json.hpp>
#include <string>

#include "tessera/eval/bob_table.hpp"
#include "tessera/mission/bob_mission.hpp"
#include "tessera/report/core_report.hpp"

namespace tessera {

/// What the report needs besides the run itself.
struct BobReportContext {
  ReportHeader run;  // command "bob", seed, effective options, wall_s
  std::string world_file;  // "builtin:labyrinth" or the map file
  double world_resolution_m = 0.0;
  std::string variant;  // "trail" or "map-aware", as the user chose it
};

/// "back at start", "all cells sensed", "no reachable target" or "none".
[[nodiscard]] const char* stop_reason_name(bob::StopReason reason);

/// Table 1's row (BobTableRow) as map_accuracy: cells_compared is the configuration's cells, as the
/// paper counts them, and correct = cells - both errors.
[[nodiscard]] nlohmann::json bob_map_accuracy_json(const BobTableRow& row);

/// `row`: the run scored against its grid truth (eval/bob_table.hpp score_bob_table).
[[nodiscard]] nlohmann::json bob_report(const BobResult& result, const BobTableRow& row,
                                        const BobReportContext& context);

}  // namespace tessera
