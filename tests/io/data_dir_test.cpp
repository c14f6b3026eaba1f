#include "tessera/io/data_dir.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

namespace tessera {
namespace {

constexpr const char* kVar = "TESSERA_DATA_DIR";

/// Each test changes TESSERA_DATA_DIR; the value it had (or its absence) comes back afterwards.
class DataDirTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (const char* v = std::getenv(kVar); v != nullptr) saved_ = v;
  }
  void TearDown() override {
    if (saved_) {
      ::setenv(kVar, saved_->c_str(), 1);
    } else {
      ::unsetenv(kVar);
    }
  }

 private:
  std::optional<std::string> saved_;
};

// The default the build compiled in: ../shared/data beside this source tree (src/io/CMakeLists.txt).
const std::filesystem::path kDefault = TESSERA_TEST_DEFAULT_DATA_DIR;

TEST_F(DataDirTest, SetVariableWins) {
  ASSERT_EQ(::setenv(kVar, "/tmp/tessera data", 1), 0);
  EXPECT_EQ(data_dir(), std::filesystem::path("/tmp/tessera data"));
  ASSERT_EQ(::setenv(kVar, "relative/dir", 1), 0);
  EXPECT_EQ(data_dir(), std::filesystem::path("relative/dir"));
}

TEST_F(DataDirTest, UnsetVariableGivesTheCompiledDefault) {
  ASSERT_EQ(::unsetenv(kVar), 0);
  EXPECT_EQ(data_dir(), kDefault);
  EXPECT_EQ(data_dir().filename(), "data");
  EXPECT_EQ(data_dir().parent_path().filename(), "shared");
}

TEST_F(DataDirTest, EmptyVariableCountsAsUnset) {
  ASSERT_EQ(::setenv(kVar, "", 1), 0);
  EXPECT_EQ(data_dir(), kDefault);
}

TEST_F(DataDirTest, DoesNotCheckThatTheFolderExists) {
  ASSERT_EQ(::setenv(kVar, "/nonexistent/tessera/data", 1), 0);
  EXPECT_EQ(data_dir(), std::filesystem::path("/nonexistent/tessera/data"));
}

}  // namespace
}  // namespace tessera
