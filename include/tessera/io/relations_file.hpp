#pragma once
// Ground-truth relations files of the SLAM benchmark (Kummerle et al. 2009, "On measuring the
// accuracy of SLAM algorithms"), as distributed with the Intel and FR079 logs.
#include <filesystem>
#include <vector>

#include "tessera/core/relation.hpp"
#include "tessera/core/result.hpp"

namespace tessera {

/// Reads one relation per line, `t1 t2 x y z roll pitch yaw` (s, s, m, m, m, rad, rad, rad): the
/// pose of the robot at t2 in the robot frame at t1. x, y and yaw are kept (z, roll and pitch are 0
/// in 2D files and are only checked to be numbers); yaw is wrapped into [-pi, pi). '#' comments and
/// blank lines are skipped; file order is kept.
/// Errors, kInput "<path>:<line>: ...": an unreadable file, a line without exactly 8 fields, a
/// field that is not a finite number, and a file with no relations.
[[nodiscard]] Result<std::vector<Relation>> read_relations(const std::filesystem::path& path);

}  // namespace tessera
