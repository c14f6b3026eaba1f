#include "tessera/io/relations_file.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <numbers>
#include <string>

#include "io_test_util.hpp"
#include "support/data.hpp"

namespace tessera {
namespace {

using io_test::TempDir;
using ::testing::HasSubstr;
using ::testing::StartsWith;

Result<std::vector<Relation>> read_relations_text(const TempDir& dir, const std::string& text) {
  io_test::write_bytes(dir / "r.relations", text);
  return read_relations(dir / "r.relations");
}

TEST(RelationsFile, KeepsXYAndYawOfEachLineInFileOrder) {
  TempDir dir;
  const Result<std::vector<Relation>> r =
      read_relations_text(dir,
                          "# t1 t2 x y z roll pitch yaw\n\n10.5 12.25 0.5 -0.25 0 0 0 1.5\r\n"
                          "3\t1   1 2 0.000000 0.000000 0.000000 4\n");
  ASSERT_TRUE(r.ok()) << r.error().message;
  ASSERT_EQ(r->size(), 2u);
  EXPECT_DOUBLE_EQ((*r)[0].t1_s, 10.5);
  EXPECT_DOUBLE_EQ((*r)[0].t2_s, 12.25);
  EXPECT_DOUBLE_EQ((*r)[0].motion.x, 0.5);
  EXPECT_DOUBLE_EQ((*r)[0].motion.y, -0.25);
  EXPECT_DOUBLE_EQ((*r)[0].motion.theta, 1.5);
  EXPECT_DOUBLE_EQ((*r)[1].t1_s, 3.0);
  EXPECT_NEAR((*r)[1].motion.theta, 4.0 - 2.0 * std::numbers::pi, 1e-12) << "wrapped";
}

void expect_bad_relations(const std::string& text, const std::string& where,
                          const std::string& phrase) {
  TempDir dir;
  const Result<std::vector<Relation>> r = read_relations_text(dir, text);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().kind, ErrorKind::kInput);
  EXPECT_THAT(r.error().message, StartsWith((dir / where).string()));
  EXPECT_THAT(r.error().message, HasSubstr(phrase));
}

TEST(RelationsFile, LineWithSevenFieldsNamesFileAndLine) {
  expect_bad_relations("1 2 0 0 0 0 0 0\n1 2 0 0 0 0 0\n",
                       "r.relations:2:", "expected 8 fields 't1 t2 x y z roll pitch yaw', got 7");
}

TEST(RelationsFile, LineWithNineFieldsIsRejected) {
  expect_bad_relations("1 2 0 0 0 0 0 0 9\n", "r.relations:1:", "got 9");
}

TEST(RelationsFile, NonNumericFieldIsNamed) {
  expect_bad_relations("1 2 0 0 0 0 0 0\n\n1 2 0.5 y 0 0 0 0\n",
                       "r.relations:3:", "y is 'y', expected a finite number");
}

TEST(RelationsFile, NanStampIsRejected) {
  expect_bad_relations("nan 2 0 0 0 0 0 0\n", "r.relations:1:", "t1 is 'nan'");
}

TEST(RelationsFile, FileWithoutRelationsIsRejected) {
  expect_bad_relations("# only a comment\n", "r.relations: ", "no relations");
}

TEST(RelationsFile, MissingFileIsAnInputError) {
  TempDir dir;
  const Result<std::vector<Relation>> r = read_relations(dir / "nope.relations");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().kind, ErrorKind::kInput);
  EXPECT_THAT(r.error().message, HasSubstr("no such file"));
}

TEST(RelationsFileData, IntelHas2984RelationsOnAbsoluteIpcStamps) {
  const auto path = support::data_path("laser/intel/intel.relations");
  TESSERA_REQUIRE_DATA(path);
  const Result<std::vector<Relation>> r = read_relations(path);
  ASSERT_TRUE(r.ok()) << r.error().message;
  ASSERT_EQ(r->size(), 2984u);
  EXPECT_DOUBLE_EQ(r->front().t1_s, 976052905.167303);
  EXPECT_DOUBLE_EQ(r->front().t2_s, 976052911.885496);
  EXPECT_DOUBLE_EQ(r->front().motion.x, -0.056990);
  EXPECT_DOUBLE_EQ(r->front().motion.y, -0.128430);
  EXPECT_DOUBLE_EQ(r->front().motion.theta, -1.682210);
}

TEST(RelationsFileData, Fr079Has1685Relations) {
  const auto path = support::data_path("laser/fr079/fr079.relations");
  TESSERA_REQUIRE_DATA(path);
  const Result<std::vector<Relation>> r = read_relations(path);
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->size(), 1685u);
}

}  // namespace
}  // namespace tessera
