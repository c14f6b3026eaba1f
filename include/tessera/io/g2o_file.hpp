#pragma once
// g2o text files of 2D pose graphs, the format of the pose-graph benchmarks (Intel, M3500) in
// Luca Carlone's collection and SE-Sync's data/ folder.
#include <filesystem>
#include <string>

#include "tessera/core/result.hpp"
#include "tessera/posegraph/pose_graph.hpp"

namespace tessera {

/// Reads `VERTEX_SE2 id x y theta` (the initial pose, m, m, rad) and `EDGE_SE2 i j dx dy dtheta I11
/// I12 I13 I22 I23 I33` (the pose of j in the frame of i, then the upper triangle of its 3x3
/// information matrix, row-major, order x, y, theta). Nodes are numbered in the order of their
/// VERTEX_SE2 lines and PoseGraph::ids keeps the g2o ids; edges are in file order and not robust.
/// A file with edges only (M3500) gets its nodes from the edge ids in ascending order, the smallest
/// at the origin and each next one placed by chaining the odometry edge `EDGE_SE2 id-1 id`.
/// Angles are wrapped into [-pi, pi). Other tags (FIX, landmarks), '#' comments and blank lines are
/// skipped.
/// Errors, kInput "<path>:<line>: ...": an unreadable file, a line with the wrong number of fields
/// or a field that is not a finite number, a repeated vertex id, an edge from a vertex to itself,
/// an information matrix that is not positive definite, an edge naming a vertex without a
/// VERTEX_SE2 line (when the file has any), a vertex the odometry chain does not reach (edges
/// only), and a file with no vertex and no edge.
[[nodiscard]] Result<posegraph::PoseGraph> read_g2o(const std::filesystem::path& path);

/// g2o text of `graph`: one VERTEX_SE2 per node, then one EDGE_SE2 per edge, each number in its
/// shortest round-trip form, so read_g2o(encode) gives the graph back exactly. Node i is written
/// with id ids[i], or i when ids is empty. Precondition: ids is empty or has one id per pose, and
/// every edge names existing nodes.
[[nodiscard]] std::string encode_g2o(const posegraph::PoseGraph& graph);

/// Writes encode_g2o(graph) to `path` atomically.
[[nodiscard]] Status write_g2o(const std::filesystem::path& path,
                               const posegraph::PoseGraph& graph);

}  // namespace tessera
