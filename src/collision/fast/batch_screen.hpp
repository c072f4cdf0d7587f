#pragma once
// The fast checker's batch screen (batch_screen.cpp): the geometric stages for up to kLanes
// configurations at once on lane vectors of the chosen SIMD level, then the narrow phase and the
// exact checker for the lanes they leave open. A function of the task's model and one checker's
// scratch (checker_model.hpp, checker_scratch.hpp).
#include "pmdplan/collision/simd_level.hpp"
#include "pmdplan/model/configuration.hpp"

namespace pmdplan::fast {

class CheckerModel;
class CheckerScratch;

/// Decides configurations[0 .. count - 1], whose poses (BatchedForwardKinematics::computeBatch's
/// layout) are `poses`: valid[i], safe[i] as FastCollisionChecker::checkBatch, and with pairGaps
/// every pair's gap of every valid lane (count x pairCount values; the lane vectors then measure
/// every pair's gap as tight as they get it). With `stopAt`, the lanes are decided in order only
/// until one's verdict is *stopAt: its index is returned and the lanes after it are left
/// undecided. Otherwise (or when none is) returns count.
int screenBatch(const CheckerModel& model, CheckerScratch& scratch, SimdLevel level,
                const Configuration* const* configurations, int count, const double* poses, bool* valid, double* safe,
                double* pairGaps, const bool* stopAt = nullptr);

}  // namespace pmdplan::fast
