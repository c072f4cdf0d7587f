#include "pmdplan/planning/roadmap_path_search.hpp"

#include <algorithm>
#include <functional>
#include <limits>
#include <queue>
#include <tuple>

namespace pmdplan {

std::vector<NodeIndex> findRoadmapPath(const Roadmap& roadmap, NodeIndex from, NodeIndex to) {
  if (from >= roadmap.nodeCount() || to >= roadmap.nodeCount()) return {};
  if (!roadmap.sameComponent(from, to)) return {};

  constexpr double unreached = std::numeric_limits<double>::infinity();
  constexpr NodeIndex none = std::numeric_limits<NodeIndex>::max();
  std::vector<double> costSoFar(roadmap.nodeCount(), unreached);
  std::vector<NodeIndex> cameFrom(roadmap.nodeCount(), none);
  std::vector<char> closed(roadmap.nodeCount(), 0);
  // (f = g + h, node): the smallest f first, equal f by the smaller node index.
  using Entry = std::tuple<double, NodeIndex>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;

  costSoFar[from] = 0.0;
  open.emplace(roadmap.distance(from, to), from);
  while (!open.empty()) {
    const NodeIndex current = std::get<1>(open.top());
    open.pop();
    if (closed[current] != 0) continue;
    if (current == to) break;
    closed[current] = 1;
    for (const RoadmapEdge& edge : roadmap.edges(current)) {
      if (closed[edge.target] != 0) continue;
      const double cost = costSoFar[current] + edge.length;
      if (cost < costSoFar[edge.target]) {
        costSoFar[edge.target] = cost;
        cameFrom[edge.target] = current;
        open.emplace(cost + roadmap.distance(edge.target, to), edge.target);
      }
    }
  }
  if (costSoFar[to] == unreached) return {};

  std::vector<NodeIndex> path;
  for (NodeIndex at = to; at != none; at = cameFrom[at]) path.push_back(at);
  std::reverse(path.begin(), path.end());
  return path;
}

}  // namespace pmdplan
