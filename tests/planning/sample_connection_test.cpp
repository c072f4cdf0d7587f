#include "pmdplan/planning/sample_connection.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <utility>
#include <vector>

#include "planning/planar_roadmap.hpp"

namespace pmdplan {
namespace {

using test::addAt;

/// Records every segment asked about; free unless it crosses the line x = `wallX`.
class RecordingMotionValidator : public MotionValidator {
 public:
  double wallX = 100.0;
  std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> asked;
  bool isValid(const Configuration& from, const Configuration& to) override {
    asked.emplace_back(from, to);
    return (from[0] - wallX) * (to[0] - wallX) > 0.0;
  }
  std::size_t statesChecked() const override { return asked.size(); }
  bool askedAbout(const Configuration& p) const {
    return std::any_of(asked.begin(), asked.end(), [&](const auto& s) { return s.first == p || s.second == p; });
  }
};

TEST(FindNeighbours, TheKNearestWithinTheThresholdNearestFirst) {
  Roadmap roadmap;
  const NodeIndex s = addAt(roadmap, 0, 0);
  const NodeIndex far = addAt(roadmap, 5, 0);
  const NodeIndex b = addAt(roadmap, 0, 2);
  const NodeIndex a = addAt(roadmap, 1, 0);
  const NodeIndex c = addAt(roadmap, 3, 0);
  EXPECT_EQ(findNeighbours(roadmap, s, 10, 4.0), (std::vector<NodeIndex>{a, b, c}));
  EXPECT_EQ(findNeighbours(roadmap, s, 2, 4.0), (std::vector<NodeIndex>{a, b}));
  EXPECT_EQ(findNeighbours(roadmap, s, 10, 5.0), (std::vector<NodeIndex>{a, b, c, far}));
  EXPECT_TRUE(findNeighbours(roadmap, s, 10, 0.5).empty());
}

TEST(FindNeighbours, EqualDistancesAreOrderedByNodeIndex) {
  Roadmap roadmap;
  const NodeIndex s = addAt(roadmap, 0, 0);
  const NodeIndex n1 = addAt(roadmap, 0, 1);
  const NodeIndex n2 = addAt(roadmap, 1, 0);
  const NodeIndex n3 = addAt(roadmap, -1, 0);
  EXPECT_EQ(findNeighbours(roadmap, s, 2, 2.0), (std::vector<NodeIndex>{n1, n2}));
  EXPECT_EQ(findNeighbours(roadmap, s, 3, 2.0), (std::vector<NodeIndex>{n1, n2, n3}));
}

TEST(ConnectSample, SkipsNeighboursAlreadyInTheSameComponent) {
  Roadmap roadmap;
  const NodeIndex a = addAt(roadmap, 1, 0);
  const NodeIndex b = addAt(roadmap, 2, 0);
  roadmap.addEdge(a, b);
  const NodeIndex s = addAt(roadmap, 0, 0);
  RecordingMotionValidator motion;
  EXPECT_EQ(connectSample(roadmap, s, {10, 5.0}, std::nullopt, motion), 1u);
  EXPECT_EQ(motion.asked.size(), 1u) << "b is in a's component once s joins a: no check";
  EXPECT_TRUE(roadmap.sameComponent(s, b));
}

TEST(ConnectSample, OnlyFreeSegmentsBecomeEdges) {
  Roadmap roadmap;
  const NodeIndex left = addAt(roadmap, -1, 0);
  const NodeIndex right = addAt(roadmap, 1, 0);
  const NodeIndex s = addAt(roadmap, -0.5, 0);
  RecordingMotionValidator motion;
  motion.wallX = 0.0;
  EXPECT_EQ(connectSample(roadmap, s, {10, 5.0}, std::nullopt, motion), 1u);
  EXPECT_TRUE(roadmap.sameComponent(s, left));
  EXPECT_FALSE(roadmap.sameComponent(s, right));
  EXPECT_EQ(motion.asked.size(), 2u);
}

// Sect. 5.2: a sample of the first hypercube tries c_ini even when c_ini is neither among the K
// nearest nor within the threshold.
TEST(ConnectSample, TriesTheForcedNeighbourBeyondKAndTheThreshold) {
  Roadmap roadmap;
  const NodeIndex start = addAt(roadmap, 0, 0);
  const NodeIndex goal = addAt(roadmap, 10, 0);
  const NodeIndex near = addAt(roadmap, 2.1, 0);
  const NodeIndex s = addAt(roadmap, 2, 0);
  {
    RecordingMotionValidator motion;
    Roadmap copy = roadmap;
    EXPECT_EQ(connectSample(copy, s, {1, 1.5}, std::nullopt, motion), 1u);
    EXPECT_FALSE(motion.askedAbout(roadmap.node(start).configuration));
    EXPECT_FALSE(copy.sameComponent(s, start));
  }
  RecordingMotionValidator motion;
  EXPECT_EQ(connectSample(roadmap, s, {1, 1.5}, start, motion), 2u);
  EXPECT_TRUE(motion.askedAbout(roadmap.node(start).configuration));
  EXPECT_TRUE(roadmap.sameComponent(s, start));
  EXPECT_TRUE(roadmap.sameComponent(near, start));
  EXPECT_FALSE(roadmap.sameComponent(s, goal));
}

TEST(ConnectSample, TheLastHypercubeForcesTheGoal) {
  Roadmap roadmap;
  const NodeIndex start = addAt(roadmap, 0, 0);
  const NodeIndex goal = addAt(roadmap, 10, 0);
  addAt(roadmap, 6.9, 0);
  const NodeIndex s = addAt(roadmap, 7, 0);
  RecordingMotionValidator motion;
  connectSample(roadmap, s, {1, 1.0}, goal, motion);
  EXPECT_TRUE(roadmap.sameComponent(s, goal));
  EXPECT_FALSE(roadmap.sameComponent(s, start));
  // Nearest first: the close node before the forced goal.
  ASSERT_EQ(motion.asked.size(), 2u);
  EXPECT_EQ(motion.asked[0].first, roadmap.node(2).configuration);
  EXPECT_EQ(motion.asked[1].first, roadmap.node(goal).configuration);
}

TEST(ConnectSample, AForcedNeighbourAlreadyAmongTheNearestIsTriedOnce) {
  Roadmap roadmap;
  const NodeIndex start = addAt(roadmap, 0, 0);
  const NodeIndex s = addAt(roadmap, 0.1, 0);
  RecordingMotionValidator motion;
  EXPECT_EQ(connectSample(roadmap, s, {10, 1.0}, start, motion), 1u);
  EXPECT_EQ(motion.asked.size(), 1u);
}

}  // namespace
}  // namespace pmdplan
