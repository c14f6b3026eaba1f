#include "tessera/core/result.hpp"

#include <gtest/gtest.h>

#include <string>

namespace tessera {
namespace {

Result<int> parse_positive(int v) {
  if (v <= 0) return input_error("x.yaml:3: value must be > 0, got " + std::to_string(v));
  return v;
}

TEST(Result, CarriesTheValueOnSuccess) {
  const Result<int> r = parse_positive(5);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(*r, 5);
}

TEST(Result, CarriesKindAndMessageOnError) {
  const Result<int> r = parse_positive(-1);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().kind, ErrorKind::kInput);
  EXPECT_EQ(r.error().message, "x.yaml:3: value must be > 0, got -1");
}

TEST(Result, StatusSignalsSuccessWithoutAValue) {
  const Status s = Ok{};
  EXPECT_TRUE(s.ok());
  const Status bad = runtime_error("disk full");
  EXPECT_EQ(bad.error().kind, ErrorKind::kRuntime);
}

}  // namespace
}  // namespace tessera
