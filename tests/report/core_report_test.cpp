#include "tessera/report/core_report.hpp"

#include <gtest/gtest.h>

namespace tessera {
namespace {

TEST(CoreReport, CarriesEveryCoreKeyWithTheProjectVersion) {
  const nlohmann::json j = core_report({"explore", 7, {{"robots", 2}}, 2.0, 10.0});
  EXPECT_EQ(j["tessera_version"], TESSERA_TEST_PROJECT_VERSION);
  EXPECT_EQ(j["command"], "explore");
  EXPECT_EQ(j["seed"], 7);
  EXPECT_EQ(j["options"]["robots"], 2);
  EXPECT_DOUBLE_EQ(j["timing"]["wall_s"].get<double>(), 2.0);
  EXPECT_DOUBLE_EQ(j["timing"]["data_duration_s"].get<double>(), 10.0);
  EXPECT_DOUBLE_EQ(j["timing"]["realtime_factor"].get<double>(), 5.0);
}

TEST(CoreReport, NoSeedAndNoDataClockAreNullNotMissing) {
  const nlohmann::json j = core_report({"posegraph optimize", std::nullopt, {}, 0.5, std::nullopt});
  ASSERT_TRUE(j.contains("seed"));
  EXPECT_TRUE(j["seed"].is_null());
  ASSERT_TRUE(j["timing"].contains("data_duration_s"));
  EXPECT_TRUE(j["timing"]["data_duration_s"].is_null());
  EXPECT_TRUE(j["timing"]["realtime_factor"].is_null());
}

TEST(RealtimeFactor, IsDataSecondsPerWallSecondAndEmptyWithoutATime) {
  EXPECT_DOUBLE_EQ(realtime_factor(300.0, 3.0).value(), 100.0);
  EXPECT_FALSE(realtime_factor(300.0, 0.0).has_value());  // too fast to time
  EXPECT_FALSE(realtime_factor(std::nullopt, 3.0).has_value());
}

}  // namespace
}  // namespace tessera
