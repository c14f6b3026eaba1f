#include "tessera/io/session_file.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>

#include "support/temp_dir.hpp"

namespace tessera {
namespace {

using ::testing::HasSubstr;

Session small_session() {
  Session s;
  s.tessera_version = "9.9.9";
  s.command = "slam";
  s.options_yaml = "loop_closure: true\nmap_resolution_m: 0.05\n";
  for (int i = 0; i < 3; ++i) {
    StampedScan scan;
    scan.t_s = 100.0 + 0.2 * i;
    scan.odometry = {0.1 * i, -0.05 * i, 0.01 * i};
    scan.laser_in_robot = {0.12, 0.0, 0.0};
    scan.scan.angle_min_rad = -1.5;
    scan.scan.angle_increment_rad = 0.01;
    scan.scan.min_range_m = 0.02;
    scan.scan.max_range_m = 30.0;
    scan.scan.ranges_m = {1.0 + i, 2.5, std::numeric_limits<double>::quiet_NaN(), 30.0};
    s.scans.push_back(scan);
    s.trajectory.push_back({scan.t_s, {0.1 * i + 1e-3, -0.05 * i, 0.01 * i}});
  }
  s.graph.poses = {{0, 0, 0}, {0, 0, 0}, {0.2, -0.1, 0.02}};
  s.graph.ids = {0, 1, 2};
  posegraph::PoseGraphEdge e;
  e.from = 1;
  e.to = 2;
  e.measurement = {0.2, -0.1, 0.02};
  e.information << 2500, 1, 0, 1, 2500, 0, 0, 0, 10000;
  e.robust = true;
  s.graph.edges = {e};
  s.vertex_scan = {-1, 0, 2};
  s.map = OccupancyGrid(GridGeometry({-1.0, -2.0}, 0.05, 4, 3));
  s.map.set_probability({1, 1}, 0.9);
  s.map.set_probability({2, 0}, 0.2);
  return s;
}

TEST(SessionFile, EverythingComesBackExactly) {
  const Session s = small_session();
  const Result<Session> back = decode_session(encode_session(s), "s.tsm");
  ASSERT_TRUE(back.ok()) << back.error().message;
  EXPECT_EQ(back->tessera_version, "9.9.9");
  EXPECT_EQ(back->command, "slam");
  EXPECT_EQ(back->options_yaml, s.options_yaml);
  ASSERT_EQ(back->scans.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    const StampedScan& a = s.scans[i];
    const StampedScan& b = back->scans[i];
    EXPECT_EQ(b.t_s, a.t_s);
    EXPECT_EQ(b.odometry.x, a.odometry.x);
    EXPECT_EQ(b.odometry.theta, a.odometry.theta);
    EXPECT_EQ(b.laser_in_robot.x, a.laser_in_robot.x);
    EXPECT_EQ(b.scan.angle_increment_rad, a.scan.angle_increment_rad);
    EXPECT_EQ(b.scan.max_range_m, a.scan.max_range_m);
    ASSERT_EQ(b.scan.ranges_m.size(), 4u);
    EXPECT_EQ(b.scan.ranges_m[0], a.scan.ranges_m[0]);
    EXPECT_TRUE(std::isnan(b.scan.ranges_m[2]));  // a reading the log marked invalid stays so
    EXPECT_EQ(back->trajectory[i].pose.x, s.trajectory[i].pose.x);
  }
  ASSERT_EQ(back->graph.edges.size(), 1u);
  EXPECT_EQ(back->graph.edges[0].information, s.graph.edges[0].information);
  EXPECT_TRUE(back->graph.edges[0].robust);
  EXPECT_EQ(back->vertex_scan, s.vertex_scan);
  EXPECT_EQ(back->graph.poses[2].y, -0.1);
  EXPECT_EQ(back->map.geometry(), s.map.geometry());
  EXPECT_EQ(back->map.log_odds_at({1, 1}), s.map.log_odds_at({1, 1}));
  EXPECT_FALSE(back->map.known({0, 0}));
  EXPECT_EQ(back->map.known_count(), 2u);
}

std::string error_of(std::string_view bytes) {
  const Result<Session> r = decode_session(bytes, "damaged.tsm");
  EXPECT_FALSE(r.ok());
  if (r.ok()) return "";
  EXPECT_EQ(r.error().kind, ErrorKind::kInput);
  EXPECT_EQ(r.error().message.find('\n'), std::string::npos);
  return r.error().message;
}

TEST(SessionFile, DamagedTruncatedNewerAndForeignFilesAreInputErrorsNamingTheFile) {
  const std::string good = encode_session(small_session());
  // Cut anywhere: never a crash, always "truncated" (or no signature when the cut is that early).
  for (std::size_t n = 0; n < good.size(); n += 7) {
    const std::string e = error_of(good.substr(0, n));
    EXPECT_THAT(e, HasSubstr("damaged.tsm: ")) << n;
    if (n >= 8) {
      EXPECT_THAT(e, HasSubstr("truncated")) << n;
    }
  }
  std::string flipped = good;
  flipped[200] = static_cast<char>(flipped[200] ^ 0x10);
  EXPECT_THAT(error_of(flipped), HasSubstr("checksum mismatch, the file is damaged"));
  std::string newer = good;
  newer[8] = 5;  // format version, little-endian u32 after the signature
  EXPECT_THAT(error_of(newer), HasSubstr("session format 5 is not one this tessera reads"));
  EXPECT_THAT(error_of("FLASER 180 1.0 2.0\n"), HasSubstr("not a tessera session"));
}

TEST(SessionFile, ContentsThatDoNotAgreeAreInputErrors) {
  Session s = small_session();
  s.trajectory.pop_back();
  EXPECT_THAT(error_of(encode_session(s)), HasSubstr("2 trajectory poses for 3 scans"));
  s = small_session();
  s.graph.edges[0].to = 7;
  EXPECT_THAT(error_of(encode_session(s)), HasSubstr("edge 0 names a vertex that is not there"));
  s = small_session();
  s.trajectory[1].pose.x = std::numeric_limits<double>::infinity();
  EXPECT_THAT(error_of(encode_session(s)), HasSubstr("record TRAJ: pose is not a finite number"));
  // Trajectories start at scans of the session, in order.
  for (const std::vector<int>& firsts : {std::vector<int>{-1}, {3}, {2, 1}, {1, 1}, {0, 0}}) {
    s = small_session();
    for (const int first : firsts) s.trajectory_starts.push_back({first, {}});
    EXPECT_THAT(error_of(encode_session(s)), HasSubstr("not at a scan of the session in order"));
  }
}

TEST(SessionFile, TrajectoryStartsComeBack) {
  Session s = small_session();
  s.trajectory_starts = {{1, {2.5, -1.0, 0.3}}, {2, {0.0, 4.0, -3.0}}};
  const Result<Session> back = decode_session(encode_session(s), "s.tsm");
  ASSERT_TRUE(back.ok()) << back.error().message;
  ASSERT_EQ(back->trajectory_starts.size(), 2u);
  EXPECT_EQ(back->trajectory_starts[0].first_scan, 1);
  EXPECT_EQ(back->trajectory_starts[0].T_map_robot.theta, 0.3);
  EXPECT_EQ(back->trajectory_starts[1].first_scan, 2);
  EXPECT_EQ(back->trajectory_starts[1].T_map_robot.y, 4.0);
}

// CRC-32 (IEEE 802.3), bit by bit: the format's checksum, computed here independently.
std::uint32_t crc32_of(std::string_view bytes) {
  std::uint32_t crc = 0xFFFFFFFFu;
  for (const char ch : bytes) {
    crc ^= static_cast<unsigned char>(ch);
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

/// The bytes with the CRC record dropped, the version byte set, and signed again.
std::string resigned(std::string bytes, char version) {
  bytes.resize(bytes.size() - 16);  // the CRC record: tag, length, 4 bytes
  bytes[8] = version;
  const std::uint32_t crc = crc32_of(bytes);
  const std::uint64_t four = 4;
  bytes += "CRC ";
  bytes.append(reinterpret_cast<const char*>(&four), 8);
  bytes.append(reinterpret_cast<const char*>(&crc), 4);
  return bytes;
}

TEST(SessionFile, AVersionOneFileReadsAsOneTrajectory) {
  // Version 1 had no STRT record: drop it, set the version and sign the file again.
  std::string bytes = encode_session(small_session());
  const std::size_t strt = bytes.find("STRT");
  ASSERT_NE(strt, std::string::npos);
  std::uint64_t length = 0;
  std::memcpy(&length, bytes.data() + strt + 4, 8);
  bytes.erase(strt, 12 + length);
  const auto signed_as = [&](char version) { return resigned(bytes, version); };
  const Result<Session> back = decode_session(signed_as(1), "old.tsm");
  ASSERT_TRUE(back.ok()) << back.error().message;
  EXPECT_TRUE(back->trajectory_starts.empty());
  EXPECT_EQ(back->scans.size(), 3u);
  EXPECT_EQ(back->format_version, 1u);
  // Version 2 requires the record.
  EXPECT_THAT(error_of(signed_as(2)), HasSubstr("no STRT record"));
}

// Format 3 added a start at scan 0 (a trimmed session places its first kept scan); a file that
// says it is format 2 may not have one.
TEST(SessionFile, AStartAtTheFirstScanNeedsFormatThree) {
  Session s = small_session();
  s.trajectory_starts = {{0, {1.0, 2.0, 0.5}}, {2, {0.0, 4.0, -3.0}}};
  const std::string bytes = encode_session(s);
  const Result<Session> back = decode_session(bytes, "trimmed.tsm");
  ASSERT_TRUE(back.ok()) << back.error().message;
  EXPECT_EQ(back->format_version, 3u);
  EXPECT_EQ(back->trajectory_starts[0].first_scan, 0);
  EXPECT_EQ(back->trajectory_starts[0].T_map_robot.y, 2.0);
  EXPECT_THAT(error_of(resigned(bytes, 2)),
              HasSubstr("trajectory start 1 is at scan 0, not at a scan after "
                        "the first in order"));
}

// Format 4 keeps the beams' times of swept scans and the robot's velocity over each (SWEP); a
// session of scans taken at once is still written as format 3, which a tessera of format 3 reads.
TEST(SessionFile, SweptScansKeepTheirBeamTimesAndVelocityInFormatFour) {
  EXPECT_EQ(decode_session(encode_session(small_session()), "at_once.tsm")->format_version, 3u);
  Session s = small_session();
  s.scans[1].scan.time_increment_s = 0.2 / 360.0;
  s.scans[2].scan.first_beam_s = 0.1;
  s.scans[2].scan.time_increment_s = -0.001;
  s.scans[1].robot_velocity = {0.3, -0.01, 1.25};
  const std::string bytes = encode_session(s);
  const Result<Session> back = decode_session(bytes, "swept.tsm");
  ASSERT_TRUE(back.ok()) << back.error().message;
  EXPECT_EQ(back->format_version, 4u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(back->scans[i].scan.first_beam_s, s.scans[i].scan.first_beam_s);
    EXPECT_EQ(back->scans[i].scan.time_increment_s, s.scans[i].scan.time_increment_s);
    EXPECT_EQ(back->scans[i].robot_velocity.vx_m_per_s, s.scans[i].robot_velocity.vx_m_per_s);
    EXPECT_EQ(back->scans[i].robot_velocity.vy_m_per_s, s.scans[i].robot_velocity.vy_m_per_s);
    EXPECT_EQ(back->scans[i].robot_velocity.omega_rad_per_s,
              s.scans[i].robot_velocity.omega_rad_per_s);
  }
  // A format 4 file without its SWEP record is refused, naming the file.
  EXPECT_THAT(error_of(resigned(encode_session(small_session()), 4)), HasSubstr("no SWEP record"));
  // So is a SWEP record that does not hold one sweep per scan.
  std::string short_sweeps = encode_session(s);
  const std::size_t swep = short_sweeps.find("SWEP");
  ASSERT_NE(swep, std::string::npos);
  short_sweeps[swep + 12] = 2;  // the sweep count
  EXPECT_THAT(error_of(resigned(short_sweeps, 4)), HasSubstr("2 sweeps for 3 scans"));
}

TEST(SessionFile, WrittenAtomicallyAndReadBack) {
  const support::TempDir dir;
  const auto path = dir.path() / "run.tsm";
  ASSERT_TRUE(write_session(path, small_session()).ok());
  const Result<Session> back = read_session(path);
  ASSERT_TRUE(back.ok()) << back.error().message;
  EXPECT_EQ(back->scans.size(), 3u);
  EXPECT_TRUE(is_session_path(path));
  EXPECT_TRUE(is_session_path("A.TSM"));
  EXPECT_FALSE(is_session_path("a.clf"));
  const Result<Session> missing = read_session(dir.path() / "none.tsm");
  ASSERT_FALSE(missing.ok());
  EXPECT_THAT(missing.error().message, HasSubstr("none.tsm"));
}

}  // namespace
}  // namespace tessera
