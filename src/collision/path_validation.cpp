#include "pmdplan/collision/path_validation.hpp"

#include <algorithm>
#include <cstdio>

namespace pmdplan {
namespace {

void addPairs(PathValidation& result, const CollisionReport& report) {
  for (const auto& pair : report.pairs)
    if (std::find(result.collisions.pairs.begin(), result.collisions.pairs.end(), pair) ==
        result.collisions.pairs.end())
      result.collisions.pairs.push_back(pair);
}

}  // namespace

PathValidation validatePath(ExactCollisionChecker& checker, const SegmentChecker& segments,
                            const std::vector<Configuration>& path, const Configuration& start,
                            const Configuration& goal, std::optional<ClosingPhase> closing) {
  PathValidation result;
  const auto& model = checker.model();
  const auto fail = [&](std::string problem) {
    result.valid = false;
    result.problems.push_back(std::move(problem));
  };
  if (path.size() < 2) {
    fail("a path needs at least two points");
    return result;
  }
  // Ends: the file must start and end exactly where the task does (within rounding of text).
  constexpr double kEndTolerance = 1e-9;
  if ((path.front() - start).cwiseAbs().maxCoeff() > kEndTolerance) fail("the first point is not the task's start");
  if ((path.back() - goal).cwiseAbs().maxCoeff() > kEndTolerance) fail("the last point is not the task's goal");
  for (std::size_t i = 0; i < path.size(); ++i)
    if (!model.withinLimits(path[i])) fail("point " + std::to_string(i) + " is outside the joint limits");
  if (closing && (closing->from == 0 || closing->from + 1 >= path.size() || !closing->rule))
    fail("the closing phase must start after the first point and before the last");
  if (!result.valid) return result;
  const auto closingCheck = [&](const Configuration& q) { return closing->rule->forbidden(checker.check(q)); };
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    const bool closingSegment = closing && i >= closing->from;
    const auto inspection = closingSegment ? segments.inspect(closingCheck, path[i], path[i + 1])
                                           : segments.inspect(checker, path[i], path[i + 1]);
    result.statesChecked += inspection.statesChecked;
    if (inspection.free) continue;
    char where[200];
    std::snprintf(where, sizeof where, "segment %zu (%zu -> %zu%s): collides at %.1f %%: ", i, i, i + 1,
                  closingSegment ? ", closing"
                  : closing      ? ", approach"
                                 : "",
                  100.0 * *inspection.firstCollision);
    fail(where + pairsText(inspection.collisions));
    addPairs(result, inspection.collisions);
  }
  std::sort(result.collisions.pairs.begin(), result.collisions.pairs.end());
  return result;
}

}  // namespace pmdplan
