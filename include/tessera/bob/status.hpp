#pragma once
// Status codes of the freestanding bob/ core. The core never throws, allocates or prints: every
// fallible call returns a Status (section 3.4 runs on a microcontroller; so does this code).
// Freestanding: no standard library beyond <cstdint>.

#include <cstdint>

namespace tessera::bob {

enum class Status : std::uint8_t {
  kOk = 0,
  kFinished,        // the explorer has stopped; see Explorer::stop_reason()
  kBadSize,         // width or height < 1, or more cells than the core takes (16384)
  kBufferTooSmall,  // a caller-supplied buffer is null or smaller than bytes_needed()
  kOutOfBounds,     // a cell outside the grid
  kFrontBlocked,    // start cell's front neighbour is occupied or outside the grid (section 3.4)
  kNotStarted,      // next_move() before start(), or start() before init()
  kAlreadyStarted,  // start() called twice
};

/// A short constant name for logs and test messages ("ok", "front blocked", ...).
[[nodiscard]] const char* status_name(Status s);

}  // namespace tessera::bob
