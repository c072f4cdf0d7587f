#include "pmdplan/planning/roadmap.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace pmdplan {
namespace {

RoadmapNode at(double x, double y, double step = 0.5) {
  return {Eigen::Vector2d(x, y), Eigen::Vector2d(x, y), step, 2};
}

TEST(Roadmap, EdgesJoinComponentsBothWays) {
  Roadmap roadmap;
  const NodeIndex a = roadmap.addNode(at(0, 0));
  const NodeIndex b = roadmap.addNode(at(3, 4));
  const NodeIndex c = roadmap.addNode(at(6, 8));
  EXPECT_EQ(roadmap.componentCount(), 3u);
  roadmap.addEdge(a, b);
  EXPECT_TRUE(roadmap.sameComponent(a, b));
  EXPECT_FALSE(roadmap.sameComponent(a, c));
  EXPECT_EQ(roadmap.componentCount(), 2u);
  ASSERT_EQ(roadmap.edges(a).size(), 1u);
  ASSERT_EQ(roadmap.edges(b).size(), 1u);
  EXPECT_EQ(roadmap.edges(a)[0].target, b);
  EXPECT_EQ(roadmap.edges(b)[0].target, a);
  EXPECT_DOUBLE_EQ(roadmap.edges(a)[0].length, 5.0);
  roadmap.addEdge(c, b);
  EXPECT_TRUE(roadmap.sameComponent(a, c));
  EXPECT_EQ(roadmap.componentCount(), 1u);
  EXPECT_EQ(roadmap.edgeCount(), 2u);
  EXPECT_DOUBLE_EQ(roadmap.distance(a, c), 10.0);
}

TEST(Roadmap, RejectsBadEdgesAndMixedDimensions) {
  Roadmap roadmap;
  const NodeIndex a = roadmap.addNode(at(0, 0));
  EXPECT_THROW(roadmap.addEdge(a, a), std::invalid_argument);
  EXPECT_THROW(roadmap.addEdge(a, 7), std::invalid_argument);
  EXPECT_THROW(roadmap.addNode({Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), 0.0, 0}), std::invalid_argument);
}

TEST(Roadmap, ClearEmptiesEverything) {
  Roadmap roadmap;
  roadmap.addEdge(roadmap.addNode(at(0, 0)), roadmap.addNode(at(1, 0)));
  roadmap.clear();
  EXPECT_EQ(roadmap.nodeCount(), 0u);
  EXPECT_EQ(roadmap.edgeCount(), 0u);
  EXPECT_EQ(roadmap.componentCount(), 0u);
}

}  // namespace
}  // namespace pmdplan
