#pragma once
// Readable GoogleTest and gmock output for grid cells, "(x, y)", found by argument-dependent
// lookup; shared by every test that compares cells.
#include <ostream>

#include "tessera/core/cell.hpp"

namespace tessera {

inline void PrintTo(const Cell& c, std::ostream* os) { *os << "(" << c.x << ", " << c.y << ")"; }

}  // namespace tessera
