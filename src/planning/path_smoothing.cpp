#include "pmdplan/planning/path_smoothing.hpp"

#include <algorithm>
#include <functional>
#include <limits>

namespace pmdplan {
namespace {

enum class EdgeState : char { Unknown, Free, Blocked };

/// Dijkstra over the complete graph of n nodes without the blocked edges (O(n^2), n is small).
/// Equal costs keep the first-found predecessor and the smallest unvisited index, so the result
/// is deterministic.
std::vector<std::size_t> shortestPath(const std::vector<std::vector<double>>& length,
                                      const std::vector<std::vector<EdgeState>>& state) {
  const std::size_t n = length.size();
  constexpr double unreached = std::numeric_limits<double>::infinity();
  constexpr std::size_t none = std::numeric_limits<std::size_t>::max();
  std::vector<double> cost(n, unreached);
  std::vector<std::size_t> previous(n, none);
  std::vector<char> done(n, 0);
  cost[0] = 0.0;
  for (std::size_t round = 0; round < n; ++round) {
    std::size_t current = none;
    for (std::size_t i = 0; i < n; ++i)
      if (done[i] == 0 && cost[i] < unreached && (current == none || cost[i] < cost[current])) current = i;
    if (current == none || current == n - 1) break;
    done[current] = 1;
    for (std::size_t next = 0; next < n; ++next) {
      if (done[next] != 0 || next == current || state[current][next] == EdgeState::Blocked) continue;
      const double candidate = cost[current] + length[current][next];
      if (candidate < cost[next]) {
        cost[next] = candidate;
        previous[next] = current;
      }
    }
  }
  std::vector<std::size_t> path;
  for (std::size_t at = n - 1; at != none; at = previous[at]) path.push_back(at);
  std::reverse(path.begin(), path.end());
  return path;
}

/// The shortcut of the nodes first..last (indices into `path`), as shortcutPathIndices describes.
std::vector<std::size_t> shortcutWindow(const std::vector<Configuration>& path, std::size_t first, std::size_t last,
                                        const PlanningSpace& space, MotionValidator& motionValidator,
                                        const std::function<bool()>& stop) {
  const std::size_t n = last - first + 1;
  std::vector<std::vector<double>> length(n, std::vector<double>(n, 0.0));
  std::vector<std::vector<EdgeState>> state(n, std::vector<EdgeState>(n, EdgeState::Unknown));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      length[i][j] = length[j][i] = space.distance(path[first + i], path[first + j]);
  for (std::size_t i = 0; i + 1 < n; ++i) state[i][i + 1] = state[i + 1][i] = EdgeState::Free;

  // Each round settles at least one unknown edge, and the original chain keeps a path, so this ends.
  // Once a stop is asked for, edges not yet checked count as blocked: the answer is the shortest
  // path over the edges known to be free (at worst the original chain), found at once.
  for (;;) {
    if (stop && stop())
      for (auto& row : state) std::replace(row.begin(), row.end(), EdgeState::Unknown, EdgeState::Blocked);
    const std::vector<std::size_t> candidate = shortestPath(length, state);
    bool allFree = true;
    for (std::size_t k = 0; k + 1 < candidate.size() && allFree; ++k) {
      const std::size_t a = candidate[k];
      const std::size_t b = candidate[k + 1];
      if (state[a][b] != EdgeState::Unknown) continue;
      const bool free = motionValidator.isValid(path[first + a], path[first + b]);
      state[a][b] = state[b][a] = free ? EdgeState::Free : EdgeState::Blocked;
      allFree = free;
    }
    if (allFree) {
      std::vector<std::size_t> indices;
      for (const std::size_t i : candidate) indices.push_back(first + i);
      return indices;
    }
  }
}

}  // namespace

std::vector<std::size_t> shortcutPathIndices(const std::vector<Configuration>& path, const PlanningSpace& space,
                                             MotionValidator& motionValidator, const std::function<bool()>& stop) {
  const std::size_t n = path.size();
  if (n <= 2) {
    std::vector<std::size_t> all(n);
    for (std::size_t i = 0; i < n; ++i) all[i] = i;
    return all;
  }
  // Windows of kMaxSmoothingWindowNodes consecutive nodes, each sharing its last node with the next.
  std::vector<std::size_t> indices{0};
  for (std::size_t first = 0; first + 1 < n; first += kMaxSmoothingWindowNodes - 1) {
    const std::size_t last = std::min(n - 1, first + kMaxSmoothingWindowNodes - 1);
    const std::vector<std::size_t> window = shortcutWindow(path, first, last, space, motionValidator, stop);
    indices.insert(indices.end(), window.begin() + 1, window.end());
  }
  return indices;
}

std::vector<Configuration> smoothPath(const std::vector<Configuration>& path, const PlanningSpace& space,
                                      MotionValidator& motionValidator, const std::function<bool()>& stop) {
  std::vector<Configuration> smoothed;
  for (const std::size_t i : shortcutPathIndices(path, space, motionValidator, stop)) smoothed.push_back(path[i]);
  return smoothed;
}

double pathLength(const std::vector<Configuration>& path, const PlanningSpace& space) {
  double total = 0.0;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) total += space.distance(path[i], path[i + 1]);
  return total;
}

}  // namespace pmdplan
