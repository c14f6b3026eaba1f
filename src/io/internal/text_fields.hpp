#pragma once
// Private helpers for the line-oriented text readers (CARMEN logs, relations, g2o, TUM RGB-D lists
// and calibration files): walking a file line by line, splitting a line into whitespace-separated
// fields without copying, and the record loop all of them share (for_each_record).
#include <charconv>
#include <numbers>
#include <string_view>
#include <system_error>
#include <vector>

#include "tessera/core/angle.hpp"
#include "tessera/core/result.hpp"

namespace tessera::io_internal {

/// Yields the lines of `text` in order with their 1-based numbers; a final line without '\n'
/// counts too.
class LineCursor {
 public:
  explicit LineCursor(std::string_view text) : text_(text) {}

  /// The next line (without its '\n') and its number; false at the end of the text.
  bool next(std::string_view& line, int& line_no) {
    if (pos_ >= text_.size()) return false;
    const std::size_t end = text_.find('\n', pos_);
    const std::size_t stop = end == std::string_view::npos ? text_.size() : end;
    line = text_.substr(pos_, stop - pos_);
    pos_ = stop + 1;
    line_no = ++line_no_;
    return true;
  }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  int line_no_ = 0;
};

/// True for the field separators of these formats: space, tab and the '\r' of CRLF files.
[[nodiscard]] inline bool is_field_space(char c) { return c == ' ' || c == '\t' || c == '\r'; }

/// Splits `line` at runs of separators into `fields` (cleared first; the views point into line).
inline void split_fields(std::string_view line, std::vector<std::string_view>& fields) {
  fields.clear();
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_field_space(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !is_field_space(line[i])) ++i;
    if (i > start) fields.push_back(line.substr(start, i - start));
  }
}

/// True when the line is blank or a '#' comment.
[[nodiscard]] inline bool is_blank_or_comment(const std::vector<std::string_view>& fields) {
  return fields.empty() || fields.front().front() == '#';
}

/// The record loop of the line-oriented readers: calls on_record(line_no, fields) for each line of
/// `text` that is neither blank nor a '#' comment, in order, with its 1-based line number and its
/// fields (views into text, valid during the call). Stops at the first call that returns an error
/// and returns that error; the readers build their "file:line: ..." messages in on_record.
/// OnRecord: Status(int line_no, const std::vector<std::string_view>& fields).
template <typename OnRecord>
[[nodiscard]] Status for_each_record(std::string_view text, OnRecord&& on_record) {
  LineCursor cursor(text);
  std::string_view line;
  int line_no = 0;
  std::vector<std::string_view> fields;
  while (cursor.next(line, line_no)) {
    split_fields(line, fields);
    if (is_blank_or_comment(fields)) continue;
    Status status = on_record(line_no, static_cast<const std::vector<std::string_view>&>(fields));
    if (!status) return status;
  }
  return Ok{};
}

/// Parses a whole field as a decimal int (no trailing garbage).
[[nodiscard]] inline bool parse_int(std::string_view text, int& out) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  int v = 0;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
  if (r.ec != std::errc{} || r.ptr != text.data() + text.size() || text.empty()) return false;
  out = v;
  return true;
}

/// normalize_angle for angles read from a file, keeping those already in [-pi, pi) bit for bit
/// (normalize_angle's fmod round trip can change the last bit, which would break exact round
/// trips).
[[nodiscard]] inline double wrap_angle(double a_rad) {
  return -std::numbers::pi <= a_rad && a_rad < std::numbers::pi ? a_rad : normalize_angle(a_rad);
}

}  // namespace tessera::io_internal
