// tessera slam: laser SLAM on a 2D laser log (slam/laser_slam.hpp). Thin glue: read the log (and
// the relations, if any) first, so that bad input writes nothing; run; write map, trajectory,
// graph and report.json; print one summary line.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "tessera/core/angle.hpp"
#include "tessera/eval/relation_metric.hpp"
#include "tessera/io/atomic_file.hpp"
#include "tessera/io/carmen_log.hpp"
#include "tessera/io/eval_report.hpp"
#include "tessera/io/g2o_file.hpp"
#include "tessera/io/json_file.hpp"
#include "tessera/io/map_yaml.hpp"
#include "tessera/io/relations_file.hpp"
#include "tessera/io/render.hpp"
#include "tessera/io/tum_trajectory.hpp"
#include "tessera/slam/laser_slam.hpp"

namespace tessera::cli {
namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// Stamps may go backwards in real logs: the span is max - min.
double data_duration_s(const LaserLog& log) {
  if (log.scans.empty()) return 0.0;
  const auto [lo, hi] =
      std::minmax_element(log.scans.begin(), log.scans.end(),
                          [](const StampedScan& a, const StampedScan& b) { return a.t_s < b.t_s; });
  return hi->t_s - lo->t_s;
}

}  // namespace

SlamCommand::SlamCommand(CLI::App& app) {
  sub_ = app.add_subcommand(
      "slam",
      "Laser SLAM on a 2D laser log (submaps, branch-and-bound loop closure, pose graph; Hess et "
      "al. 2016); writes map.yaml + map.pgm, map.png, trajectory.txt (one pose per scan), "
      "graph.g2o and report.json to --out");
  sub_->add_option("--log", log_, "Laser log: CARMEN .clf/.log (FLASER, ROBOTLASER1, RAWLASER1)")
      ->required();
  sub_->add_option("--out", out_, "Output folder")->capture_default_str();
  sub_->add_option("--relations", relations_,
                   "Score the trajectory against a relations file (Kummerle et al. 2009)");
  sub_->add_option("--time-offset", time_offset_s_,
                   "Seconds added to the log's stamps to reach the relations' time base (Intel "
                   "raw log: 976052857.337284)")
      ->capture_default_str();
  sub_->add_option("--map-resolution-m", map_resolution_m_, "Cell size of the output map")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  sub_->add_flag("--no-loop-closure", no_loop_closure_,
                 "Local SLAM only: scan-to-submap matching, no pose graph corrections");
  sub_->add_flag("--quiet", quiet_, "No progress line and no summary");
}

int SlamCommand::run() const {
  if (!std::isfinite(time_offset_s_)) {
    return report_error(usage_error("--time-offset must be a finite number of seconds"));
  }
  slam::LaserSlamOptions options;
  options.loop_closure = !no_loop_closure_;
  options.map_resolution_m = map_resolution_m_;
  if (auto problem = slam::validate(options)) return report_error(usage_error(*problem));

  // Inputs first: a bad log or relations file must leave nothing behind.
  Result<LaserLog> log = read_carmen_log(log_);
  if (!log) return report_error(log.error());
  std::optional<std::vector<Relation>> relations;
  if (relations_) {
    Result<std::vector<Relation>> read = read_relations(*relations_);
    if (!read) return report_error(read.error());
    relations = std::move(read).value();
  }

  ProgressLine progress(!quiet_ && stderr_is_terminal());
  options.progress = [&progress](const slam::SlamProgress& p) {
    if (p.scans_done % 25 != 0 && p.scans_done != p.scans_total) return;
    progress.show(fmt::format("slam: scan {}/{}  nodes {}  submaps {}  loop closures {}",
                              p.scans_done, p.scans_total, p.nodes, p.submaps, p.loop_closures));
  };
  const auto t0 = std::chrono::steady_clock::now();
  Result<slam::LaserSlamResult> result = slam::run_laser_slam(*log, options);
  progress.finish();
  const double wall_s = seconds_since(t0);
  if (!result) {
    Error e = result.error();
    e.message = log_.string() + ": " + e.message;
    return report_error(e);
  }
  const slam::LaserSlamResult& r = *result;
  const double duration_s = data_duration_s(*log);

  std::optional<RelationMetric> metric;
  if (relations) {
    Result<RelationMetric> scored = relation_metric(r.trajectory, *relations, time_offset_s_);
    if (!scored) {
      Error e = scored.error();
      e.message = relations_->string() + " against the SLAM trajectory: " + e.message;
      return report_error(e);
    }
    metric = std::move(scored).value();
  }

  const slam::LaserSlamStats& st = r.stats;
  nlohmann::json report = {{"tessera_version", TESSERA_VERSION},
                           {"command", "slam"},
                           {"seed", nullptr},
                           {"options",
                            {{"log", log_.string()},
                             {"loop_closure", options.loop_closure},
                             {"map_resolution_m", options.map_resolution_m},
                             {"submap_resolution_m", options.submaps.resolution_m},
                             {"scans_per_submap", options.submaps.scans_per_submap},
                             {"max_range_m", options.points.max_range_m},
                             {"loop_window_m", options.loop_closer.window.linear_m},
                             {"loop_window_rad", options.loop_closer.window.angular_rad},
                             {"loop_min_score", options.loop_closer.min_score},
                             {"loop_sampling_ratio", options.loop_sampling_ratio},
                             {"optimize_every_n_nodes", options.optimize_every_n_nodes}}},
                           {"slam",
                            {{"scans", st.scans},
                             {"nodes", st.nodes},
                             {"submaps", st.submaps},
                             {"loop_searches", st.loop_searches},
                             {"global_searches", st.global_searches},
                             {"loop_closures", st.loop_closures},
                             {"optimizations", st.optimizations},
                             {"graph_vertices", r.graph.poses.size()},
                             {"graph_edges", r.graph.edges.size()},
                             {"backward_stamps", log->backward_stamps},
                             {"matching_s", st.matching_s},
                             {"loop_search_s", st.loop_search_s},
                             {"optimization_s", st.optimization_s},
                             {"map_s", st.map_s}}},
                           {"timing",
                            {{"wall_s", wall_s},
                             {"data_duration_s", duration_s},
                             {"realtime_factor", wall_s > 0.0 ? duration_s / wall_s : 0.0}}}};
  if (relations_) report["options"]["relations"] = relations_->string();
  if (metric) {
    report["options"]["time_offset_s"] = time_offset_s_;
    report["relations"] = relations_report(*metric, {})["relations"];
  }

  // Outputs: each file is written atomically; the folder is made only now.
  if (Status s = ensure_directory(out_); !s) return report_error(s.error());
  if (Status s = write_map_yaml(r.map, out_ / "map.yaml", MapSaveOptions{}); !s) {
    return report_error(s.error());
  }
  RenderLayers layers;
  layers.map = &r.map;
  std::vector<Vec2> path;
  path.reserve(r.trajectory.size());
  for (const StampedPose2& p : r.trajectory) path.push_back(p.pose.translation());
  if (!path.empty()) layers.robots_m.push_back(path.back());
  layers.paths_m.push_back(std::move(path));
  Result<std::string> png = render_png(layers);
  if (!png) return report_error(png.error());
  const std::string trajectory = encode_tum_trajectory(r.trajectory);
  const std::string graph = encode_g2o(r.graph);
  const std::string json = encode_json(report);
  const std::array<PendingFile, 4> files{{{out_ / "map.png", *png},
                                          {out_ / "trajectory.txt", trajectory},
                                          {out_ / "graph.g2o", graph},
                                          {out_ / "report.json", json}}};
  if (Status s = write_files_atomic(files); !s) return report_error(s.error());

  if (!quiet_) {
    fmt::print(
        "slam: {} scans, {} nodes, {} submaps, {} loop closures; {:.1f} s for {:.1f} s of data "
        "({:.1f}x real time)\n",
        st.scans, st.nodes, st.submaps, st.loop_closures, wall_s, duration_s,
        wall_s > 0.0 ? duration_s / wall_s : 0.0);
    if (metric) {
      fmt::print(
          "relations: {} scored; translation {:.4f} +/- {:.4f} m, rotation {:.3f} +/- "
          "{:.3f} deg\n",
          metric->count, metric->trans_mean_m, metric->trans_std_m,
          rad_to_deg(metric->rot_mean_rad), rad_to_deg(metric->rot_std_rad));
    }
    fmt::print("outputs: {}/map.yaml map.pgm map.png trajectory.txt graph.g2o report.json\n",
               out_.string());
  }
  return kExitOk;
}

}  // namespace tessera::cli
