// Every input a fuzzer found a problem with (a crash, a sanitizer report, an escaped exception, an
// error that did not name the file) is kept in tests/fuzz/regressions/<format>/ and must now be
// read as what it is: bad input, answered with one kInput error line that names the file.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "fuzz_target.hpp"
#include "support/temp_dir.hpp"

namespace tessera::fuzz {
namespace {

const std::filesystem::path kRegressions = TESSERA_FUZZ_REGRESSIONS_DIR;

std::vector<std::string> format_names() {
  std::vector<std::string> names;
  for (const Target& t : targets()) names.push_back(t.format);
  return names;
}

const Target& target_named(const std::string& format) {
  const auto& all = targets();
  const auto it =
      std::find_if(all.begin(), all.end(), [&](const Target& t) { return t.format == format; });
  EXPECT_NE(it, all.end());
  return *it;
}

TEST(FuzzRegressions, EveryRegressionFolderBelongsToAFuzzTarget) {
  const std::vector<std::string> names = format_names();
  const std::set<std::string> known(names.begin(), names.end());
  ASSERT_TRUE(std::filesystem::is_directory(kRegressions)) << kRegressions;
  int folders = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kRegressions)) {
    ++folders;
    EXPECT_TRUE(entry.is_directory()) << entry.path();
    EXPECT_EQ(known.count(entry.path().filename().string()), 1u)
        << entry.path() << " is named after no fuzz target";
  }
  EXPECT_GT(folders, 0);
}

class FuzzRegression : public ::testing::TestWithParam<std::string> {};

TEST_P(FuzzRegression, EveryInputIsACleanInputErrorNamingTheFile) {
  const Target& target = target_named(GetParam());
  const std::filesystem::path folder = kRegressions / target.format;
  if (!std::filesystem::is_directory(folder)) GTEST_SKIP() << "no regression inputs yet";
  int inputs = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    ++inputs;
    const std::filesystem::path& path = entry.path();
    const std::string bytes = support::read_bytes(path);
    const Status status = target.read(bytes, path);
    ASSERT_FALSE(status) << path << " was read without an error";
    EXPECT_EQ(outcome_problem(status, path.string()), "") << path;
  }
  EXPECT_GT(inputs, 0) << folder << " is empty";
}

INSTANTIATE_TEST_SUITE_P(Formats, FuzzRegression, ::testing::ValuesIn(format_names()),
                         [](const auto& param_info) { return param_info.param; });

}  // namespace
}  // namespace tessera::fuzz
