#pragma once
// Appending little-endian binary fields to a byte string, the writing side of byte_cursor.hpp,
// shared by the binary formats tessera writes (MCAP, session files). The host is little-endian
// (x86-64, ARM), so a value's bytes are copied as they are.
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

namespace tessera::io_internal {

/// Appends the bytes of an integer or IEEE-754 real.
template <typename T>
void put(std::string& out, T v) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &v, sizeof(T));
  out.append(bytes, sizeof(T));
}

/// Appends a u32 length, then the bytes.
inline void put_string(std::string& out, std::string_view s) {
  put(out, static_cast<std::uint32_t>(s.size()));
  out.append(s);
}

}  // namespace tessera::io_internal
