#pragma once
// Numbers in the fusion module's reason texts ("too little valid depth: 12.5% ...").
#include <iomanip>
#include <sstream>
#include <string>

namespace tessera::fusion::internal {

/// `v` in fixed notation with `digits` decimals ("12.5" for fixed(12.5, 1)).
[[nodiscard]] inline std::string fixed(double v, int digits) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << v;
  return s.str();
}

}  // namespace tessera::fusion::internal
