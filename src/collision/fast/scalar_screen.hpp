#pragma once
// The fast checker's scalar screen (scalar_screen.cpp): the geometric stages for one
// configuration, then the exact checker for the pairs they leave. Functions of the task's model
// and one checker's scratch (checker_model.hpp, checker_scratch.hpp).
#include "pmdplan/collision/fast/screen_result.hpp"
#include "pmdplan/model/configuration.hpp"

namespace pmdplan::fast {

class CheckerModel;
class CheckerScratch;

/// Is q free? Its poses are lane `lane` of `poses`, laid out with `stride` lanes. With
/// safeDisplacement, the safe value when the geometric stages alone proved it free (else 0); with
/// pairGaps, every pair's gap (0 for a pair not proven apart). Counts the verdict's kind.
bool decide(const CheckerModel& model, CheckerScratch& scratch, const Configuration& q, const double* poses, int stride,
            int lane, bool armOnly, double* safeDisplacement, double* pairGaps = nullptr);

/// The geometric stages alone at q, every pair not proven apart listed (no exact checks).
ScreenResult screen(const CheckerModel& model, CheckerScratch& scratch, const Configuration& q, bool armOnly);

}  // namespace pmdplan::fast
