// Session files (io/session_file.hpp; the layout: docs/session-format.md).
#include "tessera/io/session_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <optional>

#include "internal/byte_cursor.hpp"
#include "internal/byte_writer.hpp"
#include "internal/crc32.hpp"
#include "internal/file_util.hpp"
#include "tessera/io/atomic_file.hpp"

namespace tessera {
namespace {

using io_internal::ByteCursor;
using io_internal::Bytes;

constexpr std::string_view kSignature("\x89TSM\r\n\x1a\n", 8);
constexpr std::string_view kCrcTag = "CRC ";
// A record: a 4-character tag, its payload's length (u64) and the payload.
constexpr std::size_t kRecordHead = 4 + 8;

// ---- writing ------------------------------------------------------------------------------------

using io_internal::put;
using io_internal::put_string;
void put_pose(std::string& out, const Pose2& p) {
  put(out, p.x);
  put(out, p.y);
  put(out, p.theta);
}
void put_record(std::string& out, std::string_view tag, const std::string& payload) {
  out.append(tag);
  put(out, static_cast<std::uint64_t>(payload.size()));
  out.append(payload);
}

std::string scans_payload(const std::vector<StampedScan>& scans) {
  std::string out;
  put(out, static_cast<std::uint64_t>(scans.size()));
  for (const StampedScan& s : scans) {
    put(out, s.t_s);
    put_pose(out, s.odometry);
    put_pose(out, s.laser_in_robot);
    put(out, s.scan.angle_min_rad);
    put(out, s.scan.angle_increment_rad);
    put(out, s.scan.min_range_m);
    put(out, s.scan.max_range_m);
    put(out, static_cast<std::uint32_t>(s.scan.ranges_m.size()));
    for (const double r : s.scan.ranges_m) put(out, r);
  }
  return out;
}

/// Whether any scan was swept beam by beam (its beams' times and its robot's velocity): then the
/// SWEP record keeps them (format 4).
bool any_swept(const std::vector<StampedScan>& scans) {
  return std::any_of(scans.begin(), scans.end(), [](const StampedScan& s) {
    return has_beam_times(s.scan) || !s.robot_velocity.is_zero();
  });
}

std::string sweeps_payload(const std::vector<StampedScan>& scans) {
  std::string out;
  put(out, static_cast<std::uint64_t>(scans.size()));
  for (const StampedScan& s : scans) {
    put(out, s.scan.first_beam_s);
    put(out, s.scan.time_increment_s);
    put(out, s.robot_velocity.vx_m_per_s);
    put(out, s.robot_velocity.vy_m_per_s);
    put(out, s.robot_velocity.omega_rad_per_s);
  }
  return out;
}

std::string graph_payload(const posegraph::PoseGraph& g, const std::vector<int>& vertex_scan) {
  std::string out;
  put(out, static_cast<std::uint64_t>(g.poses.size()));
  for (std::size_t i = 0; i < g.poses.size(); ++i) {
    put(out, static_cast<std::int32_t>(g.ids.empty() ? static_cast<int>(i) : g.ids[i]));
    put(out, static_cast<std::int32_t>(i < vertex_scan.size() ? vertex_scan[i] : -1));
    put_pose(out, g.poses[i]);
  }
  put(out, static_cast<std::uint64_t>(g.edges.size()));
  for (const posegraph::PoseGraphEdge& e : g.edges) {
    put(out, static_cast<std::int32_t>(e.from));
    put(out, static_cast<std::int32_t>(e.to));
    put_pose(out, e.measurement);
    for (int r = 0; r < 3; ++r) {
      for (int c = r; c < 3; ++c) put(out, e.information(r, c));
    }
    put(out, static_cast<std::uint8_t>(e.robust ? 1 : 0));
  }
  return out;
}

std::string map_payload(const OccupancyGrid& map) {
  std::string out;
  const GridGeometry& g = map.geometry();
  put(out, g.origin().x);
  put(out, g.origin().y);
  put(out, g.resolution_m());
  put(out, static_cast<std::int32_t>(g.width()));
  put(out, static_cast<std::int32_t>(g.height()));
  for (std::size_t i = 0; i < g.size(); ++i) {
    const Cell c = g.cell_of(i);
    put(out, static_cast<std::uint8_t>(map.known(c) ? 1 : 0));
    put(out, map.log_odds_at(c));
  }
  return out;
}

// ---- reading ------------------------------------------------------------------------------------

// A record's payload reader: every read is bounds-checked, and the first failure is kept with
// what was being read, so the caller reports one error.
class Fields {
 public:
  Fields(Bytes bytes, std::string_view tag) : cursor_(bytes), tag_(tag) {}

  template <typename T>
  [[nodiscard]] T get(const char* what) {
    T v{};
    Bytes b;
    if (!failed() && cursor_.take(sizeof(T), b)) {
      std::memcpy(&v, b.data(), sizeof(T));
      if constexpr (std::is_floating_point_v<T>) {
        if (!std::isfinite(v)) fail(std::string(what) + " is not a finite number");
      }
    } else {
      fail(std::string(what) + " runs past the end of the record");
    }
    return v;
  }
  Pose2 pose(const char* what) {
    const double x = get<double>(what), y = get<double>(what), theta = get<double>(what);
    return {x, y, theta};
  }
  std::string text(const char* what) {
    const auto n = get<std::uint32_t>(what);
    Bytes b;
    if (!failed() && !cursor_.take(n, b)) fail(std::string(what) + " runs past the end");
    return failed() ? std::string() : std::string(io_internal::as_text(b));
  }
  /// A count of items of at least `item_bytes` each that must fit in what is left.
  std::size_t count(const char* what, std::size_t item_bytes) {
    const auto n = get<std::uint64_t>(what);
    if (!failed() && n > cursor_.remaining() / std::max<std::size_t>(item_bytes, 1)) {
      fail(std::string(what) + " " + std::to_string(n) + " is more than the record holds");
    }
    return failed() ? 0 : static_cast<std::size_t>(n);
  }
  void fail(std::string why) {
    if (!error_) error_ = "record " + std::string(tag_) + ": " + std::move(why);
  }
  [[nodiscard]] bool failed() const { return error_.has_value(); }
  [[nodiscard]] const std::optional<std::string>& error() const { return error_; }
  [[nodiscard]] bool at_end() const { return cursor_.at_end(); }

 private:
  ByteCursor cursor_;
  std::string_view tag_;
  std::optional<std::string> error_;
};

void read_scans(Fields& f, std::vector<StampedScan>& scans) {
  constexpr std::size_t kScanHead = 11 * 8 + 4;
  scans.resize(f.count("scan count", kScanHead));
  for (std::size_t i = 0; i < scans.size() && !f.failed(); ++i) {
    StampedScan& s = scans[i];
    s.t_s = f.get<double>("scan stamp");
    s.odometry = f.pose("scan odometry");
    s.laser_in_robot = f.pose("laser pose");
    s.scan.angle_min_rad = f.get<double>("angle_min");
    s.scan.angle_increment_rad = f.get<double>("angle_increment");
    s.scan.min_range_m = f.get<double>("range_min");
    s.scan.max_range_m = f.get<double>("range_max");
    const auto n = f.get<std::uint32_t>("range count");
    if (f.failed()) break;
    s.scan.ranges_m.resize(n);
    // A range may be NaN (a reading the log marked invalid); the count is checked by the reads.
    for (double& r : s.scan.ranges_m) {
      if (f.failed()) break;
      const auto v = f.get<std::uint64_t>("range");
      std::memcpy(&r, &v, sizeof(r));
    }
  }
}

void read_sweeps(Fields& f, std::vector<StampedScan>& scans) {
  const std::size_t n = f.count("sweep count", 5 * 8);
  if (!f.failed() && n != scans.size()) {
    f.fail(std::to_string(n) + " sweeps for " + std::to_string(scans.size()) + " scans");
    return;
  }
  for (std::size_t i = 0; i < n && !f.failed(); ++i) {
    StampedScan& s = scans[i];
    s.scan.first_beam_s = f.get<double>("first beam time");
    s.scan.time_increment_s = f.get<double>("time increment");
    s.robot_velocity.vx_m_per_s = f.get<double>("robot velocity");
    s.robot_velocity.vy_m_per_s = f.get<double>("robot velocity");
    s.robot_velocity.omega_rad_per_s = f.get<double>("robot velocity");
  }
}

void read_graph(Fields& f, posegraph::PoseGraph& g, std::vector<int>& vertex_scan) {
  const std::size_t n = f.count("vertex count", 4 + 4 + 24);
  g.poses.resize(n);
  g.ids.resize(n);
  vertex_scan.resize(n);
  for (std::size_t i = 0; i < n && !f.failed(); ++i) {
    g.ids[i] = f.get<std::int32_t>("vertex id");
    vertex_scan[i] = f.get<std::int32_t>("vertex scan");
    g.poses[i] = f.pose("vertex pose");
  }
  const std::size_t m = f.count("edge count", 4 + 4 + 24 + 48 + 1);
  g.edges.resize(m);
  for (std::size_t k = 0; k < m && !f.failed(); ++k) {
    posegraph::PoseGraphEdge& e = g.edges[k];
    e.from = f.get<std::int32_t>("edge from");
    e.to = f.get<std::int32_t>("edge to");
    e.measurement = f.pose("edge measurement");
    for (int r = 0; r < 3; ++r) {
      for (int c = r; c < 3; ++c)
        e.information(r, c) = e.information(c, r) = f.get<double>("edge information");
    }
    e.robust = f.get<std::uint8_t>("edge robust flag") != 0;
    if (!f.failed() && (e.from < 0 || e.to < 0 || static_cast<std::size_t>(e.from) >= n ||
                        static_cast<std::size_t>(e.to) >= n)) {
      f.fail("edge " + std::to_string(k) + " names a vertex that is not there");
    }
  }
}

void read_map(Fields& f, OccupancyGrid& map) {
  const double x = f.get<double>("map origin"), y = f.get<double>("map origin");
  const double r = f.get<double>("map resolution");
  const auto w = f.get<std::int32_t>("map width"), h = f.get<std::int32_t>("map height");
  if (f.failed()) return;
  if (!(r > 0.0) || w < 0 || h < 0 ||
      static_cast<std::uint64_t>(w) * static_cast<std::uint64_t>(h) > io_internal::kMaxCells) {
    f.fail("a map of " + std::to_string(w) + " x " + std::to_string(h) + " cells of " +
           std::to_string(r) + " m");
    return;
  }
  map = OccupancyGrid(GridGeometry({x, y}, r, w, h));
  for (std::size_t i = 0; i < map.geometry().size() && !f.failed(); ++i) {
    const bool known = f.get<std::uint8_t>("map cell") != 0;
    const float l = f.get<float>("map cell");
    if (known && !f.failed()) {
      map.add_log_odds(map.geometry().cell_of(i), l, -std::numeric_limits<float>::max(),
                       std::numeric_limits<float>::max());
    }
  }
}

}  // namespace

std::string encode_session(const Session& s) {
  std::string out(kSignature);
  // Format 3 unless a scan was swept: a reader of format 3 would skip SWEP and misplace its beams.
  const bool swept = any_swept(s.scans);
  put(out, swept ? kSessionFormatVersion : std::uint32_t{3});
  std::string meta;
  put_string(meta, s.tessera_version);
  put_string(meta, s.command);
  put_record(out, "META", meta);
  std::string options;
  put_string(options, s.options_yaml);
  put_record(out, "OPTS", options);
  put_record(out, "SCAN", scans_payload(s.scans));
  if (swept) put_record(out, "SWEP", sweeps_payload(s.scans));
  std::string starts;
  put(starts, static_cast<std::uint64_t>(s.trajectory_starts.size()));
  for (const SessionTrajectoryStart& t : s.trajectory_starts) {
    put(starts, static_cast<std::uint64_t>(t.first_scan));
    put_pose(starts, t.T_map_robot);
  }
  put_record(out, "STRT", starts);
  std::string trajectory;
  put(trajectory, static_cast<std::uint64_t>(s.trajectory.size()));
  for (const StampedPose2& p : s.trajectory) {
    put(trajectory, p.t_s);
    put_pose(trajectory, p.pose);
  }
  put_record(out, "TRAJ", trajectory);
  put_record(out, "GRPH", graph_payload(s.graph, s.vertex_scan));
  put_record(out, "MAP ", map_payload(s.map));
  std::string crc;
  put(crc, io_internal::crc32(out));
  put_record(out, kCrcTag, crc);
  return out;
}

Result<Session> decode_session(std::string_view bytes, const std::string& name) {
  const auto error = [&](const std::string& why) -> Error {
    return input_error(name + ": " + why);
  };
  if (!bytes.starts_with(kSignature)) return error("not a tessera session (no .tsm signature)");
  ByteCursor c(io_internal::as_bytes(bytes));
  std::uint32_t version = 0;
  if (!c.skip(kSignature.size()) || !c.u32(version)) return error("truncated in its header");
  if (version > kSessionFormatVersion || version == 0) {
    return error("session format " + std::to_string(version) + " is not one this tessera reads (" +
                 std::to_string(kSessionFormatVersion) + " and older)");
  }
  // The records, up to the CRC record, which must be the last thing in the file.
  std::map<std::string, Bytes, std::less<>> records;
  bool crc_checked = false;
  while (!c.at_end()) {
    const std::size_t at = c.position();
    Bytes tag;
    std::uint64_t length = 0;
    Bytes payload;
    if (!c.take(4, tag) || !c.u64(length) || !c.take(length, payload)) {
      return error("truncated: a record at byte " + std::to_string(at) + " runs past the end (" +
                   std::to_string(bytes.size()) + " bytes)");
    }
    const std::string tag_text(io_internal::as_text(tag));
    if (tag_text == kCrcTag) {
      std::uint32_t stored = 0;
      if (length != 4 || !ByteCursor(payload).u32(stored) || !c.at_end()) {
        return error("the CRC record is malformed or not last");
      }
      const std::uint32_t computed = io_internal::crc32(bytes.substr(0, at));
      if (stored != computed) {
        return error("checksum mismatch, the file is damaged (CRC-32 stored " +
                     std::to_string(stored) + ", computed " + std::to_string(computed) + ")");
      }
      crc_checked = true;
      break;
    }
    records[tag_text] = payload;  // unknown tags are kept aside and ignored
  }
  if (!crc_checked) return error("truncated: no CRC record at the end");
  for (const char* tag : {"META", "OPTS", "SCAN", "TRAJ", "GRPH", "MAP "}) {
    if (!records.contains(tag)) return error(std::string("no ") + tag + " record");
  }

  Session s;
  s.format_version = version;
  std::optional<std::string> problem;
  const auto parse = [&](const char* tag, auto&& read) {
    if (problem) return;
    Fields f(records.at(tag), tag);
    read(f);
    if (!f.failed() && !f.at_end()) f.fail("has bytes left over");
    if (f.failed()) problem = *f.error();
  };
  parse("META", [&](Fields& f) {
    s.tessera_version = f.text("tessera version");
    s.command = f.text("command");
  });
  parse("OPTS", [&](Fields& f) { s.options_yaml = f.text("options"); });
  parse("SCAN", [&](Fields& f) { read_scans(f, s.scans); });
  if (records.contains("SWEP")) {
    parse("SWEP", [&](Fields& f) { read_sweeps(f, s.scans); });
  } else if (version >= 4) {
    return error("no SWEP record");
  }
  parse("TRAJ", [&](Fields& f) {
    s.trajectory.resize(f.count("pose count", 32));
    for (StampedPose2& p : s.trajectory) {
      p.t_s = f.get<double>("pose stamp");
      p.pose = f.pose("pose");
    }
  });
  // Version 1 had one trajectory per session and no STRT record.
  if (records.contains("STRT")) {
    parse("STRT", [&](Fields& f) {
      s.trajectory_starts.resize(f.count("trajectory count", 32));
      for (SessionTrajectoryStart& t : s.trajectory_starts) {
        const auto first = f.get<std::uint64_t>("first scan");
        t.first_scan =
            static_cast<int>(std::min<std::uint64_t>(first, std::numeric_limits<int>::max()));
        t.T_map_robot = f.pose("start pose");
      }
    });
  } else if (version >= 2) {
    return error("no STRT record");
  }
  parse("GRPH", [&](Fields& f) { read_graph(f, s.graph, s.vertex_scan); });
  parse("MAP ", [&](Fields& f) { read_map(f, s.map); });
  if (problem) return error(*problem);
  // Version 3 (a trimmed session) may also place its first scan.
  const int lowest_first = version >= 3 ? 0 : 1;
  for (std::size_t k = 0; k < s.trajectory_starts.size(); ++k) {
    const int first = s.trajectory_starts[k].first_scan;
    if (first < lowest_first || first >= static_cast<int>(s.scans.size()) ||
        (k > 0 && first <= s.trajectory_starts[k - 1].first_scan)) {
      return error("trajectory start " + std::to_string(k + 1) + " is at scan " +
                   std::to_string(first) + ", not at a scan " +
                   (lowest_first == 0 ? "of the session" : "after the first") + " in order");
    }
  }
  if (s.trajectory.size() != s.scans.size()) {
    return error(std::to_string(s.trajectory.size()) + " trajectory poses for " +
                 std::to_string(s.scans.size()) + " scans");
  }
  for (const int scan : s.vertex_scan) {
    if (scan < -1 || scan >= static_cast<int>(s.scans.size())) {
      return error("a graph vertex names scan " + std::to_string(scan) + " of " +
                   std::to_string(s.scans.size()));
    }
  }
  return s;
}

Status write_session(const std::filesystem::path& path, const Session& session) {
  return write_file_atomic(path, encode_session(session));
}

Result<Session> read_session(const std::filesystem::path& path) {
  Result<std::string> bytes = io_internal::read_file_bytes(path);
  if (!bytes.ok()) return bytes.error();
  return decode_session(*bytes, path.string());
}

bool is_session_path(const std::filesystem::path& path) {
  return io_internal::lower_extension(path) == ".tsm";
}

}  // namespace tessera
