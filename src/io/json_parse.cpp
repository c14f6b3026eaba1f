#include "internal/json_parse.hpp"

#include <cstddef>
#include <string>

#include "internal/file_util.hpp"

namespace tessera::io_internal {
namespace {

using Json = nlohmann::json;

// A SAX pass (nlohmann::json_sax) that builds nothing: it records where and why parsing stopped,
// which the DOM parser's exceptions do not say for every error (out_of_range.406, a number that
// overflows a double, carries no position), and refuses nesting deeper than kMaxJsonDepth.
class JsonChecker final : public nlohmann::json_sax<Json> {
 public:
  bool null() override { return true; }
  bool boolean(bool /*value*/) override { return true; }
  bool number_integer(number_integer_t /*value*/) override { return true; }
  bool number_unsigned(number_unsigned_t /*value*/) override { return true; }
  bool number_float(number_float_t /*value*/, const string_t& /*text*/) override { return true; }
  bool string(string_t& /*value*/) override { return true; }
  bool binary(binary_t& /*value*/) override { return true; }
  bool start_object(std::size_t /*elements*/) override { return enter(); }
  bool key(string_t& /*value*/) override { return true; }
  bool end_object() override { return leave(); }
  bool start_array(std::size_t /*elements*/) override { return enter(); }
  bool end_array() override { return leave(); }
  bool parse_error(std::size_t position, const std::string& last_token,
                   const nlohmann::json::exception& ex) override {
    failed_ = true;
    position_ = position;
    token_ = last_token;
    id_ = ex.id;
    reason_ = ex.what();
    return false;
  }

  [[nodiscard]] bool failed() const { return failed_; }
  [[nodiscard]] bool too_deep() const { return too_deep_; }
  [[nodiscard]] std::size_t position() const { return position_; }
  [[nodiscard]] const std::string& token() const { return token_; }
  [[nodiscard]] int id() const { return id_; }
  [[nodiscard]] const std::string& reason() const { return reason_; }

 private:
  bool enter() {
    if (++depth_ <= kMaxJsonDepth) return true;
    too_deep_ = true;
    return false;
  }
  bool leave() {
    --depth_;
    return true;
  }

  int depth_ = 0;
  bool failed_ = false;
  bool too_deep_ = false;
  std::size_t position_ = 0;
  std::string token_;
  int id_ = 0;
  std::string reason_;
};

// nlohmann's what() without the "[json.exception.parse_error.101] " tag and without the "parse
// error at line 3, column 5: " prefix (the caller names the line itself).
std::string plain_reason(std::string what) {
  if (what.starts_with("[json.exception.")) {
    if (const std::size_t end = what.find("] "); end != std::string::npos) what.erase(0, end + 2);
  }
  if (what.starts_with("parse error")) {
    if (const std::size_t colon = what.find(": "); colon != std::string::npos) {
      what.erase(0, colon + 2);
    }
  }
  return what;
}

}  // namespace

Result<nlohmann::json> parse_json(std::string_view text, const std::string& name) {
  JsonChecker checker;
  bool ok = false;
  try {
    ok = Json::sax_parse(text, &checker);
  } catch (const nlohmann::json::exception& e) {
    return input_error(name + ": JSON syntax error: " + plain_reason(e.what()));
  }
  if (checker.too_deep()) {
    return input_error(name + ": JSON nested deeper than " + std::to_string(kMaxJsonDepth) +
                       " levels");
  }
  if (!ok || checker.failed()) {
    // position counts the characters read, so the offending character is the one before it.
    const std::size_t offset = checker.position() > 0 ? checker.position() - 1 : 0;
    const std::string where = name + ":" + std::to_string(line_of_offset(text, offset)) + ": ";
    if (checker.id() == 406) {
      return input_error(where + "JSON number out of range: '" + checker.token() +
                         "' does not fit a double");
    }
    return input_error(where + "JSON syntax error: " + plain_reason(checker.reason()));
  }
  // The SAX pass accepted the text, so the DOM parser accepts it too; any exception it might
  // still throw is turned into the same kind of error.
  try {
    return Json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    return input_error(name + ": JSON syntax error: " + plain_reason(e.what()));
  }
}

}  // namespace tessera::io_internal
