// libFuzzer's entry point for one fuzz target (the executable links exactly one harness). Any
// outcome other than those outcome_problem allows (a crash, a sanitizer report, an exception, an
// error of the wrong kind or without the file's name) aborts, so libFuzzer saves the input.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "fuzz_target.hpp"

namespace {

// The name the inputs are read under: in a folder of its own, so that readers which look for
// referenced files (a map YAML's image, a Stage world's bitmap) find none of the fuzzer's files.
std::filesystem::path input_path(const tessera::fuzz::Target& target) {
  return std::filesystem::path("/nonexistent-fuzz-dir") / ("input" + target.file_extension);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto& all = tessera::fuzz::targets();
  if (all.size() != 1) {
    std::fprintf(stderr, "fuzz: expected exactly one registered target, got %zu\n", all.size());
    std::abort();
  }
  const tessera::fuzz::Target& target = all.front();
  const std::filesystem::path path = input_path(target);
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  const tessera::Status status = target.read(bytes, path);
  if (const std::string problem = tessera::fuzz::outcome_problem(status, path.string());
      !problem.empty()) {
    std::fprintf(stderr, "fuzz %s: %s\n", target.format.c_str(), problem.c_str());
    std::abort();
  }
  return 0;
}
