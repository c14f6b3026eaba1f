// The bag fuzz targets (fuzz/ros1_bag_fuzz.cpp, mcap_fuzz.cpp, rosbag2_sqlite_fuzz.cpp) read the
// files they are seeded with: the fixtures (tests/fixtures/io/bags/, written by
// tests/support/bag_writer.hpp) and real bags, through the in-memory decoders, which must agree
// with the file readers. A target that rejected every valid file would fuzz nothing but its
// first error path.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "fuzz_target.hpp"
#include "support/data.hpp"
#include "support/temp_dir.hpp"

namespace tessera::fuzz {
namespace {

const std::filesystem::path kFixtures = TESSERA_BAG_FIXTURES_DIR;

const Target& target_named(const std::string& format) {
  const auto& all = targets();
  const auto it =
      std::find_if(all.begin(), all.end(), [&](const Target& t) { return t.format == format; });
  if (it == all.end()) throw std::runtime_error("no fuzz target " + format);
  return *it;
}

/// The target for a bag file, chosen by its extension.
const Target& target_for(const std::filesystem::path& path) {
  const std::string ext = path.extension().string();
  if (ext == ".bag") return target_named("ros1_bag");
  if (ext == ".mcap") return target_named("mcap");
  return target_named("rosbag2_sqlite");
}

TEST(BagFuzzTargets, ReadEveryFixtureTheyAreSeededWith) {
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kFixtures)) {
    const std::filesystem::path& path = entry.path();
    if (path.extension() == ".md") continue;
    ++files;
    const Status status = target_for(path).read(support::read_bytes(path), path);
    EXPECT_TRUE(status) << path << ": " << status.error().message;
  }
  EXPECT_EQ(files, 7);
}

TEST(BagFuzzTargets, ReadRealRos1AndRosbag2Bags) {
  for (const char* relative : {"bags/ros1_neato_drive_square_demo.bag",
                               "bags/ros2_neato_obstacle_avoider/obstacle-avoider_0.db3"}) {
    const auto path = support::data_path(relative);
    TESSERA_REQUIRE_DATA(path);
    const Status status = target_for(path).read(support::read_bytes(path), path);
    EXPECT_TRUE(status) << path << ": " << status.error().message;
  }
}

TEST(BagFuzzTargets, TruncatedBagsAreInputErrorsNamingTheFile) {
  for (const auto& entry : std::filesystem::directory_iterator(kFixtures)) {
    const std::filesystem::path& path = entry.path();
    if (path.extension() == ".md") continue;
    const std::string bytes = support::read_bytes(path);
    const std::string cut = bytes.substr(0, bytes.size() * 2 / 3);
    const Status status = target_for(path).read(cut, path);
    ASSERT_FALSE(status) << path << " cut to " << cut.size() << " bytes was read";
    EXPECT_EQ(outcome_problem(status, path.string()), "") << path;
  }
}

}  // namespace
}  // namespace tessera::fuzz
