#include "fuzz_target.hpp"

#include <utility>

namespace tessera::fuzz {
namespace {

std::vector<Target>& registry() {
  static std::vector<Target> all;
  return all;
}

}  // namespace

bool register_target(Target target) {
  registry().push_back(std::move(target));
  return true;
}

const std::vector<Target>& targets() { return registry(); }

std::string outcome_problem(const Status& status, const std::string& name) {
  if (status) return {};
  const Error& e = status.error();
  if (e.kind != ErrorKind::kInput) return "error of a kind other than kInput: " + e.message;
  if (e.message.find('\n') != std::string::npos || e.message.find('\r') != std::string::npos) {
    return "error message spans several lines: " + e.message;
  }
  if (e.message.find(name) == std::string::npos) {
    return "error message does not name the file " + name + ": " + e.message;
  }
  return {};
}

}  // namespace tessera::fuzz
