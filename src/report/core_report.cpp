#include "tessera/report/core_report.hpp"

namespace tessera {
namespace {

nlohmann::json or_null(std::optional<double> v) {
  return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

}  // namespace

std::string tessera_version() { return TESSERA_VERSION; }

std::optional<double> realtime_factor(std::optional<double> data_duration_s, double wall_s) {
  if (!data_duration_s || !(wall_s > 0.0)) return std::nullopt;
  return *data_duration_s / wall_s;
}

nlohmann::json timing_json(double wall_s, std::optional<double> data_duration_s) {
  return {{"wall_s", wall_s},
          {"data_duration_s", or_null(data_duration_s)},
          {"realtime_factor", or_null(realtime_factor(data_duration_s, wall_s))}};
}

nlohmann::json core_report(const ReportHeader& run) {
  nlohmann::json j = nlohmann::json::object();
  j["tessera_version"] = tessera_version();
  j["command"] = run.command;
  j["seed"] = run.seed ? nlohmann::json(*run.seed) : nlohmann::json(nullptr);
  j["options"] = run.options;
  j["timing"] = timing_json(run.wall_s, run.data_duration_s);
  return j;
}

}  // namespace tessera
