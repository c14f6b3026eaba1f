#include "tessera/io/json_file.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "io_test_util.hpp"

namespace tessera {
namespace {

using io_test::TempDir;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

TEST(WriteJsonAtomic, WritesPrettyJsonWithTwoSpacesAndATrailingNewline) {
  TempDir dir;
  const nlohmann::json report = {{"command", "explore"}, {"seed", 1}, {"coverage", 0.5}};
  ASSERT_TRUE(write_json_atomic(dir / "report.json", report));
  EXPECT_EQ(io_test::read_bytes(dir / "report.json"),
            "{\n  \"command\": \"explore\",\n  \"coverage\": 0.5,\n  \"seed\": 1\n}\n");
  EXPECT_THAT(io_test::files_in(dir.path()), ElementsAre("report.json"));
  EXPECT_EQ(nlohmann::json::parse(io_test::read_bytes(dir / "report.json")), report);
}

TEST(WriteJsonAtomic, InvalidUtf8IsReplacedNotThrown) {
  const nlohmann::json j = std::string("bad \xff byte");
  EXPECT_EQ(encode_json(j), "\"bad \xEF\xBF\xBD byte\"\n");
}

TEST(WriteJsonAtomic, UnwritableFolderIsARuntimeErrorAndLeavesNothing) {
  TempDir dir;
  const Status s = write_json_atomic(dir / "missing" / "report.json", nlohmann::json::object());
  ASSERT_FALSE(s);
  EXPECT_EQ(s.error().kind, ErrorKind::kRuntime);
  EXPECT_THAT(s.error().message, HasSubstr("report.json"));
  EXPECT_TRUE(io_test::files_in(dir.path()).empty());
}

}  // namespace
}  // namespace tessera
