#include "pmdplan/planning/roadmap_path_search.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <random>
#include <vector>

#include "planning/planar_roadmap.hpp"
#include "pmdplan/core/random_source.hpp"

namespace pmdplan {
namespace {

using test::addAt;

double lengthOf(const Roadmap& roadmap, const std::vector<NodeIndex>& path) {
  double total = 0.0;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) total += roadmap.distance(path[i], path[i + 1]);
  return total;
}

/// Plain Dijkstra over the same graph: the reference the A* result must match in length.
double dijkstraLength(const Roadmap& roadmap, NodeIndex from, NodeIndex to) {
  std::vector<double> cost(roadmap.nodeCount(), std::numeric_limits<double>::infinity());
  std::vector<char> done(roadmap.nodeCount(), 0);
  cost[from] = 0.0;
  for (;;) {
    NodeIndex best = roadmap.nodeCount();
    for (NodeIndex i = 0; i < roadmap.nodeCount(); ++i)
      if (done[i] == 0 && cost[i] < std::numeric_limits<double>::infinity() &&
          (best == roadmap.nodeCount() || cost[i] < cost[best]))
        best = i;
    if (best == roadmap.nodeCount()) return cost[to];
    done[best] = 1;
    for (const RoadmapEdge& e : roadmap.edges(best)) cost[e.target] = std::min(cost[e.target], cost[best] + e.length);
  }
}

//   s ---- a ---- g          the direct route s-a-g is 2 long,
//    \           /           the detour s-b-c-g about 3.2; A* must take s-a-g
//     b ------- c
TEST(FindRoadmapPath, TakesTheShortestRouteOfAHandBuiltGraph) {
  Roadmap roadmap;
  const NodeIndex s = addAt(roadmap, 0, 0);
  const NodeIndex a = addAt(roadmap, 1, 0);
  const NodeIndex g = addAt(roadmap, 2, 0);
  const NodeIndex b = addAt(roadmap, 0.3, -0.8);
  const NodeIndex c = addAt(roadmap, 1.7, -0.8);
  roadmap.addEdge(s, b);
  roadmap.addEdge(b, c);
  roadmap.addEdge(c, g);
  roadmap.addEdge(s, a);
  roadmap.addEdge(a, g);
  EXPECT_EQ(findRoadmapPath(roadmap, s, g), (std::vector<NodeIndex>{s, a, g}));
  EXPECT_EQ(findRoadmapPath(roadmap, g, s), (std::vector<NodeIndex>{g, a, s}));
  EXPECT_EQ(findRoadmapPath(roadmap, b, a), (std::vector<NodeIndex>{b, s, a}));
  EXPECT_EQ(findRoadmapPath(roadmap, c, c), (std::vector<NodeIndex>{c}));
}

TEST(FindRoadmapPath, DisconnectedNodesHaveNoPath) {
  Roadmap roadmap;
  const NodeIndex s = addAt(roadmap, 0, 0);
  const NodeIndex g = addAt(roadmap, 1, 0);
  const NodeIndex x = addAt(roadmap, 0.5, 0);
  roadmap.addEdge(s, x);
  EXPECT_TRUE(findRoadmapPath(roadmap, s, g).empty());
  EXPECT_TRUE(findRoadmapPath(roadmap, s, 99).empty());
}

TEST(FindRoadmapPath, MatchesDijkstraOnRandomGraphs) {
  RandomSource random(7);
  for (int graph = 0; graph < 50; ++graph) {
    Roadmap roadmap;
    for (int i = 0; i < 40; ++i) addAt(roadmap, random.uniform01(), random.uniform01());
    for (int e = 0; e < 90; ++e) {
      const auto a = static_cast<NodeIndex>(random.uniform01() * 40);
      const auto b = static_cast<NodeIndex>(random.uniform01() * 40);
      if (a != b) roadmap.addEdge(a, b);
    }
    const NodeIndex from = 0;
    const NodeIndex to = 39;
    const std::vector<NodeIndex> path = findRoadmapPath(roadmap, from, to);
    const double reference = dijkstraLength(roadmap, from, to);
    if (!roadmap.sameComponent(from, to)) {
      EXPECT_TRUE(path.empty());
      continue;
    }
    ASSERT_GE(path.size(), 2u);
    EXPECT_EQ(path.front(), from);
    EXPECT_EQ(path.back(), to);
    for (std::size_t i = 0; i + 1 < path.size(); ++i) {
      bool joined = false;
      for (const RoadmapEdge& e : roadmap.edges(path[i])) joined = joined || e.target == path[i + 1];
      EXPECT_TRUE(joined) << "consecutive path nodes must share an edge";
    }
    EXPECT_NEAR(lengthOf(roadmap, path), reference, 1e-12) << "graph " << graph;
  }
}

}  // namespace
}  // namespace pmdplan
