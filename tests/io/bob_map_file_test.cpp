#include "tessera/io/bob_map_file.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "support/temp_dir.hpp"

namespace tessera {
namespace {

using ::testing::HasSubstr;

BobMapFile lab_map() {
  BobMapFile m;
  m.width = 11;
  m.height = 14;
  m.cell_mm = 220;
  m.rows.assign(28, 0);
  for (std::size_t i = 0; i < m.rows.size(); ++i) m.rows[i] = static_cast<std::uint8_t>(i * 37);
  for (std::size_t y = 0; y < 14; ++y) m.rows[2 * y + 1] &= 0x07;  // padding bits 0
  return m;
}

TEST(BobMapFile, HeaderIsDocumentedLayoutAndElevenByFourteenTakesThirtyEightBytes) {
  const Result<std::string> bytes = encode_bob_map(lab_map());
  ASSERT_TRUE(bytes.ok());
  ASSERT_EQ(bytes->size(), 38u);
  EXPECT_EQ(bytes->substr(0, 4), "BOB1");
  EXPECT_EQ(static_cast<unsigned char>((*bytes)[4]), 11);
  EXPECT_EQ(static_cast<unsigned char>((*bytes)[5]), 0);
  EXPECT_EQ(static_cast<unsigned char>((*bytes)[6]), 14);
  EXPECT_EQ(static_cast<unsigned char>((*bytes)[8]), 220);
  EXPECT_EQ(static_cast<unsigned char>((*bytes)[9]), 0);
}

TEST(BobMapFile, RoundTripsThroughAFile) {
  support::TempDir dir;
  const auto path = dir.path() / "map.bob";
  ASSERT_TRUE(write_bob_map(path, lab_map()).ok());
  const Result<BobMapFile> back = read_bob_map(path);
  ASSERT_TRUE(back.ok()) << back.error().message;
  EXPECT_EQ(*back, lab_map());
}

TEST(BobMapFile, RejectsBadMagicAndWrongLength) {
  const Result<BobMapFile> magic = decode_bob_map("BOB2\x0b\x00\x0e\x00\xdc\x00", "x.bob");
  ASSERT_FALSE(magic.ok());
  EXPECT_THAT(magic.error().message, HasSubstr("x.bob: not a BOB1 map"));
  std::string bytes = *encode_bob_map(lab_map());
  bytes.pop_back();
  const Result<BobMapFile> short_rows = decode_bob_map(bytes, "y.bob");
  ASSERT_FALSE(short_rows.ok());
  EXPECT_EQ(short_rows.error().kind, ErrorKind::kInput);
  EXPECT_THAT(short_rows.error().message, HasSubstr("y.bob: 27 bytes of rows, expected 28"));
  BobMapFile bad = lab_map();
  bad.rows.pop_back();
  EXPECT_FALSE(encode_bob_map(bad).ok());
}

TEST(BobMapFile, MissingFileIsAnInputError) {
  support::TempDir dir;
  const Result<BobMapFile> r = read_bob_map(dir.path() / "nope.bob");
  ASSERT_FALSE(r.ok());
  EXPECT_THAT(r.error().message, HasSubstr("nope.bob"));
}

}  // namespace
}  // namespace tessera
