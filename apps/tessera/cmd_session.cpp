// Saved sessions (issue 16, io/session_file.hpp): `tessera slam --save FILE.tsm`, `tessera info
// FILE.tsm` and `tessera session export FILE.tsm --out DIR`.
#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string_view>

#include "commands.hpp"
#include "config_file.hpp"
#include "slam_report.hpp"
#include "tessera/io/session_file.hpp"
#include "tessera/report/core_report.hpp"

namespace tessera::cli {
namespace {

// What a session holds, for `info` and the export's report.
nlohmann::json session_json(const std::filesystem::path& file, const Session& s) {
  int submaps = 0, nodes = 0, loops = 0;
  for (const int scan : s.vertex_scan) (scan < 0 ? submaps : nodes) += 1;
  for (const posegraph::PoseGraphEdge& e : s.graph.edges) loops += e.robust ? 1 : 0;
  const double duration_s = s.scans.empty() ? 0.0 : s.scans.back().t_s - s.scans.front().t_s;
  const GridGeometry& g = s.map.geometry();
  std::error_code ec;
  const auto bytes = std::filesystem::file_size(file, ec);
  return {{"file", file.string()},
          {"format_version", kSessionFormatVersion},
          {"tessera_version", s.tessera_version},
          {"command", s.command},
          {"scans", s.scans.size()},
          {"duration_s", duration_s},
          {"nodes", nodes},
          {"submaps", submaps},
          {"edges", s.graph.edges.size()},
          {"robust_edges", loops},
          {"map_cells", {g.width(), g.height()}},
          {"map_resolution_m", g.resolution_m()},
          {"file_bytes", ec ? 0 : bytes}};
}

// The run's settings as a session keeps them: --print-config's YAML without the settings of
// where the run wrote and showed its outputs, which are not the session's (a session saved from
// another folder is the same session).
std::string session_options_yaml(const CLI::App& command) {
  static const std::set<std::string, std::less<>> kNotTheSessions = {
      "out", "save", "record", "serve", "serve_address", "serve_linger", "step_delay_ms", "quiet"};
  std::istringstream in(effective_config_yaml(command));
  std::string out, line;
  while (std::getline(in, line)) {
    std::string_view key = line;
    if (key.starts_with("# ")) key.remove_prefix(2);
    key = key.substr(0, key.find(':'));
    if (!kNotTheSessions.contains(key)) out += line + "\n";
  }
  return out;
}

}  // namespace

void SlamCommand::add_session_options() {
  sub_->add_option("--save", save_,
                   "Save the session to this .tsm file (the scans, options, trajectory, pose "
                   "graph and map; docs/session-format.md), written atomically");
}

Status SlamCommand::save_session(const LaserLog& log, const slam::LaserSlamResult& r) const {
  if (!save_) return Ok{};
  Session s;
  s.tessera_version = tessera_version();
  s.command = "slam";
  s.options_yaml = session_options_yaml(*sub_);
  s.scans = log.scans;
  s.trajectory = r.trajectory;
  s.graph = r.graph;
  s.vertex_scan = r.vertex_scan;
  s.map = r.map;
  return write_session(*save_, s);
}

int InfoCommand::run_session() const {
  Result<Session> read = read_session(file_);
  if (!read) return report_error(read.error());
  const nlohmann::json j = session_json(file_, *read);
  if (json_) {
    fmt::print("{}\n", j.dump(2));
    return kExitOk;
  }
  fmt::print("{}: tessera session, format {}, written by tessera {} ({})\n", file_.string(),
             kSessionFormatVersion, read->tessera_version, read->command);
  fmt::print("  scans       {} over {:.1f} s\n", read->scans.size(), j["duration_s"].get<double>());
  fmt::print("  graph       {} nodes, {} submaps, {} edges ({} robust: loop closures)\n",
             j["nodes"].get<int>(), j["submaps"].get<int>(), read->graph.edges.size(),
             j["robust_edges"].get<int>());
  const GridGeometry& g = read->map.geometry();
  fmt::print("  map         {} x {} cells at {} m\n", g.width(), g.height(), g.resolution_m());
  return kExitOk;
}

SessionCommand::SessionCommand(CLI::App& app) {
  CLI::App* session = app.add_subcommand("session", "Saved SLAM sessions (.tsm)");
  session->require_subcommand(1);
  sub_ = session;
  export_ = session->add_subcommand(
      "export",
      "Write a session's map (map.yaml + map.pgm, map.png), pose graph (graph.g2o), trajectory "
      "(trajectory.txt, TUM) and report.json to --out");
  export_->add_option("file", file_, "Session file (.tsm)")->required();
  export_->add_option("--out", out_, "Output folder")->capture_default_str();
  export_->add_flag("--quiet", quiet_, "No summary");
}

int SessionCommand::run() const {
  const auto t0 = std::chrono::steady_clock::now();
  Result<Session> read = read_session(file_);
  if (!read) return report_error(read.error());
  slam::LaserSlamResult r;
  r.trajectory = read->trajectory;
  r.graph = read->graph;
  r.vertex_scan = read->vertex_scan;
  r.map = read->map;
  nlohmann::json report = core_report({"session export",
                                       std::nullopt,
                                       {{"file", file_.string()}, {"out", out_.string()}},
                                       seconds_since(t0),
                                       0.0});
  report["session"] = session_json(file_, *read);
  if (Status s = write_laser_slam_outputs(out_, r, report, nullptr, Pose2{}, nullptr); !s) {
    return report_error(s.error());
  }
  if (!quiet_) {
    fmt::print("session: {} scans, {} poses exported\n", read->scans.size(),
               read->trajectory.size());
    fmt::print("outputs: {}/map.yaml map.pgm map.png trajectory.txt graph.g2o report.json\n",
               out_.string());
  }
  return kExitOk;
}

}  // namespace tessera::cli
