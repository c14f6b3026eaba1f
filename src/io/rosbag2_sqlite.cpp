// rosbag2's sqlite3 storage (rosbag2_storage_default_plugins, sqlite_storage.cpp): tables
// topics(id, name, type, serialization_format, offered_qos_profiles) and messages(id, topic_id,
// timestamp, data), read in timestamp order as `ros2 bag play` does. The file is opened read-only
// and immutable (no journal, no locks), so bags on read-only media open too.
#include <sqlite3.h>

#include <algorithm>
#include <map>
#include <memory>
#include <string>
#include <string_view>

#include "internal/bag_builder.hpp"

namespace tessera::io_internal {
namespace {

struct CloseDb {
  void operator()(sqlite3* db) const { sqlite3_close(db); }
};
struct FinalizeStatement {
  void operator()(sqlite3_stmt* s) const { sqlite3_finalize(s); }
};
using Db = std::unique_ptr<sqlite3, CloseDb>;
using Statement = std::unique_ptr<sqlite3_stmt, FinalizeStatement>;

/// file: URI of a path (RFC 3986 percent-encoding of what SQLite's URI parser treats specially).
std::string file_uri(const std::filesystem::path& path) {
  std::string uri = "file:";
  for (const char c : std::filesystem::absolute(path).string()) {
    if (c == '%' || c == '?' || c == '#') {
      constexpr char kHex[] = "0123456789ABCDEF";
      const auto u = static_cast<unsigned char>(c);
      uri += '%';
      uri += kHex[u >> 4];
      uri += kHex[u & 0xF];
    } else {
      uri += c;
    }
  }
  return uri + "?mode=ro&immutable=1";
}

std::string text_column(sqlite3_stmt* s, int column) {
  const unsigned char* t = sqlite3_column_text(s, column);
  return t == nullptr ? std::string() : std::string(reinterpret_cast<const char*>(t));
}

/// Reads tables topics and messages of the open database `db` into `builder`. Both must be
/// tables: a crafted file could name a view there whose query never ends (a recursive one).
Status read_tables(sqlite3* db, const std::string& file, BagBuilder& builder) {
  auto prepare = [&](const char* sql, Statement& out) -> Status {
    sqlite3_stmt* s = nullptr;
    if (sqlite3_prepare_v2(db, sql, -1, &s, nullptr) != SQLITE_OK) {
      sqlite3_finalize(s);
      return input_error(file + ": not a rosbag2 sqlite3 file (" + sqlite3_errmsg(db) +
                         "; expected tables topics and messages)");
    }
    out.reset(s);
    return Ok{};
  };

  Statement kinds;
  if (Status s = prepare(
          "SELECT count(*) FROM sqlite_master WHERE type = 'table' AND "
          "name IN ('topics', 'messages')",
          kinds);
      !s) {
    return s;
  }
  if (sqlite3_step(kinds.get()) != SQLITE_ROW || sqlite3_column_int(kinds.get(), 0) != 2) {
    return input_error(file + ": not a rosbag2 sqlite3 file (expected tables topics and messages)");
  }

  Statement topics;
  if (Status s =
          prepare("SELECT id, name, type, serialization_format FROM topics ORDER BY id", topics);
      !s) {
    return s;
  }
  std::map<std::int64_t, std::size_t> topic_of_id;
  int rc = 0;
  while ((rc = sqlite3_step(topics.get())) == SQLITE_ROW) {
    const std::int64_t id = sqlite3_column_int64(topics.get(), 0);
    topic_of_id[id] = builder.topic(text_column(topics.get(), 1), text_column(topics.get(), 2),
                                    text_column(topics.get(), 3));
  }
  if (rc != SQLITE_DONE) {
    return input_error(file + ": reading table topics: " + sqlite3_errmsg(db));
  }

  Statement messages;
  if (Status s = prepare("SELECT topic_id, timestamp, data FROM messages ORDER BY timestamp, id",
                         messages);
      !s) {
    return s;
  }
  while ((rc = sqlite3_step(messages.get())) == SQLITE_ROW) {
    const std::int64_t topic_id = sqlite3_column_int64(messages.get(), 0);
    const auto it = topic_of_id.find(topic_id);
    if (it == topic_of_id.end()) {
      return input_error(file + ": a message names topic_id " + std::to_string(topic_id) +
                         ", which table topics does not have");
    }
    const std::int64_t t_ns = sqlite3_column_int64(messages.get(), 1);
    const void* blob = sqlite3_column_blob(messages.get(), 2);
    const int n = sqlite3_column_bytes(messages.get(), 2);
    builder.message(it->second, t_ns,
                    Bytes(static_cast<const std::uint8_t*>(blob), static_cast<std::size_t>(n)));
  }
  if (rc != SQLITE_DONE) {
    return input_error(file + ": reading table messages: " + sqlite3_errmsg(db));
  }
  return Ok{};
}

}  // namespace

Status read_rosbag2_sqlite_file(const std::filesystem::path& path, BagBuilder& builder) {
  const std::string file = path.string();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return input_error(file + ": no such file");
  sqlite3* raw_db = nullptr;
  const int opened = sqlite3_open_v2(file_uri(path).c_str(), &raw_db,
                                     SQLITE_OPEN_READONLY | SQLITE_OPEN_URI, nullptr);
  Db db(raw_db);
  if (opened != SQLITE_OK) {
    return input_error(file + ": cannot open as sqlite3: " +
                       (db ? sqlite3_errmsg(db.get()) : sqlite3_errstr(opened)));
  }
  return read_tables(db.get(), file, builder);
}

Status decode_rosbag2_sqlite(std::string_view bytes, const std::string& file,
                             BagBuilder& builder) {
  sqlite3* raw_db = nullptr;
  const int opened = sqlite3_open_v2(":memory:", &raw_db, SQLITE_OPEN_READWRITE, nullptr);
  Db db(raw_db);
  if (opened != SQLITE_OK) {
    return input_error(file + ": cannot open an in-memory sqlite3 database: " +
                       sqlite3_errstr(opened));
  }
  // sqlite owns (and frees) the copy; the database is read-only like the files.
  auto* copy = static_cast<unsigned char*>(sqlite3_malloc64(bytes.size() + 1));
  if (copy == nullptr) return input_error(file + ": out of memory copying the sqlite3 file");
  std::copy(bytes.begin(), bytes.end(), copy);
  if (sqlite3_deserialize(db.get(), "main", copy, static_cast<sqlite3_int64>(bytes.size()),
                          static_cast<sqlite3_int64>(bytes.size() + 1),
                          SQLITE_DESERIALIZE_FREEONCLOSE | SQLITE_DESERIALIZE_READONLY) !=
      SQLITE_OK) {
    return input_error(file + ": cannot open as sqlite3: " + sqlite3_errmsg(db.get()));
  }
  return read_tables(db.get(), file, builder);
}

}  // namespace tessera::io_internal
