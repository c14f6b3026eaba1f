#pragma once
// The core keys every report.json carries (../shared/DESIGN.md "report.json", docs/report-schema.md):
// "tessera_version" (CMake's project version), "command", "seed", "options" (the effective options)
// and "timing" {wall_s, data_duration_s, realtime_factor}. Every command starts its report here and
// adds the sections that apply ("world", "exploration", "map_accuracy", "trajectory", ...).
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace tessera {

/// What every run states about itself.
struct ReportHeader {
  std::string command;                                // "explore", "eval ate", "posegraph optimize"
  std::optional<std::uint64_t> seed;                  // empty: nothing in the run is random (null)
  nlohmann::json options = nlohmann::json::object();  // the effective options, as the user sees them
  double wall_s = 0.0;                                // wall-clock time of the run itself
  // Time span of the data the run consumed (a log, a sequence, a simulated run's clock); empty
  // when the run has no data clock (a pose graph, a BOB run counted in moves): null in the report.
  std::optional<double> data_duration_s;
};

/// The version of the tessera build ("0.1.0"), from CMake's project(VERSION).
[[nodiscard]] std::string tessera_version();

/// Data seconds processed per wall-clock second: data_duration_s / wall_s. Empty when there is no
/// data clock or wall_s is not positive (a run too fast to time). The one formula of every report.
[[nodiscard]] std::optional<double> realtime_factor(std::optional<double> data_duration_s,
                                                    double wall_s);

/// {"wall_s", "data_duration_s", "realtime_factor"}; the last two null when empty.
[[nodiscard]] nlohmann::json timing_json(double wall_s, std::optional<double> data_duration_s);

/// A report with the core keys, in DESIGN's order; sections are added by the caller.
[[nodiscard]] nlohmann::json core_report(const ReportHeader& run);

}  // namespace tessera
