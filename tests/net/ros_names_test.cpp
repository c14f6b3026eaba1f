#include "tessera/net/ros_names.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace tessera::net {
namespace {

using ::testing::HasSubstr;

TEST(RosNames, TopicsMapToDdsWithTheRtPrefix) {
  EXPECT_EQ(dds_topic_name("/r1/scan"), "rt/r1/scan");
  EXPECT_EQ(dds_topic_name("/tf"), "rt/tf");
  EXPECT_EQ(dds_topic_name("/team/map"), "rt/team/map");
}

TEST(RosNames, TypesMapToTheDdsModuleAndTrailingUnderscore) {
  EXPECT_EQ(*dds_type_name("sensor_msgs/msg/LaserScan"), "sensor_msgs::msg::dds_::LaserScan_");
  EXPECT_EQ(*dds_type_name("tf2_msgs/msg/TFMessage"), "tf2_msgs::msg::dds_::TFMessage_");
  EXPECT_EQ(*dds_type_name("tessera_msgs/msg/FrontierClaim"),
            "tessera_msgs::msg::dds_::FrontierClaim_");
  for (const char* bad :
       {"sensor_msgs/LaserScan", "/msg/LaserScan", "sensor_msgs/msg/", "a/msg/b/c", "LaserScan"}) {
    const auto r = dds_type_name(bad);
    ASSERT_FALSE(r.ok()) << bad;
    EXPECT_THAT(r.error().message, HasSubstr("<package>/msg/<Type>"));
  }
}

TEST(RosNames, ValidTopicNamesPass) {
  for (const char* good : {"/scan", "/r1/scan", "/team/map", "/r_2/cmd_vel", "/_private/x1"}) {
    EXPECT_TRUE(check_topic_name(good).ok()) << good;
  }
}

TEST(RosNames, InvalidTopicNamesSayWhichRuleTheyBreak) {
  const std::pair<const char*, const char*> cases[] = {
      {"scan", "must start with '/'"},
      {"", "must start with '/'"},
      {"/", "names no topic"},
      {"/r1/", "must not end with '/'"},
      {"/r1//scan", "empty token"},
      {"/r1/scan-2", "'-'"},
      {"/1robot/scan", "starting with a digit"},
      {"/r1/sc an", "' '"},
  };
  for (const auto& [name, why] : cases) {
    const Status s = check_topic_name(name);
    ASSERT_FALSE(s.ok()) << name;
    EXPECT_THAT(s.error().message, HasSubstr(why)) << name;
  }
}

TEST(RosNames, RelativeNamesResolveInTheNamespace) {
  EXPECT_EQ(*resolve_topic_name("scan", "/r1"), "/r1/scan");
  EXPECT_EQ(*resolve_topic_name("scan", "/r1/"), "/r1/scan");
  EXPECT_EQ(*resolve_topic_name("scan", "/"), "/scan");
  EXPECT_EQ(*resolve_topic_name("scan", ""), "/scan");
  EXPECT_EQ(*resolve_topic_name("/tf", "/r1"), "/tf");
  EXPECT_FALSE(resolve_topic_name("bad name", "/r1").ok());
}

}  // namespace
}  // namespace tessera::net
