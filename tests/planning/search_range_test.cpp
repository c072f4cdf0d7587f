#include "pmdplan/planning/search_range.hpp"

#include <gtest/gtest.h>

namespace pmdplan {
namespace {

NodeIndex addOnTheLine(Roadmap& roadmap, double x, double step) {
  return roadmap.addNode({Eigen::Vector2d(x, 0.0), Eigen::Vector2d(x, 0.0), step, step == 0.0 || step == 1.0 ? 0 : 2});
}

TEST(SearchRange, StartsAsTheWholeSegment) {
  Roadmap roadmap;
  const NodeIndex start = addOnTheLine(roadmap, 0.0, 0.0);
  const NodeIndex goal = addOnTheLine(roadmap, 1.0, 1.0);
  const SearchRange range = updateSearchRange(roadmap, start, goal);
  EXPECT_EQ(range.low, 0.0);
  EXPECT_EQ(range.high, 1.0);
  EXPECT_TRUE(range.contains(0.0));
  EXPECT_TRUE(range.contains(1.0));
  EXPECT_TRUE(SearchRange{}.contains(0.5));
}

// Fig. 13: s_1 from B^a(c_goal^a) joins c_goal; s_2 from the hypercube at 0.5 and s_3 from
// B^a(c_ini^a) join c_ini. Two components, range [0.5, 1.0].
TEST(SearchRange, ReproducesFigure13) {
  Roadmap roadmap;
  const NodeIndex start = addOnTheLine(roadmap, 0.0, 0.0);
  const NodeIndex goal = addOnTheLine(roadmap, 1.0, 1.0);
  const NodeIndex s1 = addOnTheLine(roadmap, 0.98, 1.0);
  roadmap.addEdge(s1, goal);
  const NodeIndex s2 = addOnTheLine(roadmap, 0.5, 0.5);
  const NodeIndex s3 = addOnTheLine(roadmap, 0.03, 0.0);
  roadmap.addEdge(s3, start);
  roadmap.addEdge(s2, s3);
  ASSERT_EQ(roadmap.componentCount(), 2u);

  const SearchRange range = updateSearchRange(roadmap, start, goal);
  EXPECT_EQ(range.low, 0.5);
  EXPECT_EQ(range.high, 1.0);
  EXPECT_FALSE(range.contains(0.25));
  EXPECT_TRUE(range.contains(0.75));
}

TEST(SearchRange, IgnoresIsolatedSamplesAndNarrowsFromBothSides) {
  Roadmap roadmap;
  const NodeIndex start = addOnTheLine(roadmap, 0.0, 0.0);
  const NodeIndex goal = addOnTheLine(roadmap, 1.0, 1.0);
  addOnTheLine(roadmap, 0.6, 0.625);  // joined to neither: no influence
  const NodeIndex nearGoal = addOnTheLine(roadmap, 0.75, 0.75);
  roadmap.addEdge(nearGoal, goal);
  const NodeIndex nearStart = addOnTheLine(roadmap, 0.25, 0.25);
  roadmap.addEdge(nearStart, start);
  const SearchRange range = updateSearchRange(roadmap, start, goal);
  EXPECT_EQ(range.low, 0.25);
  EXPECT_EQ(range.high, 0.75);
}

TEST(SearchRange, ComponentsReachingPastEachOtherGiveTheOverlap) {
  Roadmap roadmap;
  const NodeIndex start = addOnTheLine(roadmap, 0.0, 0.0);
  const NodeIndex goal = addOnTheLine(roadmap, 1.0, 1.0);
  const NodeIndex farFromStart = addOnTheLine(roadmap, 0.7, 0.75);
  roadmap.addEdge(farFromStart, start);
  const NodeIndex farFromGoal = addOnTheLine(roadmap, 0.3, 0.25);
  roadmap.addEdge(farFromGoal, goal);
  const SearchRange range = updateSearchRange(roadmap, start, goal);
  EXPECT_EQ(range.low, 0.25);
  EXPECT_EQ(range.high, 0.75);
}

}  // namespace
}  // namespace pmdplan
