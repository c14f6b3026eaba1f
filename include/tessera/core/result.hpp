#pragma once
#include <string>
#include <utility>
#include <variant>

#include "tessera/core/assert.hpp"

namespace tessera {

/// What kind of mistake a user made; apps/ maps these to exit codes 2, 3 and 4.
enum class ErrorKind { kUsage, kInput, kRuntime };

/// An error a user can cause. `message` is one line and names the file and line where it applies:
/// "maps/lab.yaml:7: resolution must be > 0, got -0.05".
struct Error {
  ErrorKind kind = ErrorKind::kInput;
  std::string message;
};

/// An input error. Input errors quote what they found in the file, so control characters (bytes
/// below 0x20 and 0x7f: a line break inside a quoted YAML string, a damaged PNG chunk name) become
/// '?', which keeps the message one line and keeps terminal escapes out of it.
[[nodiscard]] inline Error input_error(std::string message) {
  for (char& c : message) {
    if ((c >= 0 && c < 0x20) || c == 0x7f) c = '?';
  }
  return {ErrorKind::kInput, std::move(message)};
}
[[nodiscard]] inline Error usage_error(std::string message) {
  return {ErrorKind::kUsage, std::move(message)};
}
[[nodiscard]] inline Error runtime_error(std::string message) {
  return {ErrorKind::kRuntime, std::move(message)};
}

/// A value or an Error; shaped like std::expected until C++23.
template <typename T>
class [[nodiscard]] Result {
 public:
  Result(T value) : v_(std::move(value)) {}      // NOLINT: implicit, like std::expected
  Result(Error error) : v_(std::move(error)) {}  // NOLINT

  [[nodiscard]] bool ok() const { return v_.index() == 0; }
  explicit operator bool() const { return ok(); }

  [[nodiscard]] T& value() & {
    TESSERA_ASSERT(ok());
    return std::get<0>(v_);
  }
  [[nodiscard]] const T& value() const& {
    TESSERA_ASSERT(ok());
    return std::get<0>(v_);
  }
  [[nodiscard]] T&& value() && {
    TESSERA_ASSERT(ok());
    return std::get<0>(std::move(v_));
  }
  [[nodiscard]] const Error& error() const {
    TESSERA_ASSERT(!ok());
    return std::get<1>(v_);
  }
  T* operator->() { return &value(); }
  const T* operator->() const { return &value(); }
  T& operator*() & { return value(); }
  const T& operator*() const& { return value(); }

 private:
  std::variant<T, Error> v_;
};

/// Success without a value.
struct Ok {};
using Status = Result<Ok>;

}  // namespace tessera
