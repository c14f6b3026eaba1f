// Example firmware for the freestanding BOBMapping core (section 3.4) on a Cortex-M4: explores the
// 11 x 14 grid of the paper's experiments (section 4) in static buffers, against a fixed world
// kept in flash and an exact four-neighbour cell sensor, then stores the run's figures where a
// debugger can read them. It is a size and link check, not a robot: a real firmware replaces
// sense_around() with the five IR sensors of section 3.2 and moves the motors on each step.

#include <cstddef>
#include <cstdint>

#include "tessera/bob/explorer.hpp"

namespace {

using tessera::bob::Direction;
using tessera::bob::Explorer;
using tessera::bob::ExplorerOptions;
using tessera::bob::FinalMap;
using tessera::bob::GridCell;
using tessera::bob::PackedMap;
using tessera::bob::Status;

constexpr int kWidth = 11;
constexpr int kHeight = 14;

// The test world, top row first ('#' solid, 'R' the start, facing North); the same one as the
// "open 11 x 14 lab" of tests/bob/exploration_test.cpp.
constexpr char kWorld[kHeight][kWidth + 1] = {
    "...........", "...........", "..###......", "..#........", "..#....##..",
    "..#....##..", "...........", "...........", "......#....", ".....###...",
    "...........", "..##.......", "...........", "R..........",
};
constexpr GridCell kStart{0, 0};

bool solid(GridCell c) {
  if (c.x < 0 || c.x >= kWidth || c.y < 0 || c.y >= kHeight) return true;
  return kWorld[kHeight - 1 - c.y][c.x] == '#';
}

// The whole memory of the explorer: the 4-bit map, which the map-aware search also uses in place
// (decision 0004), and the 1-bit final map, which the explorer keeps current while mapping and
// which also holds the obstacles seen inside visited cells (decision 0008). No scratch.
std::uint8_t g_map[PackedMap::bytes_needed(kWidth, kHeight)];
std::uint8_t g_final_map[FinalMap::bytes_needed(kWidth, kHeight)];
#if BOB_FIRMWARE_MAP_AWARE
constexpr ExplorerOptions kOptions{tessera::bob::Backtrack::kShortestKnownPath};
#else
constexpr ExplorerOptions kOptions{tessera::bob::Backtrack::kTrail};
#endif
Explorer g_explorer;

void sense_around(GridCell c) {
  for (const Direction d : tessera::bob::kClockwiseFromNorth) {
    const GridCell n = tessera::bob::step(c, d);
    (void)g_explorer.sense(n, solid(n));  // kOutOfBounds past the grid's edge: ignored
  }
}

}  // namespace

// What the run did, for a debugger: status, moves, turns, stop reason, and the final 1-bit map.
extern "C" {
volatile std::uint32_t bob_result[4];
volatile const std::uint8_t* bob_final_map;
}

namespace {

void run_explorer() {
  Status s = g_explorer.init(kOptions, g_map, sizeof(g_map), g_final_map, sizeof(g_final_map),
                             kWidth, kHeight);
  if (s == Status::kOk) {
    sense_around(kStart);
    s = g_explorer.start(kStart, Direction::kNorth);
  }
  GridCell at = kStart;
  Direction move = Direction::kNorth;
  while (s == Status::kOk) {
    s = g_explorer.next_move(move);
    if (s != Status::kOk) break;
    at = tessera::bob::step(at, move);  // a robot drives one cell here, sampling its sensors
    sense_around(at);
  }
  bob_result[0] = static_cast<std::uint32_t>(s);
  bob_result[1] = g_explorer.moves();
  bob_result[2] = g_explorer.turns();
  bob_result[3] = static_cast<std::uint32_t>(g_explorer.stop_reason());
  bob_final_map = g_final_map;
}

}  // namespace

// Start-up: copy .data from flash, clear .bss, explore, then idle. No C library, no static
// constructors (the core's types are constant-initialised).
extern "C" {
extern std::uint32_t _sidata, _sdata, _edata, _sbss, _ebss, _estack;

[[noreturn]] void reset_handler() {
  const std::uint32_t* src = &_sidata;
  for (std::uint32_t* dst = &_sdata; dst < &_edata;) *dst++ = *src++;
  for (std::uint32_t* dst = &_sbss; dst < &_ebss;) *dst++ = 0;
  run_explorer();
  for (;;) {
  }
}

// GCC may call these even in freestanding code (e.g. to zero an aggregate); there is no C library,
// so the firmware provides them. -fno-tree-loop-distribute-patterns keeps the loops from becoming
// calls to themselves.
void* memset(void* dst, int value, std::size_t n) {
  auto* d = static_cast<std::uint8_t*>(dst);
  while (n-- != 0) *d++ = static_cast<std::uint8_t>(value);
  return dst;
}
void* memcpy(void* dst, const void* src, std::size_t n) {
  auto* d = static_cast<std::uint8_t*>(dst);
  const auto* s = static_cast<const std::uint8_t*>(src);
  while (n-- != 0) *d++ = *s++;
  return dst;
}

[[noreturn]] void default_handler() {
  for (;;) {
  }
}

// Cortex-M vector table: initial stack pointer, reset, and the 14 other system exceptions.
using Handler = void (*)();
__attribute__((section(".isr_vector"), used)) const Handler vector_table[16] = {
    reinterpret_cast<Handler>(&_estack),
    reset_handler,
    default_handler,
    default_handler,
    default_handler,
    default_handler,
    default_handler,
    nullptr,
    nullptr,
    nullptr,
    nullptr,
    default_handler,
    default_handler,
    nullptr,
    default_handler,
    default_handler,
};
}
