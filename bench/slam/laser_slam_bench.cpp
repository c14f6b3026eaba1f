// Laser SLAM on the real Intel Research Lab log (first 1,088 s, 5,505 scans, raw odometry), scored
// with the Kummerle relation metric on the 1,033 relations inside it. Prints, for odometry alone,
// local SLAM (no loop closure) and the full pipeline: relation errors (mean/std of translation and
// rotation), wall time on one core, scans per second and the real-time factor.
//
//   laser_slam_bench [--log FILE] [--relations FILE] [--time-offset S] [--scans N]
//                    [--set key=value ...] [--out DIR] [--no-baselines]
//
// --set changes one option (see kSetters below) so that tuning needs no rebuild. --out writes
// map.png, trajectory.txt and local_trajectory.txt for a look at the result. The requirement
// (issue 4): full SLAM <= 0.03 m and <= 0.6 deg mean relation error, >= 30x real time on one core.
// --crop X0,Y0,X1,Y1 adds a close-up map_crop.png; --as-logged maps a (corrected) log at its own
// poses without SLAM. Diagnostics: DBG_WORST=1 lists the worst relations, DBG_OUTLIERS=1 the loop
// constraints the optimised graph disagrees with.
// The data folder is TESSERA_DATA_DIR, default ../shared/data beside the project.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "tessera/core/angle.hpp"
#include "tessera/eval/relation_metric.hpp"
#include "tessera/io/carmen_log.hpp"
#include "tessera/io/relations_file.hpp"
#include "tessera/render/render.hpp"
#include "tessera/io/tum_trajectory.hpp"
#include "tessera/slam/laser_slam.hpp"
#include "tessera/io/data_dir.hpp"

namespace tessera {
namespace {

using Setter = std::function<void(slam::LaserSlamOptions&, double)>;

const std::map<std::string, Setter>& setters() {
  static const std::map<std::string, Setter> kSetters = {
      {"points.max_range_m", [](auto& o, double v) { o.points.max_range_m = v; }},
      {"points.missing_ray_length_m", [](auto& o, double v) { o.points.missing_ray_length_m = v; }},
      {"matching_voxel_m", [](auto& o, double v) { o.matching_voxel_m = v; }},
      {"loop_points.max_length_m", [](auto& o, double v) { o.loop_points.max_length_m = v; }},
      {"loop_points.max_range_m", [](auto& o, double v) { o.loop_points.max_range_m = v; }},
      {"loop_points.min_num_points",
       [](auto& o, double v) { o.loop_points.min_num_points = static_cast<int>(v); }},
      {"submaps.resolution_m", [](auto& o, double v) { o.submaps.resolution_m = v; }},
      {"submaps.scans_per_submap",
       [](auto& o, double v) { o.submaps.scans_per_submap = static_cast<int>(v); }},
      {"submaps.hit", [](auto& o, double v) { o.submaps.insert.hit_probability = v; }},
      {"submaps.evidence_step_m", [](auto& o, double v) { o.submaps.hit_evidence_step_m = v; }},
      {"submaps.max_evidence", [](auto& o, double v) { o.submaps.max_hit_evidence_scale = v; }},
      {"submaps.miss", [](auto& o, double v) { o.submaps.insert.miss_probability = v; }},
      {"submaps.miss_margin_m", [](auto& o, double v) { o.submaps.insert.miss_margin_m = v; }},
      {"submaps.join_m", [](auto& o, double v) { o.submaps.insert.join_returns_within_m = v; }},
      {"map.join_m", [](auto& o, double v) { o.map_insert.join_returns_within_m = v; }},
      {"map.miss_margin_m", [](auto& o, double v) { o.map_insert.miss_margin_m = v; }},
      {"motion_filter.max_distance_m",
       [](auto& o, double v) { o.motion_filter.max_distance_m = v; }},
      {"motion_filter.max_angle_rad", [](auto& o, double v) { o.motion_filter.max_angle_rad = v; }},
      {"motion_filter.max_time_s", [](auto& o, double v) { o.motion_filter.max_time_s = v; }},
      {"real_time_search", [](auto& o, double v) { o.real_time_search = v != 0.0; }},
      {"real_time.linear_window_m", [](auto& o, double v) { o.real_time.linear_window_m = v; }},
      {"real_time.angular_window_rad",
       [](auto& o, double v) { o.real_time.angular_window_rad = v; }},
      {"use_odometry", [](auto& o, double v) { o.use_odometry = v != 0.0; }},
      {"without_odometry.linear_window_m",
       [](auto& o, double v) { o.real_time_without_odometry.linear_window_m = v; }},
      {"without_odometry.angular_window_rad",
       [](auto& o, double v) { o.real_time_without_odometry.angular_window_rad = v; }},
      {"without_odometry.translation_delta_cost_weight",
       [](auto& o, double v) { o.real_time_without_odometry.translation_delta_cost_weight = v; }},
      {"without_odometry.rotation_delta_cost_weight",
       [](auto& o, double v) { o.real_time_without_odometry.rotation_delta_cost_weight = v; }},
      {"real_time.step_range_m", [](auto& o, double v) { o.real_time.angular_step_range_m = v; }},
      {"refiner.translation_weight", [](auto& o, double v) { o.refiner.translation_weight = v; }},
      {"refiner.rotation_weight", [](auto& o, double v) { o.refiner.rotation_weight = v; }},
      {"refiner.max_iterations",
       [](auto& o, double v) { o.refiner.max_iterations = static_cast<int>(v); }},
      {"loop_closure", [](auto& o, double v) { o.loop_closure = v != 0.0; }},
      {"loop.linear_m", [](auto& o, double v) { o.loop_closer.window.linear_m = v; }},
      {"loop.angular_rad", [](auto& o, double v) { o.loop_closer.window.angular_rad = v; }},
      {"loop.depth",
       [](auto& o, double v) { o.loop_closer.branch_and_bound_depth = static_cast<int>(v); }},
      {"loop.min_score", [](auto& o, double v) { o.loop_closer.min_score = v; }},
      {"loop.refiner.translation_weight",
       [](auto& o, double v) { o.loop_closer.refiner.translation_weight = v; }},
      {"loop.refiner.rotation_weight",
       [](auto& o, double v) { o.loop_closer.refiner.rotation_weight = v; }},
      {"global.linear_m", [](auto& o, double v) { o.global_window.linear_m = v; }},
      {"global.angular_rad", [](auto& o, double v) { o.global_window.angular_rad = v; }},
      {"global_min_score", [](auto& o, double v) { o.global_min_score = v; }},
      {"global_sampling_ratio", [](auto& o, double v) { o.global_sampling_ratio = v; }},
      {"loop_min_overlap", [](auto& o, double v) { o.loop_min_overlap = v; }},
      {"loop_sampling_ratio", [](auto& o, double v) { o.loop_sampling_ratio = v; }},
      {"optimize_every_n_nodes",
       [](auto& o, double v) { o.optimize_every_n_nodes = static_cast<int>(v); }},
      {"optimizer_iterations",
       [](auto& o, double v) { o.optimizer_iterations = static_cast<int>(v); }},
      {"local_sigmas.t", [](auto& o, double v) { o.local_sigmas.translation_m = v; }},
      {"local_per_m.t", [](auto& o, double v) { o.local_sigmas_per_m.translation_m = v; }},
      {"local_per_m.r", [](auto& o, double v) { o.local_sigmas_per_m.rotation_rad = v; }},
      {"local_sigmas.r", [](auto& o, double v) { o.local_sigmas.rotation_rad = v; }},
      {"submap_sigmas.t", [](auto& o, double v) { o.submap_sigmas.translation_m = v; }},
      {"submap_sigmas.r", [](auto& o, double v) { o.submap_sigmas.rotation_rad = v; }},
      {"loop_sigmas.t", [](auto& o, double v) { o.loop_sigmas.translation_m = v; }},
      {"loop_sigmas.r", [](auto& o, double v) { o.loop_sigmas.rotation_rad = v; }},
      {"loop_hessian_scale", [](auto& o, double v) { o.loop_hessian_scale = v; }},
      {"submaps.travel_m", [](auto& o, double v) { o.submaps.travel_per_submap_m = v; }},
      {"growth_m", [](auto& o, double v) { o.loop_window_growth_m_per_m = v; }},
      {"growth_rad", [](auto& o, double v) { o.loop_window_growth_rad_per_m = v; }},
      {"max_window_m", [](auto& o, double v) { o.loop_window_max.linear_m = v; }},
      {"verify_beyond", [](auto& o, double v) { o.verify_beyond = v; }},
      {"verify_span", [](auto& o, double v) { o.verify_span_nodes = static_cast<int>(v); }},
      {"verify_m", [](auto& o, double v) { o.verify_tolerance.linear_m = v; }},
      {"verify_rad", [](auto& o, double v) { o.verify_tolerance.angular_rad = v; }},
      {"outlier_sigmas", [](auto& o, double v) { o.loop_outlier_sigmas = v; }},
      {"wrong_share", [](auto& o, double v) { o.wrong_closure_share = v; }},
      {"wrong_seed",
       [](auto& o, double v) { o.wrong_closure_seed = static_cast<std::uint64_t>(v); }},
      {"refiner.unknown", [](auto& o, double v) { o.refiner.unknown_probability = v; }},
      {"loop.refiner.unknown",
       [](auto& o, double v) { o.loop_closer.refiner.unknown_probability = v; }},
      {"final.unknown", [](auto& o, double v) { o.final_map_refiner.unknown_probability = v; }},
      {"calibrate", [](auto& o, double v) { o.odometry_calibration.enabled = v != 0.0; }},
      {"calibrate.min_travel_m",
       [](auto& o, double v) { o.odometry_calibration.min_travel_m = v; }},
      {"calibrate.min_turn_rad",
       [](auto& o, double v) { o.odometry_calibration.min_turn_rad = v; }},
      {"calibrate.segment_m", [](auto& o, double v) { o.odometry_calibration.segment_m = v; }},
      {"calibrate.segment_rad", [](auto& o, double v) { o.odometry_calibration.segment_rad = v; }},
      {"calibrate.memory_m", [](auto& o, double v) { o.odometry_calibration.memory_m = v; }},
      {"calibrate.max_error",
       [](auto& o, double v) { o.odometry_calibration.max_scale_error = v; }},
      {"calibrate.max_drift",
       [](auto& o, double v) { o.odometry_calibration.max_drift_rad_per_m = v; }},
      {"huber_scale", [](auto& o, double v) { o.huber_scale = v; }},
      {"final.passes", [](auto& o, double v) { o.final_map_passes = static_cast<int>(v); }},
      {"final.hessian", [](auto& o, double v) { o.final_map_hessian_scale = v; }},
      {"final.t", [](auto& o, double v) { o.final_map_refiner.translation_weight = v; }},
      {"final.r", [](auto& o, double v) { o.final_map_refiner.rotation_weight = v; }},
      {"final.iter",
       [](auto& o, double v) { o.final_map_refiner.max_iterations = static_cast<int>(v); }},
  };
  return kSetters;
}

void print_metric(const char* name, const std::vector<StampedPose2>& trajectory,
                  const std::vector<Relation>& relations, double time_offset_s) {
  if (relations.empty()) return;
  const Result<RelationMetric> m = relation_metric(trajectory, relations, time_offset_s);
  if (!m) {
    std::printf("%-22s relation metric: %s\n", name, m.error().message.c_str());
    return;
  }
  if (std::getenv("DBG_WORST") != nullptr) {
    std::vector<RelationError> worst = m->errors;
    std::sort(worst.begin(), worst.end(),
              [](const RelationError& a, const RelationError& b) { return a.rot_rad > b.rot_rad; });
    for (std::size_t i = 0; i < std::min<std::size_t>(8, worst.size()); ++i) {
      std::printf("  worst %zu: t1 %.3f t2 %.3f  %.4f m %.3f deg\n", i,
                  worst[i].t1_s - time_offset_s, worst[i].t2_s - time_offset_s, worst[i].trans_m,
                  rad_to_deg(worst[i].rot_rad));
    }
  }
  // Short relations (< 10 s apart) measure local accuracy, long ones global consistency.
  double short_t = 0.0, short_r = 0.0, long_t = 0.0, long_r = 0.0;
  int n_short = 0, n_long = 0;
  for (const RelationError& e : m->errors) {
    if (std::abs(e.t2_s - e.t1_s) < 10.0) {
      short_t += e.trans_m;
      short_r += e.rot_rad;
      ++n_short;
    } else {
      long_t += e.trans_m;
      long_r += e.rot_rad;
      ++n_long;
    }
  }
  std::printf(
      "%-22s relations %4zu  trans %.4f +- %.4f m  rot %.3f +- %.3f deg  | short %d: %.4f m "
      "%.3f deg  long %d: %.4f m %.3f deg\n",
      name, m->count, m->trans_mean_m, m->trans_std_m, rad_to_deg(m->rot_mean_rad),
      rad_to_deg(m->rot_std_rad), n_short, short_t / std::max(n_short, 1),
      rad_to_deg(short_r / std::max(n_short, 1)), n_long, long_t / std::max(n_long, 1),
      rad_to_deg(long_r / std::max(n_long, 1)));
}

int run(int argc, char** argv) {
  std::filesystem::path log_path = data_dir() / "laser/intel/intel-raw-first5505-sot.clf";
  std::filesystem::path relations_path = data_dir() / "laser/intel/intel.relations";
  double time_offset_s = 976052857.337284;
  long max_scans = -1;
  bool baselines = true;
  std::filesystem::path out;
  slam::LaserSlamOptions options;
  double crop[4] = {};
  bool use_crop = false;
  bool as_logged = false;  // map the scans at the log's own poses (a corrected log), no SLAM
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (arg == "--log" && has_value) {
      log_path = argv[++i];
    } else if (arg == "--relations" && has_value) {
      relations_path = argv[++i];
    } else if (arg == "--time-offset" && has_value) {
      time_offset_s = std::atof(argv[++i]);
    } else if (arg == "--scans" && has_value) {
      max_scans = std::atol(argv[++i]);
    } else if (arg == "--out" && has_value) {
      out = argv[++i];
    } else if (arg == "--crop" && has_value) {
      const int got =
          std::sscanf(argv[++i], "%lf,%lf,%lf,%lf", &crop[0], &crop[1], &crop[2], &crop[3]);
      if (got != 4) return 2;
      use_crop = true;
    } else if (arg == "--as-logged") {
      as_logged = true;
    } else if (arg == "--no-baselines") {
      baselines = false;
    } else if (arg == "--set" && has_value) {
      const std::string kv = argv[++i];
      const auto eq = kv.find('=');
      const auto it = setters().find(kv.substr(0, eq));
      if (eq == std::string::npos || it == setters().end()) {
        std::fprintf(stderr, "unknown --set %s; keys:", kv.c_str());
        for (const auto& [k, f] : setters()) std::fprintf(stderr, " %s", k.c_str());
        std::fprintf(stderr, "\n");
        return 2;
      }
      it->second(options, std::atof(kv.c_str() + eq + 1));
    } else {
      std::fprintf(stderr, "unknown argument %s\n", arg.c_str());
      return 2;
    }
  }
  if (auto problem = slam::validate(options)) {
    std::fprintf(stderr, "options: %s\n", problem->c_str());
    return 2;
  }

  Result<LaserLog> log = read_carmen_log(log_path);
  if (!log) {
    std::fprintf(stderr, "%s\n", log.error().message.c_str());
    return 3;
  }
  if (max_scans >= 0 && static_cast<std::size_t>(max_scans) < log->scans.size()) {
    log->scans.resize(static_cast<std::size_t>(max_scans));
  }
  // "--relations none": a log without relations (a perturbed corrected log, scored by ATE outside).
  Result<std::vector<Relation>> relations =
      relations_path == "none" ? Result<std::vector<Relation>>(std::vector<Relation>{})
                               : read_relations(relations_path);
  if (!relations) {
    std::fprintf(stderr, "%s\n", relations.error().message.c_str());
    return 3;
  }
  double t_min = log->scans.front().t_s, t_max = t_min;
  for (const StampedScan& s : log->scans) {
    t_min = std::min(t_min, s.t_s);
    t_max = std::max(t_max, s.t_s);
  }
  const double duration_s = t_max - t_min;
  std::printf("log %s: %zu scans, %.1f s of data, %d backward stamps\n",
              log_path.filename().c_str(), log->scans.size(), duration_s, log->backward_stamps);

  if (baselines) {
    std::vector<StampedPose2> odometry;
    for (const StampedScan& s : log->scans) odometry.push_back({s.t_s, s.odometry});
    print_metric("odometry", odometry, *relations, time_offset_s);
  }

  if (as_logged) {
    // A corrected log's poses are a SLAM result; loop_closure off and no matching is not what we
    // want here, so build the map directly from the logged poses.
    const slam::RangeInserter inserter(options.map_insert);
    slam::ProbabilityGrid grid(GridGeometry({-10.0, -10.0}, options.map_resolution_m, 400, 400));
    for (const StampedScan& s : log->scans) {
      inserter.insert(grid, s.odometry, slam::scan_to_points(s, options.points));
    }
    const OccupancyGrid map = grid.to_occupancy_grid(2);
    RenderLayers bare;
    bare.map = &map;
    std::filesystem::create_directories(out);
    if (Status s = write_png(out / "map_as_logged.png", bare); !s) return 4;
    const GridGeometry& mg = map.geometry();
    std::printf("map: origin (%.2f, %.2f) m, %d x %d cells\n", mg.origin().x, mg.origin().y,
                mg.width(), mg.height());
    return 0;
  }
  // Scan by scan, so that the time of each add_scan (matching, loop search and the optimisations
  // it triggers) gives the per-scan median and 99th percentile.
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<double> scan_ms;
  scan_ms.reserve(log->scans.size());
  Result<slam::LaserSlamResult> result = [&]() -> Result<slam::LaserSlamResult> {
    slam::LaserSlam slam(options);
    for (const StampedScan& scan : log->scans) {
      const auto ts = std::chrono::steady_clock::now();
      if (Status s = slam.add_scan(scan); !s) return s.error();
      scan_ms.push_back(
          1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - ts).count());
    }
    return slam.finish();
  }();
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!scan_ms.empty()) {
    std::sort(scan_ms.begin(), scan_ms.end());
    const auto at = [&](double q) {
      return scan_ms[std::min(scan_ms.size() - 1,
                              static_cast<std::size_t>(q * static_cast<double>(scan_ms.size())))];
    };
    std::printf("per scan: median %.2f ms, 99th percentile %.2f ms, max %.2f ms\n", at(0.5),
                at(0.99), scan_ms.back());
  }
  if (!result) {
    std::fprintf(stderr, "slam: %s\n", result.error().message.c_str());
    return 4;
  }
  const slam::LaserSlamStats& st = result->stats;
  print_metric("local SLAM (no loops)", result->local_trajectory, *relations, time_offset_s);
  print_metric("full SLAM", result->trajectory, *relations, time_offset_s);
  std::printf(
      "nodes %d  submaps %d  loop searches %d (global %d)  loop closures %d  optimisations %d  "
      "edges %zu  max loop correction %.3f m %.4f rad  candidates %d unverified %d rejected %d wrong injected %d\n",
      st.nodes, st.submaps, st.loop_searches, st.global_searches, st.loop_closures,
      st.optimizations, result->graph.edges.size(), st.max_loop_correction_m,
      st.max_loop_correction_rad, st.loop_candidates, st.loop_unverified, st.loop_rejected,
      st.loop_wrong_injected);
  std::printf("odometry scales: translation %.4f rotation %.4f drift %.5f rad/m\n",
              st.odometry_translation_scale, st.odometry_rotation_scale,
              st.odometry_drift_rad_per_m);
  {
    // Loop constraints the final graph disagrees with: outliers the robust loss had to absorb.
    int robust = 0, off_10cm = 0, off_50cm = 0;
    for (const posegraph::PoseGraphEdge& e : result->graph.edges) {
      if (!e.robust) continue;
      ++robust;
      const Pose2 err = between(between(result->graph.poses[static_cast<std::size_t>(e.from)],
                                        result->graph.poses[static_cast<std::size_t>(e.to)]),
                                e.measurement);
      const double d = std::hypot(err.x, err.y);
      off_10cm += d > 0.1 ? 1 : 0;
      off_50cm += d > 0.5 ? 1 : 0;
      if (d > 0.1 && std::getenv("DBG_OUTLIERS") != nullptr) {
        std::printf("outlier %d -> %d (scan %d) off %.3f m\n", e.from, e.to,
                    result->vertex_scan[static_cast<std::size_t>(e.to)], d);
      }
    }
    std::printf("loop constraints %d: %d off by > 0.1 m, %d by > 0.5 m after optimisation\n",
                robust, off_10cm, off_50cm);
  }
  std::printf(
      "wall %.2f s (matching %.2f, loop search %.2f, optimisation %.2f, whole-map matches "
      "%.2f, map %.2f)  %.2f ms/scan  %.0f scans/s  real-time factor %.1f\n",
      wall_s, st.matching_s, st.loop_search_s, st.optimization_s, st.whole_map_s, st.map_s,
      1e3 * wall_s / static_cast<double>(st.scans), static_cast<double>(st.scans) / wall_s,
      duration_s / wall_s);

  if (!out.empty()) {
    const GridGeometry& mg = result->map.geometry();
    std::printf("map: origin (%.2f, %.2f) m, %d x %d cells of %.3f m\n", mg.origin().x,
                mg.origin().y, mg.width(), mg.height(), mg.resolution_m());
    std::filesystem::create_directories(out);
    RenderLayers layers;
    layers.map = &result->map;
    std::vector<Vec2> path;
    for (const StampedPose2& p : result->trajectory) path.push_back(p.pose.translation());
    layers.paths_m.push_back(path);
    if (Status s = write_png(out / "map.png", layers); !s) {
      std::fprintf(stderr, "%s\n", s.error().message.c_str());
    }
    RenderLayers bare;
    bare.map = &result->map;
    if (Status s = write_png(out / "map_only.png", bare); !s) {
      std::fprintf(stderr, "%s\n", s.error().message.c_str());
    }
    if (use_crop) {
      // A close-up of the map (metres, map frame) at 4 pixels per cell.
      const GridGeometry& g = result->map.geometry();
      const Cell lo = g.cell_at_unchecked({crop[0], crop[1]});
      const Cell hi = g.cell_at_unchecked({crop[2], crop[3]});
      OccupancyGrid part(
          GridGeometry(g.center_of(lo) - Vec2{0.5 * g.resolution_m(), 0.5 * g.resolution_m()},
                       g.resolution_m(), hi.x - lo.x + 1, hi.y - lo.y + 1));
      for (int y = lo.y; y <= hi.y; ++y) {
        for (int x = lo.x; x <= hi.x; ++x) {
          const Cell c{x, y};
          if (g.contains(c) && result->map.known(c)) {
            part.set_probability(c - lo, *result->map.probability_at(c));
          }
        }
      }
      RenderLayers close;
      close.map = &part;
      if (Status s = write_png(out / "map_crop.png", close, 4); !s) {
        std::fprintf(stderr, "%s\n", s.error().message.c_str());
      }
    }
    if (Status s = write_tum_trajectory(out / "trajectory.txt", result->trajectory); !s) {
      std::fprintf(stderr, "%s\n", s.error().message.c_str());
    }
    if (Status s = write_tum_trajectory(out / "local_trajectory.txt", result->local_trajectory);
        !s) {
      std::fprintf(stderr, "%s\n", s.error().message.c_str());
    }
  }
  return 0;
}

}  // namespace
}  // namespace tessera

int main(int argc, char** argv) { return tessera::run(argc, argv); }
