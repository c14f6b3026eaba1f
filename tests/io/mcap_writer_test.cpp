// McapWriter: what it writes reads back with tessera's own MCAP reader (io/ros_bag.hpp) message for
// message, over many chunks and uncompressed; a writer that does not finish leaves nothing. The
// third-party check (@mcap/core, rosmsg2-serialization) is tests/record/mcap_recording_test.sh.
#include "tessera/io/mcap_writer.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <vector>

#include "support/temp_dir.hpp"
#include "tessera/io/ros_bag.hpp"
#include "tessera/io/ros_message_encoders.hpp"

namespace tessera {
namespace {

using support::TempDir;
using ::testing::HasSubstr;

struct Written {
  std::string topic;
  std::int64_t t_ns;
  std::vector<std::uint8_t> bytes;
};

// Writes `n` messages round-robin on three topics (two sharing a type), stamps going 1 ms apart
// with every tenth one 5 ms back (out of order, as several robots' messages come).
std::vector<Written> write_messages(McapWriter& writer, int n) {
  const std::string tf = ros2msg_definition(kRos2TfMessage);
  const MessageSink::ChannelId a = writer.channel("/tf", kRos2TfMessage, tf);
  const MessageSink::ChannelId b =
      writer.channel("/scan", kRos2LaserScan, ros2msg_definition(kRos2LaserScan));
  const MessageSink::ChannelId c = writer.channel("/robot1/tf", kRos2TfMessage, tf);
  EXPECT_EQ(writer.channel("/tf", kRos2TfMessage, tf), a);  // same topic and type: same channel
  std::vector<Written> out;
  for (int i = 0; i < n; ++i) {
    const std::int64_t t = 1'000'000'000LL + 1'000'000LL * i - (i % 10 == 9 ? 5'000'000 : 0);
    const MessageSink::ChannelId channel = i % 3 == 0 ? a : i % 3 == 1 ? b : c;
    std::vector<std::uint8_t> bytes(40 + i % 17, static_cast<std::uint8_t>(i));
    EXPECT_TRUE(writer.publish(channel, t, bytes));
    out.push_back({i % 3 == 0 ? "/tf" : i % 3 == 1 ? "/scan" : "/robot1/tf", t, bytes});
  }
  return out;
}

void expect_reads_back(const std::filesystem::path& path, const std::vector<Written>& written) {
  BagReadOptions keep_all;
  keep_all.keep = [](const BagTopic&) { return true; };
  Result<RosBag> bag = read_ros_bag(path, keep_all);
  ASSERT_TRUE(bag.ok()) << bag.error().message;
  EXPECT_EQ(bag->format, "MCAP");
  ASSERT_EQ(bag->messages.size(), written.size());
  for (std::size_t i = 0; i < written.size(); ++i) {
    const BagMessage& m = bag->messages[i];
    EXPECT_EQ(bag->topics[m.topic].name, written[i].topic) << i;
    EXPECT_EQ(bag->topics[m.topic].serialization, "cdr") << i;
    EXPECT_EQ(m.log_time_ns, written[i].t_ns) << i;
    const auto bytes = bag->bytes(m);
    EXPECT_TRUE(
        std::equal(bytes.begin(), bytes.end(), written[i].bytes.begin(), written[i].bytes.end()))
        << i;
  }
}

TEST(McapWriter, ManyChunksReadBackMessageForMessage) {
  TempDir dir;
  const auto path = dir / "run.mcap";
  McapWriterOptions options;
  options.chunk_bytes = 4096;
  Result<McapWriter> writer = McapWriter::open(path, options);
  ASSERT_TRUE(writer.ok()) << writer.error().message;
  const std::vector<Written> written = write_messages(*writer, 3000);
  EXPECT_FALSE(std::filesystem::exists(path)) << "the file must appear only when finished";
  ASSERT_TRUE(writer->finish());
  EXPECT_EQ(writer->message_count(), 3000U);
  EXPECT_GT(writer->chunk_count(), 20U);
  expect_reads_back(path, written);
}

TEST(McapWriter, UncompressedChunksReadBackToo) {
  TempDir dir;
  const auto path = dir / "plain.mcap";
  McapWriterOptions options;
  options.zstd_level = 0;
  Result<McapWriter> writer = McapWriter::open(path, options);
  ASSERT_TRUE(writer.ok());
  const std::vector<Written> written = write_messages(*writer, 100);
  ASSERT_TRUE(writer->finish());
  expect_reads_back(path, written);
}

TEST(McapWriter, AWriterThatNeverFinishesLeavesNoFileAndNoTemporary) {
  TempDir dir;
  const auto path = dir / "failed.mcap";
  {
    Result<McapWriter> writer = McapWriter::open(path);
    ASSERT_TRUE(writer.ok());
    write_messages(*writer, 500);
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

TEST(McapWriter, FinishingTwiceOrPublishingAfterwardsIsAnError) {
  TempDir dir;
  Result<McapWriter> writer = McapWriter::open(dir / "once.mcap");
  ASSERT_TRUE(writer.ok());
  write_messages(*writer, 10);
  ASSERT_TRUE(writer->finish());
  const Status again = writer->finish();
  ASSERT_FALSE(again);
  EXPECT_EQ(again.error().kind, ErrorKind::kRuntime);
  EXPECT_FALSE(writer->publish(0, 0, std::vector<std::uint8_t>(4, 0)));
}

TEST(McapWriter, UnwritableFolderIsARuntimeErrorNamingTheFile) {
  TempDir dir;
  Result<McapWriter> writer = McapWriter::open(dir / "no" / "such" / "x.mcap");
  ASSERT_FALSE(writer.ok());
  EXPECT_EQ(writer.error().kind, ErrorKind::kRuntime);
  EXPECT_THAT(writer.error().message, HasSubstr("x.mcap: cannot write"));
}

}  // namespace
}  // namespace tessera
