// Saved sessions (issue 16, io/session_file.hpp): `tessera info FILE.tsm` and `tessera session
// export FILE.tsm --out DIR`. The slam command's --save and --resume are slam_session.cpp.
#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "commands.hpp"
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
          {"format_version", s.format_version},
          {"tessera_version", s.tessera_version},
          {"command", s.command},
          {"settings_yaml", s.options_yaml},
          {"scans", s.scans.size()},
          {"trajectories",
           s.trajectory_starts.size() +
               (!s.trajectory_starts.empty() && s.trajectory_starts[0].first_scan == 0 ? 0 : 1)},
          {"duration_s", duration_s},
          {"nodes", nodes},
          {"submaps", submaps},
          {"edges", s.graph.edges.size()},
          {"robust_edges", loops},
          {"map_cells", {g.width(), g.height()}},
          {"map_resolution_m", g.resolution_m()},
          {"file_bytes", ec ? 0 : bytes}};
}

}  // namespace

int InfoCommand::run_session() const {
  Result<Session> read = read_session(file_);
  if (!read) return report_error(read.error());
  const nlohmann::json j = session_json(file_, *read);
  if (json_) {
    fmt::print("{}\n", j.dump(2));
    return kExitOk;
  }
  fmt::print("{}: tessera session, format {}, written by tessera {} ({})\n", file_.string(),
             read->format_version, read->tessera_version, read->command);
  const int trajectories = j["trajectories"].get<int>();
  fmt::print("  scans       {} over {:.1f} s in {} trajector{}\n", read->scans.size(),
             j["duration_s"].get<double>(), trajectories, trajectories == 1 ? "y" : "ies");
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
