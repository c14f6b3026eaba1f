#include "tessera/report/bob_report.hpp"

#include <gtest/gtest.h>

namespace tessera {
namespace {

BobResult finished_run() {
  BobResult r;
  r.width = 3;
  r.height = 2;
  r.stop_reason = bob::StopReason::kBackAtStart;
  return r;
}

BobTableRow table_row() {
  BobTableRow row;
  row.cells = 6;
  row.empty_as_occupied = 1;
  row.occupied_as_empty = 2;
  row.success_rate = 0.5;
  row.path_cells = 9;
  row.free_reachable = 4;
  return row;
}

TEST(BobReport, PutsTableOneUnderMapAccuracyWithDesignKeysAndTheRowBesideThem) {
  BobReportContext context;
  context.run = {"bob", 3, {{"variant", "trail"}}, 1.5, std::nullopt};
  context.world_file = "builtin:labyrinth";
  context.world_resolution_m = 0.05;
  context.variant = "trail";
  const nlohmann::json j = bob_report(finished_run(), table_row(), context);
  const nlohmann::json& a = j["map_accuracy"];
  EXPECT_EQ(a["cells_compared"], 6);
  EXPECT_EQ(a["correct"], 3);  // 6 cells - 1 - 2 errors
  EXPECT_EQ(a["empty_as_occupied"], 1);
  EXPECT_EQ(a["occupied_as_empty"], 2);
  EXPECT_DOUBLE_EQ(a["success_rate"].get<double>(), 0.5);
  EXPECT_EQ(a["path_cells"], 9);
  EXPECT_EQ(a["free_reachable_c"], 4);
  EXPECT_EQ(a["stop_reason"], "back at start");
  EXPECT_EQ(a["variant"], "trail");
  EXPECT_FALSE(j.contains("bob"));
  EXPECT_EQ(j["command"], "bob");
  EXPECT_EQ(j["seed"], 3);
  EXPECT_EQ(j["world"]["width_cells"], 3);
  EXPECT_TRUE(j["timing"]["data_duration_s"].is_null());  // a BOB run counts moves, not seconds
  EXPECT_TRUE(j.contains("localisation"));
}

}  // namespace
}  // namespace tessera
