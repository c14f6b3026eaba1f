// read_ros_bag on bags the test writes (ROS 1 with none / bz2 / lz4 chunks, MCAP with none / zstd
// / lz4 chunks, rosbag2 folders, plain and zstd-compressed), on malformed ones, and on the real
// bags of
// ../shared/data/bags (topics and counts as SOURCES.md lists them).
#include "tessera/io/ros_bag.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sqlite3.h>
#include <zstd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <memory>

#include "support/data.hpp"
#include "support/synthetic_bag.hpp"
#include "support/temp_dir.hpp"

namespace tessera {
namespace {

using support::TempDir;
using ::testing::HasSubstr;

std::map<std::string, std::uint64_t> counts(const RosBag& bag) {
  std::map<std::string, std::uint64_t> out;
  for (const BagTopic& t : bag.topics) out[t.name] = t.message_count;
  return out;
}

BagReadOptions keep_all() {
  BagReadOptions o;
  o.keep = [](const BagTopic&) { return true; };
  return o;
}

/// The bag read back holds every written message, bytes and times unchanged, in order.
void expect_same_messages(const RosBag& bag, const support::SyntheticRun& run) {
  ASSERT_EQ(bag.messages.size(), run.messages.size());
  for (std::size_t i = 0; i < run.messages.size(); ++i) {
    const BagMessage& m = bag.messages[i];
    EXPECT_EQ(bag.topics[m.topic].name, run.topics[run.messages[i].topic].name) << i;
    EXPECT_EQ(m.log_time_ns, run.messages[i].t_ns) << i;
    const auto bytes = bag.bytes(m);
    ASSERT_TRUE(std::equal(bytes.begin(), bytes.end(), run.messages[i].data.begin(),
                           run.messages[i].data.end()))
        << "message " << i;
  }
}

class Ros1Compression : public ::testing::TestWithParam<const char*> {};

TEST_P(Ros1Compression, WrittenBagReadsBackWithEveryMessage) {
  TempDir dir;
  const auto run = support::synthetic_run(RosEncoding::kRos1, 40, 90);
  support::write_bytes(dir / "run.bag",
                       support::write_ros1_bag(run.topics, run.messages, GetParam(), 30));
  Result<RosBag> bag = read_ros_bag(dir / "run.bag", keep_all());
  ASSERT_TRUE(bag.ok()) << bag.error().message;
  EXPECT_EQ(bag->format, "ROS 1 bag 2.0");
  EXPECT_EQ(counts(*bag), (std::map<std::string, std::uint64_t>{
                              {"/scan", 40}, {"/odom", 80}, {"/tf", 80}, {"/tf_static", 1}}));
  EXPECT_EQ(bag->topics.front().serialization, "ros1");
  expect_same_messages(*bag, run);
}

INSTANTIATE_TEST_SUITE_P(RosBag, Ros1Compression, ::testing::Values("none", "bz2", "lz4"));

class McapCompression : public ::testing::TestWithParam<const char*> {};

TEST_P(McapCompression, WrittenFileReadsBackWithEveryMessage) {
  TempDir dir;
  const auto run = support::synthetic_run(RosEncoding::kCdr, 40, 90);
  support::write_bytes(dir / "run.mcap", support::write_mcap(run.topics, run.messages, GetParam()));
  Result<RosBag> bag = read_ros_bag(dir / "run.mcap", keep_all());
  ASSERT_TRUE(bag.ok()) << bag.error().message;
  EXPECT_EQ(bag->format, "MCAP");
  const BagTopic& tf_static = bag->topics.front();  // topics in the order the file names them
  EXPECT_EQ(tf_static.name, "/tf_static");
  EXPECT_EQ(tf_static.type, "tf2_msgs/msg/TFMessage");
  EXPECT_EQ(tf_static.serialization, "cdr");
  EXPECT_EQ(counts(*bag)["/odom"], 80u);
  expect_same_messages(*bag, run);
}

INSTANTIATE_TEST_SUITE_P(RosBag, McapCompression, ::testing::Values("", "zstd", "lz4"));

TEST(RosBag, Rosbag2FolderWithMcapStorageReadsItsFiles) {
  TempDir dir;
  const auto run = support::synthetic_run(RosEncoding::kCdr, 10, 30);
  support::write_bytes(dir / "run_0.mcap", support::write_mcap(run.topics, run.messages, "zstd"));
  support::write_bytes(dir / "metadata.yaml",
                       "rosbag2_bagfile_information:\n  version: 5\n  storage_identifier: mcap\n"
                       "  relative_file_paths:\n    - run_0.mcap\n  compression_format: \"\"\n");
  Result<RosBag> bag = read_ros_bag(dir.path());
  ASSERT_TRUE(bag.ok()) << bag.error().message;
  EXPECT_EQ(bag->format, "rosbag2 (mcap)");
  EXPECT_EQ(counts(*bag)["/scan"], 10u);
  EXPECT_TRUE(bag->messages.empty());  // nothing kept unless asked
}

// Zstandard as rosbag2's streaming compressor writes it: frames that do not state their size.
std::string zstd_stream(const std::string& in) {
  std::unique_ptr<ZSTD_CCtx, decltype(&ZSTD_freeCCtx)> ctx(ZSTD_createCCtx(), &ZSTD_freeCCtx);
  std::string out(ZSTD_compressBound(in.size()) + 64, '\0');
  ZSTD_inBuffer input{in.data(), in.size(), 0};
  ZSTD_outBuffer output{out.data(), out.size(), 0};
  while (ZSTD_compressStream2(ctx.get(), &output, &input, ZSTD_e_end) != 0) {
  }
  out.resize(output.pos);
  return out;
}

// A rosbag2 sqlite3 storage file of `run`, as rosbag2_storage_default_plugins writes its tables;
// each message's bytes through `encode` (rosbag2's message compression, or none).
std::string rosbag2_db3(const TempDir& dir, const support::SyntheticRun& run,
                        const std::function<std::string(const std::string&)>& encode) {
  const std::filesystem::path path = dir / "scratch.db3";
  sqlite3* db = nullptr;
  EXPECT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  sqlite3_exec(db,
               "CREATE TABLE topics(id INTEGER PRIMARY KEY, name TEXT NOT NULL, type TEXT NOT "
               "NULL, serialization_format TEXT NOT NULL, offered_qos_profiles TEXT NOT NULL);"
               "CREATE TABLE messages(id INTEGER PRIMARY KEY, topic_id INTEGER NOT NULL, "
               "timestamp INTEGER NOT NULL, data BLOB NOT NULL);",
               nullptr, nullptr, nullptr);
  sqlite3_stmt* topic = nullptr;
  sqlite3_prepare_v2(db, "INSERT INTO topics VALUES (?, ?, ?, 'cdr', '')", -1, &topic, nullptr);
  for (std::size_t i = 0; i < run.topics.size(); ++i) {
    sqlite3_bind_int64(topic, 1, static_cast<sqlite3_int64>(i + 1));
    sqlite3_bind_text(topic, 2, run.topics[i].name.c_str(), -1, SQLITE_TRANSIENT);
    sqlite3_bind_text(topic, 3, run.topics[i].type.c_str(), -1, SQLITE_TRANSIENT);
    EXPECT_EQ(sqlite3_step(topic), SQLITE_DONE);
    sqlite3_reset(topic);
  }
  sqlite3_finalize(topic);
  sqlite3_stmt* message = nullptr;
  sqlite3_prepare_v2(db, "INSERT INTO messages(topic_id, timestamp, data) VALUES (?, ?, ?)", -1,
                     &message, nullptr);
  for (const support::MessageToWrite& m : run.messages) {
    const std::string data = encode(std::string(m.data.begin(), m.data.end()));
    sqlite3_bind_int64(message, 1, static_cast<sqlite3_int64>(m.topic + 1));
    sqlite3_bind_int64(message, 2, m.t_ns);
    sqlite3_bind_blob(message, 3, data.data(), static_cast<int>(data.size()), SQLITE_TRANSIENT);
    EXPECT_EQ(sqlite3_step(message), SQLITE_DONE);
    sqlite3_reset(message);
  }
  sqlite3_finalize(message);
  sqlite3_close(db);
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::filesystem::remove(path);
  return bytes;
}

// The run in stamp order, as a rosbag2 sqlite3 file gives its messages back.
support::SyntheticRun in_stamp_order(support::SyntheticRun run) {
  std::stable_sort(run.messages.begin(), run.messages.end(),
                   [](const auto& a, const auto& b) { return a.t_ns < b.t_ns; });
  return run;
}

std::string rosbag2_metadata(const std::string& storage, const std::string& mode,
                             const std::string& file) {
  return "rosbag2_bagfile_information:\n  version: 5\n  storage_identifier: " + storage +
         "\n  relative_file_paths: [" + file +
         "]\n  compression_format: zstd\n"
         "  compression_mode: " +
         mode + "\n";
}

// `ros2 bag record --compression-mode file --compression-format zstd`: each storage file is
// compressed whole (run_0.db3.zstd, run_0.mcap.zstd), in frames that do not state their size.
TEST(RosBag, Rosbag2FilesCompressedWholeAreRead) {
  const auto run = in_stamp_order(support::synthetic_run(RosEncoding::kCdr, 20, 40));
  const auto none = [](const std::string& b) { return b; };
  for (const std::string storage : {"sqlite3", "mcap"}) {
    TempDir dir;
    const std::string file = storage == "mcap" ? "run_0.mcap.zstd" : "run_0.db3.zstd";
    const std::string plain = storage == "mcap" ? support::write_mcap(run.topics, run.messages, "")
                                                : rosbag2_db3(dir, run, none);
    support::write_bytes(dir / file, zstd_stream(plain));
    support::write_bytes(dir / "metadata.yaml", rosbag2_metadata(storage, "FILE", file));
    Result<RosBag> bag = read_ros_bag(dir.path(), keep_all());
    ASSERT_TRUE(bag.ok()) << bag.error().message;
    EXPECT_EQ(bag->format, "rosbag2 (" + storage + ", zstd)");
    expect_same_messages(*bag, run);

    // Cut short, it is one line naming the file, not a half-read bag.
    const std::string whole = zstd_stream(plain);
    support::write_bytes(dir / file, whole.substr(0, whole.size() / 2));
    Result<RosBag> cut = read_ros_bag(dir.path(), keep_all());
    ASSERT_FALSE(cut.ok());
    EXPECT_THAT(cut.error().message, HasSubstr(file + ": zstd: truncated frame"));
  }
}

// `ros2 bag record --compression-mode message --compression-format zstd`: the storage file is
// plain and each message's bytes are compressed.
TEST(RosBag, Rosbag2MessagesCompressedOneByOneAreRead) {
  const auto run = in_stamp_order(support::synthetic_run(RosEncoding::kCdr, 20, 40));
  for (const std::string storage : {"sqlite3", "mcap"}) {
    TempDir dir;
    support::SyntheticRun compressed = run;
    for (support::MessageToWrite& m : compressed.messages) {
      const std::string z = zstd_stream(std::string(m.data.begin(), m.data.end()));
      m.data.assign(z.begin(), z.end());
    }
    const std::string file = storage == "mcap" ? "run_0.mcap" : "run_0.db3";
    support::write_bytes(dir / file,
                         storage == "mcap"
                             ? support::write_mcap(compressed.topics, compressed.messages, "")
                             : rosbag2_db3(dir, run, zstd_stream));
    support::write_bytes(dir / "metadata.yaml", rosbag2_metadata(storage, "MESSAGE", file));
    Result<RosBag> bag = read_ros_bag(dir.path(), keep_all());
    ASSERT_TRUE(bag.ok()) << bag.error().message;
    expect_same_messages(*bag, run);

    // A message that is not zstd data is named.
    support::write_bytes(dir / file,
                         storage == "mcap"
                             ? support::write_mcap(run.topics, run.messages, "")
                             : rosbag2_db3(dir, run, [](const std::string& b) { return b; }));
    Result<RosBag> plain = read_ros_bag(dir.path(), keep_all());
    ASSERT_FALSE(plain.ok());
    EXPECT_THAT(plain.error().message, HasSubstr(file + ": message 1 of "));
    EXPECT_THAT(plain.error().message, HasSubstr("zstd: "));
  }
}

TEST(RosBag, UnindexedBagIsReadFrontToBack) {
  TempDir dir;
  const auto run = support::synthetic_run(RosEncoding::kRos1, 12, 20);
  std::string bytes = support::write_ros1_bag(run.topics, run.messages, "lz4", 5);
  const std::size_t at = bytes.find("index_pos=") + 10;
  bytes.replace(at, 8, std::string(8, '\0'));  // as a recording cut off before its index
  support::write_bytes(dir / "open.bag", bytes);
  Result<RosBag> bag = read_ros_bag(dir / "open.bag", keep_all());
  ASSERT_TRUE(bag.ok()) << bag.error().message;
  expect_same_messages(*bag, run);
}

TEST(RosBag, UnknownChunkCompressionIsNamed) {
  TempDir dir;
  const auto run = support::synthetic_run(RosEncoding::kRos1, 3, 10);
  support::write_bytes(dir / "zip.bag", support::write_ros1_bag(run.topics, run.messages, "zip"));
  Result<RosBag> bag = read_ros_bag(dir / "zip.bag");
  ASSERT_FALSE(bag.ok());
  EXPECT_EQ(bag.error().kind, ErrorKind::kInput);
  EXPECT_THAT(bag.error().message, HasSubstr("zip.bag: byte "));
  EXPECT_THAT(bag.error().message, HasSubstr("compression 'zip' is unknown"));
}

TEST(RosBag, ChunkClaimingGigabytesIsRefusedWithoutAllocatingThem) {
  TempDir dir;
  const auto run = support::synthetic_run(RosEncoding::kRos1, 3, 10);
  std::string bytes = support::write_ros1_bag(run.topics, run.messages, "lz4");
  const std::size_t at = bytes.find("size=") + 5;  // the chunk's uncompressed size, u32
  bytes.replace(at, 4, std::string("\xF0\xFF\xFF\xFF", 4));
  support::write_bytes(dir / "huge.bag", bytes);
  Result<RosBag> bag = read_ros_bag(dir / "huge.bag");
  ASSERT_FALSE(bag.ok());
  EXPECT_THAT(bag.error().message, HasSubstr("huge.bag: byte "));
  EXPECT_THAT(bag.error().message, HasSubstr("4294967280 bytes uncompressed, more than the"));
}

TEST(RosBag, ChunkThatDoesNotDecompressToItsSizeIsRefused) {
  TempDir dir;
  const auto run = support::synthetic_run(RosEncoding::kRos1, 3, 10);
  std::string bytes = support::write_ros1_bag(run.topics, run.messages, "bz2");
  const std::size_t at = bytes.find("BZh");  // the bzip2 stream header: corrupt its first block
  bytes[at + 20] = static_cast<char>(bytes[at + 20] ^ 0x5A);
  support::write_bytes(dir / "bad.bag", bytes);
  Result<RosBag> bag = read_ros_bag(dir / "bad.bag");
  ASSERT_FALSE(bag.ok());
  EXPECT_THAT(bag.error().message, HasSubstr("bad.bag"));
  EXPECT_THAT(bag.error().message, HasSubstr("bz2"));
}

/// Every prefix of a bag is either an error naming the file or (a whole-record prefix of an
/// unindexed bag) a readable bag; never a crash or a read past the buffer (ASan checks).
void expect_truncations_refused(const std::string& bytes, const std::string& name) {
  TempDir dir;
  const std::size_t step = std::max<std::size_t>(1, bytes.size() / 150);
  for (std::size_t n = 0; n < bytes.size(); n += step) {
    support::write_bytes(dir / name, std::string_view(bytes).substr(0, n));
    Result<RosBag> bag = read_ros_bag(dir / name);
    ASSERT_FALSE(bag.ok()) << n << " of " << bytes.size() << " bytes";
    EXPECT_THAT(bag.error().message, HasSubstr(name)) << n;
  }
}

TEST(RosBag, TruncatedRos1BagIsAnError) {
  const auto run = support::synthetic_run(RosEncoding::kRos1, 10, 20);
  expect_truncations_refused(support::write_ros1_bag(run.topics, run.messages, "lz4", 4), "t.bag");
}

TEST(RosBag, TruncatedMcapIsAnError) {
  const auto run = support::synthetic_run(RosEncoding::kCdr, 10, 20);
  expect_truncations_refused(support::write_mcap(run.topics, run.messages, "zstd", "cdr", 4),
                             "t.mcap");
}

TEST(RosBag, McapRecordLengthBeyondTheFileIsRefused) {
  TempDir dir;
  const auto run = support::synthetic_run(RosEncoding::kCdr, 2, 5);
  std::string bytes = support::write_mcap(run.topics, run.messages, "");
  bytes[8 + 1 + 7] = '\x7F';  // the header record's u64 length, top byte
  support::write_bytes(dir / "long.mcap", bytes);
  Result<RosBag> bag = read_ros_bag(dir / "long.mcap");
  ASSERT_FALSE(bag.ok());
  EXPECT_THAT(bag.error().message, HasSubstr("long.mcap: byte 8: record of"));
}

TEST(RosBag, SqliteFileWithoutRosbag2TablesIsNamed) {
  TempDir dir;
  const auto path = dir / "other.db3";
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  ASSERT_EQ(
      sqlite3_exec(db, "CREATE TABLE notes(id INTEGER, text TEXT)", nullptr, nullptr, nullptr),
      SQLITE_OK);
  sqlite3_close(db);
  Result<RosBag> bag = read_ros_bag(path);
  ASSERT_FALSE(bag.ok());
  EXPECT_EQ(bag.error().kind, ErrorKind::kInput);
  EXPECT_THAT(bag.error().message, HasSubstr("other.db3: not a rosbag2 sqlite3 file"));
}

// A crafted file can put a view where rosbag2 has a table; a recursive one would never end.
TEST(RosBag, SqliteFileWithAViewForATableIsRefusedBeforeQueryingIt) {
  TempDir dir;
  const auto path = dir / "endless.db3";
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  ASSERT_EQ(sqlite3_exec(db,
                         "CREATE TABLE topics(id INTEGER, name TEXT, type TEXT, "
                         "serialization_format TEXT);"
                         "CREATE VIEW messages AS WITH RECURSIVE n(i) AS (SELECT 1 UNION ALL "
                         "SELECT i + 1 FROM n) SELECT 1 AS topic_id, i AS timestamp, x'00' AS data, "
                         "i AS id FROM n",
                         nullptr, nullptr, nullptr),
            SQLITE_OK);
  sqlite3_close(db);
  Result<RosBag> bag = read_ros_bag(path);
  ASSERT_FALSE(bag.ok());
  EXPECT_EQ(bag.error().kind, ErrorKind::kInput);
  EXPECT_THAT(bag.error().message, HasSubstr("endless.db3: not a rosbag2 sqlite3 file"));
}

TEST(RosBag, Rosbag2FolderProblemsNameMetadataYaml) {
  TempDir dir;
  support::write_bytes(dir / "metadata.yaml",
                       "rosbag2_bagfile_information:\n  storage_identifier: [\n");
  EXPECT_THAT(read_ros_bag(dir.path()).error().message, HasSubstr("metadata.yaml:"));
  support::write_bytes(dir / "metadata.yaml",
                       "rosbag2_bagfile_information:\n  storage_identifier: sqlite3\n"
                       "  relative_file_paths: [gone_0.db3]\n");
  EXPECT_THAT(read_ros_bag(dir.path()).error().message,
              HasSubstr("metadata.yaml: storage file gone_0.db3 is missing"));
  support::write_bytes(dir / "metadata.yaml",
                       "rosbag2_bagfile_information:\n  storage_identifier: sqlite3\n"
                       "  compression_format: lz4\n  relative_file_paths: [a_0.db3.lz4]\n");
  EXPECT_THAT(
      read_ros_bag(dir.path()).error().message,
      HasSubstr("compression_format 'lz4' is not supported (rosbag2 compresses with zstd)"));
  support::write_bytes(dir / "metadata.yaml",
                       "rosbag2_bagfile_information:\n  storage_identifier: sqlite3\n"
                       "  compression_format: zstd\n  compression_mode: CHUNK\n"
                       "  relative_file_paths: [a_0.db3.zstd]\n");
  EXPECT_THAT(read_ros_bag(dir.path()).error().message,
              HasSubstr("compression_mode 'CHUNK', expected FILE or MESSAGE"));
}

TEST(RosBag, FileThatIsNoBagIsNamed) {
  TempDir dir;
  support::write_bytes(dir / "x.bag", "hello");
  Result<RosBag> bag = read_ros_bag(dir / "x.bag");
  ASSERT_FALSE(bag.ok());
  EXPECT_THAT(bag.error().message, HasSubstr("x.bag: not a ROS bag"));
  EXPECT_FALSE(read_ros_bag(dir / "missing.bag").ok());
  EXPECT_FALSE(read_ros_bag(dir.path()).ok());  // a folder without metadata.yaml
}

// ---- The real bags (../shared/data/bags/SOURCES.md) ----

TEST(RosBagRealData, Ros2FiniteStateControllerTopicsAndCounts) {
  const auto path = support::data_path("bags/ros2_neato_finite_state_controller");
  TESSERA_REQUIRE_DATA(path);
  Result<RosBag> bag = read_ros_bag(path);
  ASSERT_TRUE(bag.ok()) << bag.error().message;
  EXPECT_EQ(bag->format, "rosbag2 (sqlite3)");
  EXPECT_EQ(counts(*bag), (std::map<std::string, std::uint64_t>{{"/scan", 280},
                                                                {"/odom", 301},
                                                                {"/tf", 903},
                                                                {"/tf_static", 2},
                                                                {"/cmd_vel", 479},
                                                                {"/stable_scan", 280},
                                                                {"/projected_stable_scan", 280},
                                                                {"/bump", 301},
                                                                {"/accel", 301}}));
  EXPECT_NEAR(bag->duration_s(), 63.26, 0.01);
}

TEST(RosBagRealData, Ros2ObstacleAvoiderTopicsAndCounts) {
  const auto path = support::data_path("bags/ros2_neato_obstacle_avoider");
  TESSERA_REQUIRE_DATA(path);
  Result<RosBag> bag = read_ros_bag(path);
  ASSERT_TRUE(bag.ok()) << bag.error().message;
  const auto c = counts(*bag);
  EXPECT_EQ(c.at("/scan"), 153u);
  EXPECT_EQ(c.at("/odom"), 166u);
  EXPECT_EQ(c.at("/tf"), 498u);
  EXPECT_EQ(c.at("/tf_static"), 2u);
  EXPECT_EQ(bag->message_count(), 1545u);         // metadata.yaml's message_count
  EXPECT_NEAR(bag->duration_s(), 32.448, 0.001);  // metadata.yaml's duration
  // The .db3 file on its own reads the same.
  Result<RosBag> db3 = read_ros_bag(path / "obstacle-avoider_0.db3");
  ASSERT_TRUE(db3.ok()) << db3.error().message;
  EXPECT_EQ(counts(*db3), c);
}

TEST(RosBagRealData, Ros1NeatoBagTopicsAndCounts) {
  const auto path = support::data_path("bags/ros1_neato_drive_square_demo.bag");
  TESSERA_REQUIRE_DATA(path);
  Result<RosBag> bag = read_ros_bag(path);
  ASSERT_TRUE(bag.ok()) << bag.error().message;
  EXPECT_EQ(bag->format, "ROS 1 bag 2.0");
  const auto c = counts(*bag);
  EXPECT_EQ(c.at("/scan"), 404u);
  EXPECT_EQ(c.at("/odom"), 413u);
  EXPECT_EQ(c.at("/tf"), 2177u);
  EXPECT_EQ(c.at("/tf_static"), 1u);
  EXPECT_EQ(c.at("/stable_scan"), 405u);
  EXPECT_NEAR(bag->duration_s(), 88.0, 1.0);
}

TEST(RosBagRealData, ScanMatcherDemoWithItsWrongIndexLengthsReads) {
  const auto path = support::data_path("bags/laser_scan_matcher_demo.bag");
  TESSERA_REQUIRE_DATA(path);
  Result<RosBag> bag = read_ros_bag(path, keep_all());
  ASSERT_TRUE(bag.ok()) << bag.error().message;
  ASSERT_EQ(bag->topics.size(), 1u);
  EXPECT_EQ(bag->topics[0].name, "/scan");
  EXPECT_EQ(bag->topics[0].type, "sensor_msgs/LaserScan");
  EXPECT_EQ(bag->topics[0].message_count, 360u);
  EXPECT_NEAR(bag->topics[0].rate_hz(), 10.0, 0.1);
  Result<LaserScanMessage> first =
      decode_laser_scan(bag->bytes(bag->messages.front()), RosEncoding::kRos1);
  ASSERT_TRUE(first.ok()) << first.error().message;
  EXPECT_EQ(first->header.frame_id, "/laser");
  EXPECT_EQ(first->ranges_m.size(), 681u);
  EXPECT_NEAR(first->angle_min_rad, -2.08621, 1e-5);
  EXPECT_NEAR(first->angle_increment_rad, 0.00613592, 1e-8);
  EXPECT_NEAR(first->range_min_m, 0.02, 1e-6);
  EXPECT_NEAR(first->range_max_m, 5.6, 1e-6);
}

TEST(RosBagRealData, LegacyFormat12GivesAClearError) {
  const auto path = support::data_path("bags/laser_scan_sparsifier_demo_v1.2.bag");
  TESSERA_REQUIRE_DATA(path);
  Result<RosBag> bag = read_ros_bag(path);
  ASSERT_FALSE(bag.ok());
  EXPECT_EQ(bag.error().kind, ErrorKind::kInput);
  EXPECT_THAT(bag.error().message,
              HasSubstr("laser_scan_sparsifier_demo_v1.2.bag: legacy ROS bag format 1.2"));
}

}  // namespace
}  // namespace tessera
