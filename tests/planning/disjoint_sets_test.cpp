#include "pmdplan/planning/disjoint_sets.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace pmdplan {
namespace {

TEST(DisjointSets, StartsAsSingletons) {
  DisjointSets sets;
  for (int i = 0; i < 5; ++i) EXPECT_EQ(sets.add(), static_cast<std::size_t>(i));
  EXPECT_EQ(sets.setCount(), 5u);
  for (std::size_t a = 0; a < 5; ++a)
    for (std::size_t b = 0; b < 5; ++b) EXPECT_EQ(sets.same(a, b), a == b);
}

TEST(DisjointSets, UnionsAreTransitiveAndCounted) {
  DisjointSets sets;
  for (int i = 0; i < 6; ++i) sets.add();
  EXPECT_TRUE(sets.unite(0, 1));
  EXPECT_TRUE(sets.unite(2, 3));
  EXPECT_EQ(sets.setCount(), 4u);
  EXPECT_FALSE(sets.same(1, 2));
  EXPECT_TRUE(sets.unite(1, 3));
  EXPECT_TRUE(sets.same(0, 2));
  EXPECT_FALSE(sets.unite(0, 3)) << "already one set";
  EXPECT_EQ(sets.setCount(), 3u);
  EXPECT_FALSE(sets.same(4, 5));
  EXPECT_FALSE(sets.same(0, 4));
}

TEST(DisjointSets, MatchesANaiveLabellingOnALongChain) {
  DisjointSets sets;
  const std::size_t n = 1000;
  std::vector<std::size_t> label(n);
  for (std::size_t i = 0; i < n; ++i) label[i] = sets.add();
  // Join every third element to its successor's chain; compare with naive relabelling.
  for (std::size_t i = 0; i + 3 < n; i += 3) {
    sets.unite(i, i + 3);
    const std::size_t from = label[i + 3];
    for (auto& l : label)
      if (l == from) l = label[i];
  }
  for (std::size_t a = 0; a < n; a += 7)
    for (std::size_t b = 0; b < n; b += 11) EXPECT_EQ(sets.same(a, b), label[a] == label[b]);
  EXPECT_EQ(sets.setCount(), n - (n - 1) / 3);
}

TEST(DisjointSets, ClearAndOutOfRange) {
  DisjointSets sets;
  sets.add();
  EXPECT_THROW(sets.find(1), std::out_of_range);
  sets.clear();
  EXPECT_EQ(sets.size(), 0u);
  EXPECT_EQ(sets.setCount(), 0u);
}

}  // namespace
}  // namespace pmdplan
