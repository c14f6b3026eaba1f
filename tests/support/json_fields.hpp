#pragma once
// Small readers of report JSON shared by the report tests: an object's key set and a number.
#include <nlohmann/json.hpp>

#include <set>
#include <string>

namespace tessera::support {

inline std::set<std::string> keys(const nlohmann::json& j) {
  std::set<std::string> k;
  for (const auto& [key, value] : j.items()) k.insert(key);
  return k;
}

inline double num(const nlohmann::json& j) { return j.get<double>(); }

}  // namespace tessera::support
