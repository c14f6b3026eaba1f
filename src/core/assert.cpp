#include "tessera/core/assert.hpp"

#include <atomic>
#include <cstdio>
#include <cstdlib>

namespace tessera {
namespace {

void default_handler(const char* expression, const char* file, int line) {
  // The one place the library writes to a stream: a programmer error is about to abort.
  std::fprintf(stderr, "%s:%d: assertion failed: %s\n", file, line, expression);
  std::abort();
}

std::atomic<AssertHandler> g_handler{&default_handler};

}  // namespace

AssertHandler set_assert_handler(AssertHandler handler) {
  return g_handler.exchange(handler != nullptr ? handler : &default_handler);
}

void assert_failed(const char* expression, const char* file, int line) {
  g_handler.load()(expression, file, line);
  std::abort();  // a handler that returns still must not continue past a broken precondition
}

}  // namespace tessera
