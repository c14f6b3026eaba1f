#pragma once
// One fuzz target per input format: a function that reads a file's bytes the way tessera's reader
// for that format does. The same targets run under libFuzzer (libfuzzer_main.cpp, one executable
// per format, the `fuzz` preset) and as GoogleTest regression tests (tests/fuzz/), which feed them
// every input a fuzzer ever found a problem with (tests/fuzz/regressions/<format>/).
//
// Adding a reader: fuzz/<format>_fuzz.cpp with a read function and TESSERA_FUZZ_TARGET, and one
// tessera_fuzz_harness(<format> ...) line in fuzz/harnesses.cmake.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "tessera/core/result.hpp"

namespace tessera::fuzz {

/// Reads `bytes` as the contents of the file `path` (named in errors; readers that follow
/// references to other files look for them next to it).
using ReadFunction = Status (*)(std::string_view bytes, const std::filesystem::path& path);

struct Target {
  std::string format;          // the harness's name and its regression folder's name
  std::string file_extension;  // what a file of the format is called, ".json"
  ReadFunction read = nullptr;
};

/// Registers a target (TESSERA_FUZZ_TARGET does it at start-up); returns true.
bool register_target(Target target);

/// Every registered target, in registration order.
[[nodiscard]] const std::vector<Target>& targets();

/// Empty when `status` is what a reader may answer for any input named `name`: success, or a
/// kInput error whose message is one line and names the file. Otherwise what is wrong with it.
[[nodiscard]] std::string outcome_problem(const Status& status, const std::string& name);

/// The status of a reader's result, its value dropped.
template <typename T>
[[nodiscard]] Status status_of(const Result<T>& result) {
  if (result) return Ok{};
  return result.error();
}

}  // namespace tessera::fuzz

/// Registers `read` as the fuzz target of `format`, whose files end in `extension`.
#define TESSERA_FUZZ_TARGET(format, extension, read)     \
  [[maybe_unused]] const bool tessera_fuzz_registered_ = \
      ::tessera::fuzz::register_target(::tessera::fuzz::Target{format, extension, read})
