#pragma once
// Programmer-error checks. A broken precondition calls the installed handler (default: abort with
// the failed expression). Tests may install a handler that throws. Errors a user can cause never
// go through here: they are returned as Result<T>.

namespace tessera {

using AssertHandler = void (*)(const char* expression, const char* file, int line);

/// Installs `handler` and returns the previous one. nullptr restores the default (abort).
AssertHandler set_assert_handler(AssertHandler handler);

[[noreturn]] void assert_failed(const char* expression, const char* file, int line);

}  // namespace tessera

#define TESSERA_ASSERT(expr) \
  ((expr) ? static_cast<void>(0) : ::tessera::assert_failed(#expr, __FILE__, __LINE__))
