#include "tessera/core/assert.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

namespace tessera {
namespace {

struct AssertionFailure {
  std::string expression;
  std::string file;
  int line = 0;
};

void throwing_handler(const char* expression, const char* file, int line) {
  throw AssertionFailure{expression, file, line};
}

int g_calls = 0;
void counting_handler(const char*, const char*, int) { ++g_calls; }

/// Restores the handler a test found when it ends, so tests do not leak handlers.
class AssertHandlerTest : public ::testing::Test {
 protected:
  void SetUp() override { previous_ = set_assert_handler(nullptr); }
  void TearDown() override { set_assert_handler(previous_); }

 private:
  AssertHandler previous_ = nullptr;
};

TEST_F(AssertHandlerTest, SetReturnsThePreviousHandler) {
  const AssertHandler default_handler = set_assert_handler(&throwing_handler);
  ASSERT_NE(default_handler, nullptr);
  EXPECT_NE(default_handler, &throwing_handler);
  EXPECT_EQ(set_assert_handler(&counting_handler), &throwing_handler);
  EXPECT_EQ(set_assert_handler(&throwing_handler), &counting_handler);
}

TEST_F(AssertHandlerTest, NullptrRestoresTheDefault) {
  const AssertHandler default_handler = set_assert_handler(&throwing_handler);
  EXPECT_EQ(set_assert_handler(nullptr), &throwing_handler);
  // What nullptr installed is the default itself, not a null pointer.
  EXPECT_EQ(set_assert_handler(&throwing_handler), default_handler);
}

TEST_F(AssertHandlerTest, ThrowingHandlerSeesExpressionFileAndLine) {
  set_assert_handler(&throwing_handler);
  const int x = 2;
  int line = 0;
  try {
    line = __LINE__ + 1;
    TESSERA_ASSERT(x + 1 == 4);
    FAIL() << "the handler was not called";
  } catch (const AssertionFailure& f) {
    EXPECT_EQ(f.expression, "x + 1 == 4");
    EXPECT_EQ(f.file, __FILE__);
    EXPECT_EQ(f.line, line);
  }
}

TEST_F(AssertHandlerTest, HoldingConditionDoesNotCallTheHandler) {
  set_assert_handler(&counting_handler);
  g_calls = 0;
  TESSERA_ASSERT(1 + 1 == 2);
  EXPECT_EQ(g_calls, 0);
}

TEST_F(AssertHandlerTest, ConditionIsEvaluatedOnce) {
  set_assert_handler(&throwing_handler);
  int n = 0;
  TESSERA_ASSERT(++n == 1);
  EXPECT_EQ(n, 1);
  EXPECT_THROW(TESSERA_ASSERT(++n == 1), AssertionFailure);
  EXPECT_EQ(n, 2);
}

using AssertHandlerDeathTest = AssertHandlerTest;

TEST_F(AssertHandlerDeathTest, DefaultHandlerPrintsTheFailureAndAborts) {
  // SetUp installed the default (nullptr).
  EXPECT_DEATH(TESSERA_ASSERT(2 < 1), "assert_test\\.cpp:[0-9]+: assertion failed: 2 < 1");
}

TEST_F(AssertHandlerDeathTest, HandlerThatReturnsStillAborts) {
  // A handler that returns must not let the caller continue past a broken precondition.
  set_assert_handler(&counting_handler);
  EXPECT_DEATH(
      {
        TESSERA_ASSERT(2 < 1);
        std::exit(0);  // reached only if assert_failed returned
      },
      "");
}

}  // namespace
}  // namespace tessera
