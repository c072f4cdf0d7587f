#pragma once
// The fast checker's narrow phase, one configuration (a lane of posed links) at a time
// (narrow_phase.cpp): link against link or obstacle, part against part, each first by the bounding
// spheres, the parts placed in the world on first use; and the exact checker on the pairs it
// leaves. Functions of the task's model and one checker's scratch (checker_model.hpp,
// checker_scratch.hpp), shared by the scalar screen, the batch screen and the pair tests.
#include <cmath>
#include <cstddef>

#include "pair_outcome.hpp"
#include "pmdplan/model/configuration.hpp"

namespace pmdplan::fast {

class CheckerModel;
class CheckerScratch;

/// Distance between two spheres' surfaces (negative when they overlap).
inline double sphereSphereGap(const double* a, double ra, const double* b, double rb) {
  const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
  return std::sqrt(dx * dx + dy * dy + dz * dz) - ra - rb;
}

/// Starts on lane `lane` of poses laid out with `stride` lanes ([(link * 12 + value) * stride +
/// lane]): no link placed yet.
void beginLane(const CheckerModel& model, CheckerScratch& scratch, const double* poses, int stride, int lane);
/// Places the link's bounding sphere centre (LaneScratch::boundX, ...).
void placeBound(const CheckerModel& model, CheckerScratch& scratch, int link);
/// Links a and b (a's parts against b's bound, then part against part); on Apart, gap is a lower
/// bound on their gap. Reads b's placed bound.
Outcome linkPairContact(const CheckerModel& model, CheckerScratch& scratch, int a, int b, double& gap);
/// The link against obstacle o; on Apart, gap is a lower bound on their gap.
Outcome linkObstacleContact(const CheckerModel& model, CheckerScratch& scratch, int link, std::size_t o, double& gap);
/// The exact checker on the pairs in CheckerScratch::uncertain at q (mesh enclosures first): is q
/// free? Counts them in the statistics.
bool confirmUncertain(const CheckerModel& model, CheckerScratch& scratch, const Configuration& q);

}  // namespace pmdplan::fast
