// BOBMapping robot firmware for a Cortex-M4 (the ARM MPS2 AN386 board, which QEMU emulates as
// mps2-an386): the freestanding explorer of the bob/ core (section 3.4, Code 1 / Code 2) runs the
// robot's loop in static buffers and talks to the rest of the robot over UART0 (CMSDK APB UART,
// 0x40004000). On this board the rest of the robot is the host simulator (`tessera bob
// --firmware`): it moves the simulated body, reads the wheel encoders and the ceiling beacons
// (section 3.3) and the five IR sensors (section 3.2) during the move, and answers each motion
// request with the step's cell readings, or with a bump. The firmware decides every move and
// keeps the robot's only map; at the end it sends its counters and both maps, and stops the
// emulator through semihosting. Wire protocol (ASCII lines, firmware -> host "F:", host "H:"),
// docs/bob-firmware.md:
//   F: "H <variant> <resense>"            hello: 0 trail / 1 map-aware; re-sensing 1 on / 0 off
//   F: "W"             H: "G <w> <h>"      grid size   F: "I <status>"  (Explorer::init)
//   F: "S"             H: readings, "E"    sensing at the start pose   F: "U <maps>"
//   F: "P"             H: "C <x> <y>"      start cell  F: "A <status>"  (Explorer::start)
//   (status != 0: back to "W" with the next start cell)
//   F: "M <direction>" H: readings, "E"    one move (0 N, 1 E, 2 S, 3 W) and what it saw
//                                          F: "U <maps>"
//                      H: "B"              ... or a bump: F: "A <status>" (Explorer::blocked),
//                                          "U <maps>"
//   F: "F <status> <stop reason> <moves> <turns> <re-sensed> <ignored>", "D <maps>"
//   maps: "<4-bit map hex> <final map hex>", the bytes of PackedMap and FinalMap in memory order
//   readings: "T <x> <y> <occupied 0/1>" (a swept target cell), "X <x> <y>" (another detection)

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

// The paper's grid (section 4.1): 11 x 14 cells; any grid whose maps fit these buffers works.
constexpr int kWidth = 11;
constexpr int kHeight = 14;

// The whole memory of the explorer: the 4-bit map, which the map-aware search also uses in place
// (decision 0004), and the 1-bit final map, which the explorer keeps current while mapping and
// which also holds the obstacles seen inside visited cells (decision 0008). No scratch.
std::uint8_t g_map[PackedMap::bytes_needed(kWidth, kHeight)];
std::uint8_t g_final_map[FinalMap::bytes_needed(kWidth, kHeight)];
#if BOB_FIRMWARE_MAP_AWARE
constexpr ExplorerOptions kOptions{tessera::bob::Backtrack::kShortestKnownPath, true};
#else
constexpr ExplorerOptions kOptions{tessera::bob::Backtrack::kTrail, true};
#endif
Explorer g_explorer;

// CMSDK APB UART (ARM DDI 0479): DATA, STATE (bit 0 TX full, bit 1 RX full), CTRL (bit 0 TX
// enable, bit 1 RX enable), INTSTATUS, BAUDDIV.
struct Uart {
  volatile std::uint32_t data;
  volatile std::uint32_t state;
  volatile std::uint32_t ctrl;
  volatile std::uint32_t intstatus;
  volatile std::uint32_t bauddiv;
};
Uart& uart0() { return *reinterpret_cast<Uart*>(0x40004000u); }

void uart_init() {
  uart0().bauddiv = 16;  // the smallest divider the UART accepts
  uart0().ctrl = 3u;
}

void put(char c) {
  while ((uart0().state & 1u) != 0) {
  }
  uart0().data = static_cast<std::uint8_t>(c);
}

char get() {
  while ((uart0().state & 2u) == 0) {
  }
  return static_cast<char>(uart0().data & 0xFFu);
}

void put_uint(std::uint32_t v) {
  char digits[10];
  int n = 0;
  do {
    digits[n++] = static_cast<char>('0' + v % 10u);
    v /= 10u;
  } while (v != 0);
  while (n > 0) put(digits[--n]);
}

// A line is built field by field (no line buffer: the RAM budget is 512 bytes, docs/bob-firmware.md).
void field(std::uint32_t v) {
  put(' ');
  put_uint(v);
}

void send0(char letter) {
  put(letter);
  put('\n');
}

void send1(char letter, std::uint32_t value) {
  put(letter);
  field(value);
  put('\n');
}

void put_hex(const std::uint8_t* bytes, std::size_t n) {
  constexpr char kHex[] = "0123456789abcdef";
  put(' ');
  for (std::size_t i = 0; i < n; ++i) {
    put(kHex[bytes[i] >> 4]);
    put(kHex[bytes[i] & 0xFu]);
  }
}

// The monitor's stream (section 4.2: the robot reports to a listening monitor): both maps as
// they stand, after every step.
void send_maps(char letter) {
  put(letter);
  put_hex(g_explorer.map().data(), g_explorer.map().memory_bytes());
  put_hex(g_explorer.final_map().data(), g_explorer.final_map().memory_bytes());
  put('\n');
}

// One line from the host: its letter, and up to three signed decimal values in `v`.
char receive(int v[3]) {
  const char letter = get();
  int count = -1;
  bool negative = false;
  for (char c = get(); c != '\n'; c = get()) {
    if (c == ' ') {
      if (count >= 0 && count < 3 && negative) v[count] = -v[count];
      ++count;
      negative = false;
      if (count < 3) v[count] = 0;
    } else if (c == '-') {
      negative = true;
    } else if (count >= 0 && count < 3) {
      v[count] = v[count] * 10 + (c - '0');
    }
  }
  if (count >= 0 && count < 3 && negative) v[count] = -v[count];
  return letter;
}

// The readings of one step, or a bump, until the host's "E". Cells outside the grid come back
// kOutOfBounds from the explorer: ignored, the sensors see past the grid's edge.
void take_readings() {
  int v[3] = {0, 0, 0};
  for (;;) {
    const char letter = receive(v);
    if (letter == 'T') {
      (void)g_explorer.report_target({v[0], v[1]}, v[2] != 0);
    } else if (letter == 'X') {
      (void)g_explorer.report_detection({v[0], v[1]});
    } else if (letter == 'B') {  // the motors stalled against an obstacle: the move is undone
      send1('A', static_cast<std::uint32_t>(g_explorer.blocked()));
      send_maps('U');
      return;
    } else {  // 'E'
      send_maps('U');
      return;
    }
  }
}

// Semihosting SYS_EXIT (ADP_Stopped_ApplicationExit): the emulator stops. On a board without a
// debugger the breakpoint faults into default_handler, which idles.
[[noreturn]] void stop() {
  register std::uint32_t op asm("r0") = 0x18u;
  register std::uint32_t reason asm("r1") = 0x20026u;
  asm volatile("bkpt 0xab" : : "r"(op), "r"(reason) : "memory");
  for (;;) {
  }
}

// BOBMapping Code 1: place the robot, then move and sense until the explorer stops.
[[noreturn]] void run_robot() {
  uart_init();
  put('H');
  field(kOptions.backtrack == tessera::bob::Backtrack::kTrail ? 0u : 1u);
  field(kOptions.resense ? 1u : 0u);
  put('\n');
  int v[3] = {0, 0, 0};
  Status s = Status::kFrontBlocked;
  while (s != Status::kOk) {
    send0('W');
    if (receive(v) != 'G') stop();
    s = g_explorer.init(kOptions, g_map, sizeof(g_map), g_final_map, sizeof(g_final_map), v[0],
                        v[1]);
    send1('I', static_cast<std::uint32_t>(s));
    if (s != Status::kOk) stop();
    send0('S');
    take_readings();
    send0('P');
    if (receive(v) != 'C') stop();
    s = g_explorer.start({v[0], v[1]}, Direction::kNorth);
    send1('A', static_cast<std::uint32_t>(s));
  }
  Direction move = Direction::kNorth;
  while ((s = g_explorer.next_move(move)) == Status::kOk) {
    send1('M', static_cast<std::uint32_t>(move));  // the motors drive one cell; sensing on the way
    take_readings();
  }
  put('F');
  field(static_cast<std::uint32_t>(s));
  field(static_cast<std::uint32_t>(g_explorer.stop_reason()));
  field(g_explorer.moves());
  field(g_explorer.turns());
  field(g_explorer.resensed());
  field(g_explorer.ignored_readings());
  put('\n');
  send_maps('D');
  stop();
}

}  // namespace

// Start-up: copy .data from flash, clear .bss, run the robot. No C library, no static
// constructors (the core's types are constant-initialised).
extern "C" {
extern std::uint32_t _sidata, _sdata, _edata, _sbss, _ebss, _estack;

[[noreturn]] void reset_handler() {
  const std::uint32_t* src = &_sidata;
  for (std::uint32_t* dst = &_sdata; dst < &_edata;) *dst++ = *src++;
  for (std::uint32_t* dst = &_sbss; dst < &_ebss;) *dst++ = 0;
  run_robot();
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
