#include "pmdplan/collision/path_validation.hpp"

#include <algorithm>
#include <cstdio>

#include "pmdplan/core/input_error.hpp"
#include "pmdplan/core/stop_request.hpp"

namespace pmdplan {
namespace {

void addPairs(PathValidation& result, const CollisionReport& report) {
  for (const auto& pair : report.pairs)
    if (std::find(result.collisions.pairs.begin(), result.collisions.pairs.end(), pair) ==
        result.collisions.pairs.end())
      result.collisions.pairs.push_back(pair);
}

}  // namespace

long checkValidationWork(const SegmentChecker& segments, const std::vector<Configuration>& path) {
  double states = 0.0;  // intervals() is at most 10⁷ a segment; the sum is compared as a double
  for (std::size_t i = 0; i + 1 < path.size(); ++i)
    states += static_cast<double>(segments.bound().intervals(path[i], path[i + 1], segments.tolerance())) + 1.0;
  if (states > static_cast<double>(kMaxValidationStates)) {
    char text[300];
    std::snprintf(text, sizeof text,
                  "checking the %zu segments at %g mm needs %.0f states, more than the %ld pmdplan checks in one "
                  "validation; expected a shorter path or a larger --tolerance-mm",
                  path.size() - 1, segments.tolerance() * 1000.0, states, kMaxValidationStates);
    throw InputError("", "points", text);
  }
  return static_cast<long>(states);
}

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
  checkValidationWork(segments, path);
  // A stop request (core/stop_request.hpp) is looked at before every state: one segment may need
  // thousands of them.
  const auto approachCheck = [&](const Configuration& q) {
    if (stopRequested()) throw StopRequested();
    return checker.check(q);
  };
  const auto closingCheck = [&](const Configuration& q) { return closing->rule->forbidden(approachCheck(q)); };
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    const bool closingSegment = closing && i >= closing->from;
    const auto inspection = closingSegment ? segments.inspect(closingCheck, path[i], path[i + 1])
                                           : segments.inspect(approachCheck, path[i], path[i + 1]);
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
