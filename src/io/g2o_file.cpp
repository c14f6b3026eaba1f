#include "tessera/io/g2o_file.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <array>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "internal/decoders.hpp"
#include "internal/file_util.hpp"
#include "internal/text_fields.hpp"
#include "tessera/io/atomic_file.hpp"

namespace tessera {
namespace {

using io_internal::format_double;

/// An EDGE_SE2 line before its vertex ids are turned into node indices.
struct RawEdge {
  int from_id = 0;
  int to_id = 0;
  posegraph::PoseGraphEdge edge;
  int line_no = 0;
};

/// The order of the information entries on an EDGE_SE2 line: I11 I12 I13 I22 I23 I33.
constexpr std::array<std::pair<int, int>, 6> kUpperTriangle = {
    {{0, 0}, {0, 1}, {0, 2}, {1, 1}, {1, 2}, {2, 2}}};

/// The numbers after the ids: the pose (VERTEX_SE2) or measurement and information (EDGE_SE2).
constexpr std::array<std::string_view, 9> kValueNames = {"x",   "y",   "theta", "I11", "I12",
                                                         "I13", "I22", "I23",   "I33"};

/// Symmetric information matrix from the upper triangle I11 I12 I13 I22 I23 I33.
Eigen::Matrix3d information_from_upper(const std::array<double, 6>& u) {
  Eigen::Matrix3d m;
  m << u[0], u[1], u[2], u[1], u[3], u[4], u[2], u[4], u[5];
  return m;
}

/// Turns edge ids into node indices when the file has VERTEX_SE2 lines.
Status resolve_with_vertices(const std::string& file, const std::vector<RawEdge>& raw,
                             const std::unordered_map<int, int>& index_of,
                             posegraph::PoseGraph& g) {
  for (const RawEdge& r : raw) {
    for (int id : {r.from_id, r.to_id}) {
      if (!index_of.contains(id)) {
        return input_error(file + ":" + std::to_string(r.line_no) + ": EDGE_SE2 names vertex " +
                           std::to_string(id) + ", which has no VERTEX_SE2 line");
      }
    }
    posegraph::PoseGraphEdge e = r.edge;
    e.from = index_of.at(r.from_id);
    e.to = index_of.at(r.to_id);
    g.edges.push_back(e);
  }
  return Ok{};
}

/// Edges only (M3500): the nodes are the edge ids in ascending order, the first at the origin and
/// each next one placed by the odometry edge from the id before it.
Status resolve_by_chaining(const std::string& file, const std::vector<RawEdge>& raw,
                           posegraph::PoseGraph& g) {
  std::unordered_map<int, int> first_line;              // where each id first appears, for errors
  std::unordered_map<int, const RawEdge*> odometry_to;  // id -> the first edge id-1 -> id
  for (const RawEdge& r : raw) {
    first_line.try_emplace(r.from_id, r.line_no);
    first_line.try_emplace(r.to_id, r.line_no);
    if (r.to_id - 1 == r.from_id) odometry_to.try_emplace(r.to_id, &r);
  }
  for (const auto& entry : first_line) g.ids.push_back(entry.first);
  std::sort(g.ids.begin(), g.ids.end());
  std::unordered_map<int, int> index_of;
  g.poses.reserve(g.ids.size());
  for (std::size_t i = 0; i < g.ids.size(); ++i) {
    const int id = g.ids[i];
    index_of[id] = static_cast<int>(i);
    if (i == 0) {
      g.poses.push_back({});
      continue;
    }
    const auto it = odometry_to.find(id);
    if (it == odometry_to.end()) {
      return input_error(file + ":" + std::to_string(first_line.at(id)) + ": vertex " +
                         std::to_string(id) +
                         " is not reached by the odometry chain: the file has no VERTEX_SE2 "
                         "lines and no EDGE_SE2 " +
                         std::to_string(id - 1) + " " + std::to_string(id));
    }
    g.poses.push_back(g.poses.back() * it->second->edge.measurement);
  }
  return resolve_with_vertices(file, raw, index_of, g);
}

}  // namespace

Result<posegraph::PoseGraph> read_g2o(const std::filesystem::path& path) {
  Result<std::string> bytes = io_internal::read_file_bytes(path);
  if (!bytes) return bytes.error();
  return io_internal::decode_g2o(*bytes, path.string());
}

namespace io_internal {

Result<posegraph::PoseGraph> decode_g2o(std::string_view text, const std::string& file) {
  posegraph::PoseGraph graph;
  std::unordered_map<int, int> index_of;     // g2o id -> node index
  std::unordered_map<int, int> vertex_line;  // g2o id -> line of its VERTEX_SE2
  std::vector<RawEdge> raw;

  const Status read = io_internal::for_each_record(
      text, [&](int line_no, const std::vector<std::string_view>& fields) -> Status {
        const std::string_view tag = fields.front();
        const bool vertex = tag == "VERTEX_SE2";
        if (!vertex && tag != "EDGE_SE2") return Ok{};
        const std::string where = file + ":" + std::to_string(line_no) + ": ";
        const std::size_t expected = vertex ? 5 : 12;
        if (fields.size() != expected) {
          return input_error(where + std::string(tag) + " line has " +
                             std::to_string(fields.size()) + " fields, expected " +
                             std::to_string(expected) +
                             (vertex ? " (VERTEX_SE2 id x y theta)"
                                     : " (EDGE_SE2 i j dx dy dtheta I11 I12 I13 I22 I23 I33)"));
        }
        const std::size_t ids = vertex ? 1 : 2;
        std::array<int, 2> id{};
        for (std::size_t k = 0; k < ids; ++k) {
          if (!io_internal::parse_int(fields[1 + k], id[k])) {
            return input_error(where + std::string(tag) + " vertex id '" +
                               std::string(fields[1 + k]) + "' is not an integer");
          }
        }
        std::array<double, 9> v{};
        for (std::size_t k = 0; k + 1 + ids < fields.size(); ++k) {
          if (!io_internal::parse_double(fields[k + 1 + ids], v[k])) {
            return input_error(where + std::string(tag) + " " + std::string(kValueNames[k]) +
                               " is '" + std::string(fields[k + 1 + ids]) +
                               "', expected a finite number");
          }
        }
        const Pose2 pose{v[0], v[1], io_internal::wrap_angle(v[2])};
        if (vertex) {
          if (const auto it = vertex_line.find(id[0]); it != vertex_line.end()) {
            return input_error(where + "vertex " + std::to_string(id[0]) +
                               " is already defined on line " + std::to_string(it->second));
          }
          vertex_line[id[0]] = line_no;
          index_of[id[0]] = static_cast<int>(graph.poses.size());
          graph.poses.push_back(pose);
          graph.ids.push_back(id[0]);
          return Ok{};
        }
        if (id[0] == id[1]) {
          return input_error(where + "EDGE_SE2 joins vertex " + std::to_string(id[0]) +
                             " to itself");
        }
        RawEdge r{id[0], id[1], {}, line_no};
        r.edge.measurement = pose;
        r.edge.information = information_from_upper({v[3], v[4], v[5], v[6], v[7], v[8]});
        if (Eigen::LLT<Eigen::Matrix3d>(r.edge.information).info() != Eigen::Success) {
          return input_error(where + "EDGE_SE2 " + std::to_string(id[0]) + " " +
                             std::to_string(id[1]) +
                             ": information matrix is not positive definite");
        }
        raw.push_back(r);
        return Ok{};
      });
  if (!read) return read.error();

  if (graph.poses.empty() && raw.empty()) {
    return input_error(file + ": no VERTEX_SE2 or EDGE_SE2 lines");
  }
  const Status resolved = graph.poses.empty() ? resolve_by_chaining(file, raw, graph)
                                              : resolve_with_vertices(file, raw, index_of, graph);
  if (!resolved) return resolved.error();
  return graph;
}

}  // namespace io_internal

std::string encode_g2o(const posegraph::PoseGraph& graph) {
  TESSERA_ASSERT(graph.ids.empty() || graph.ids.size() == graph.poses.size());
  const auto id_of = [&](int node) {
    return graph.ids.empty() ? node : graph.ids[static_cast<std::size_t>(node)];
  };
  std::string out;
  for (std::size_t i = 0; i < graph.poses.size(); ++i) {
    const Pose2& p = graph.poses[i];
    out += "VERTEX_SE2 " + std::to_string(id_of(static_cast<int>(i))) + " " + format_double(p.x) +
           " " + format_double(p.y) + " " + format_double(p.theta) + "\n";
  }
  const int n = static_cast<int>(graph.poses.size());
  for (const posegraph::PoseGraphEdge& e : graph.edges) {
    TESSERA_ASSERT(0 <= e.from && e.from < n && 0 <= e.to && e.to < n);
    const Pose2& z = e.measurement;
    const Eigen::Matrix3d& I = e.information;
    out += "EDGE_SE2 " + std::to_string(id_of(e.from)) + " " + std::to_string(id_of(e.to)) + " " +
           format_double(z.x) + " " + format_double(z.y) + " " + format_double(z.theta);
    for (const auto& [r, c] : kUpperTriangle) out += " " + format_double(I(r, c));
    out += "\n";
  }
  return out;
}

Status write_g2o(const std::filesystem::path& path, const posegraph::PoseGraph& graph) {
  return write_file_atomic(path, encode_g2o(graph));
}

}  // namespace tessera
