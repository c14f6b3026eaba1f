#include <fmt/format.h>

#include <array>
#include <chrono>
#include <nlohmann/json.hpp>
#include <string>

#include "commands.hpp"
#include "tessera/io/atomic_file.hpp"
#include "tessera/io/g2o_file.hpp"
#include "tessera/io/json_file.hpp"
#include "tessera/posegraph/pose_graph.hpp"
#include "tessera/report/core_report.hpp"

namespace tessera::cli {

PosegraphCommand::PosegraphCommand(CLI::App& app) {
  sub_ = app.add_subcommand("posegraph", "Pose-graph tools (g2o files)");
  sub_->require_subcommand(1);
  optimize_ = sub_->add_subcommand(
      "optimize",
      "Optimise a 2D pose graph (VERTEX_SE2/EDGE_SE2 g2o; a file of edges only gets its initial "
      "poses by chaining the odometry edges) with Ceres; writes the optimised graph and a "
      "report.json");
  iterations_ = posegraph::OptimizeOptions{}.max_iterations;
  optimize_->add_option("in", in_, "Input pose graph (.g2o)")->required();
  optimize_->add_option("out", out_, "Output pose graph (.g2o)")->required();
  optimize_->add_option("--report", report_,
                        "Where to write the report (default: <out stem>.report.json beside out)");
  optimize_->add_option("--iterations", iterations_, "Most solver iterations")
      ->check(CLI::Range(1, 1000000))
      ->capture_default_str();
  optimize_->add_flag("--quiet", quiet_, "No summary line");
}

int PosegraphCommand::run() const {
  const auto start = std::chrono::steady_clock::now();
  const std::filesystem::path report_path =
      report_ ? *report_ : out_.parent_path() / (out_.stem().string() + ".report.json");
  if (report_path == out_) {
    return report_error(usage_error(out_.string() + ": the report would overwrite the graph"));
  }
  Result<posegraph::PoseGraph> graph = read_g2o(in_);
  if (!graph) return report_error(graph.error());

  posegraph::OptimizeOptions options;
  options.max_iterations = iterations_;
  const Result<posegraph::OptimizeSummary> optimized = posegraph::optimize(*graph, options);
  if (!optimized) return report_error(optimized.error());
  const posegraph::OptimizeSummary& s = *optimized;
  const double wall_s = seconds_since(start);

  // Nothing is random and a pose graph has no data clock: seed and data_duration_s are null.
  nlohmann::json report = core_report(
      {"posegraph optimize", std::nullopt, {{"iterations", iterations_}}, wall_s, std::nullopt});
  report.update(nlohmann::json{{"input", {{"file", in_.string()}}},
                                 {"output", {{"file", out_.string()}}},
                                 {"posegraph",
                                  {{"nodes", graph->poses.size()},
                                   {"edges", graph->edges.size()},
                                   {"initial_cost", s.initial_cost},
                                   {"final_cost", s.final_cost},
                                   {"iterations", s.iterations},
                                   {"time_s", s.time_s},
                                   {"converged", s.converged},
                                   {"termination", s.termination}}}});
  const std::string g2o = encode_g2o(*graph);
  const std::string json = encode_json(report);
  const std::array<PendingFile, 2> files{{{out_, g2o}, {report_path, json}}};
  if (Status written = write_files_atomic(files); !written) return report_error(written.error());

  if (!quiet_) {
    fmt::print(
        "posegraph: {} nodes, {} edges, cost {:.6g} -> {:.6g}, {} iterations, {:.3f} s, {}\n",
        graph->poses.size(), graph->edges.size(), s.initial_cost, s.final_cost, s.iterations,
        s.time_s, s.converged ? "converged" : "not converged");
  }
  return kExitOk;
}

}  // namespace tessera::cli
