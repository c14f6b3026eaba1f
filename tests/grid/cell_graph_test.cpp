#include "tessera/grid/cell_graph.hpp"

#include <gtest/gtest.h>

#include <string>

#include "tessera/core/assert.hpp"

namespace tessera {
namespace {

// Three cells on an L, plus a fourth whose centre repeats cell 1's.
CellGraph l_graph() {
  CellGraph g;
  g.centres_m = {{0.0, 0.0}, {2.0, 0.0}, {0.0, 2.0}, {2.0, 0.0}};
  g.adjacent = {{1, 2}, {0, 3}, {0}, {1}};
  return g;
}

TEST(CellGraph, SizeIsTheNumberOfCentres) {
  EXPECT_EQ(l_graph().size(), 4u);
  EXPECT_EQ(CellGraph{}.size(), 0u);
}

TEST(CellGraph, NearestIsTheCellWithTheClosestCentre) {
  const CellGraph g = l_graph();
  EXPECT_EQ(g.nearest({0.0, 0.0}), 0u);
  EXPECT_EQ(g.nearest({0.9, 0.1}), 0u);
  EXPECT_EQ(g.nearest({1.1, 0.0}), 1u);
  EXPECT_EQ(g.nearest({0.2, 1.2}), 2u);
  EXPECT_EQ(g.nearest({-10.0, 50.0}), 2u);  // far outside: still the nearest centre
}

TEST(CellGraph, TiesGoToTheLowerId) {
  const CellGraph g = l_graph();
  // (1, 0) is 1 m from cells 0 and 1.
  EXPECT_EQ(g.nearest({1.0, 0.0}), 0u);
  // (1, 1) is sqrt(2) m from cells 0, 1, 2 and 3.
  EXPECT_EQ(g.nearest({1.0, 1.0}), 0u);
  // On cell 3's centre, which is also cell 1's: the lower id.
  EXPECT_EQ(g.nearest({2.0, 0.0}), 1u);
  // (1, 2) is 1 m from cell 2 and sqrt(5) m from 1 and 3: no tie.
  EXPECT_EQ(g.nearest({1.0, 2.0}), 2u);
}

void throwing_handler(const char* expression, const char*, int) {
  throw std::string(expression);
}

TEST(CellGraph, NearestOnAnEmptyGraphBreaksItsPrecondition) {
  const AssertHandler previous = set_assert_handler(&throwing_handler);
  EXPECT_THROW(static_cast<void>(CellGraph{}.nearest({0.0, 0.0})), std::string);
  set_assert_handler(previous);
}

}  // namespace
}  // namespace tessera
