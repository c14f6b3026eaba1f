#include "tessera/io/relations_file.hpp"

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "internal/decoders.hpp"
#include "internal/file_util.hpp"
#include "internal/text_fields.hpp"

namespace tessera {

Result<std::vector<Relation>> read_relations(const std::filesystem::path& path) {
  Result<std::string> bytes = io_internal::read_file_bytes(path);
  if (!bytes) return bytes.error();
  return io_internal::decode_relations(*bytes, path.string());
}

namespace io_internal {

Result<std::vector<Relation>> decode_relations(std::string_view text, const std::string& file) {
  constexpr std::array<std::string_view, 8> kNames = {"t1", "t2",   "x",     "y",
                                                      "z",  "roll", "pitch", "yaw"};

  std::vector<Relation> relations;
  const Status read = io_internal::for_each_record(
      text, [&](int line_no, const std::vector<std::string_view>& fields) -> Status {
        const std::string where = file + ":" + std::to_string(line_no) + ": ";
        if (fields.size() != kNames.size()) {
          return input_error(where + "expected 8 fields 't1 t2 x y z roll pitch yaw', got " +
                             std::to_string(fields.size()));
        }
        std::array<double, 8> v{};
        for (std::size_t i = 0; i < kNames.size(); ++i) {
          if (!io_internal::parse_double(fields[i], v[i])) {
            return input_error(where + std::string(kNames[i]) + " is '" + std::string(fields[i]) +
                               "', expected a finite number");
          }
        }
        relations.push_back({v[0], v[1], {v[2], v[3], io_internal::wrap_angle(v[7])}});
        return Ok{};
      });
  if (!read) return read.error();
  if (relations.empty()) {
    return input_error(file + ": no relations (lines 't1 t2 x y z roll pitch yaw')");
  }
  return relations;
}

}  // namespace io_internal

}  // namespace tessera
