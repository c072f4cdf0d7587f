#include "pmdplan/collision/fast/fast_collision_checker.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "checker_state.hpp"

namespace pmdplan {

FastCollisionChecker::FastCollisionChecker(const Task& task, ExactCollisionChecker& exact, double band)
    : state_(std::make_unique<fast::CheckerState>(task, exact, band)), pairs_(*state_) {}

FastCollisionChecker::~FastCollisionChecker() = default;

SimdLevel FastCollisionChecker::simdLevel() const { return state_->simdLevel_; }

void FastCollisionChecker::setSimdLevel(SimdLevel level) {
  const bool known = level == SimdLevel::sse2 || level == SimdLevel::avx2 || level == SimdLevel::avx512;
  if (!known || laneWidth(level) > laneWidth(widestSimdLevel()))
    throw std::invalid_argument(std::string("SIMD level ") + (known ? simdLevelName(level) : "unknown") +
                                ": this CPU runs sse2 to " + simdLevelName(widestSimdLevel()));
  state_->simdLevel_ = level;
}

namespace {

/// The batch's joint values into the kinematics' lanes (spare lanes repeat the last configuration),
/// then its forward kinematics into the pose scratch.
void loadLanes(fast::CheckerState& s, const Configuration* const* configurations, int count) {
  const int dof = s.kinematics_.dof();
  double joints[64 * FastCollisionChecker::kLanes];
  std::vector<double> wide;
  double* q = joints;
  if (dof > 64) {
    wide.resize(static_cast<std::size_t>(dof) * FastCollisionChecker::kLanes);
    q = wide.data();
  }
  for (int lane = 0; lane < FastCollisionChecker::kLanes; ++lane) {
    const Configuration& c = *configurations[std::min(lane, count - 1)];
    if (c.size() != dof) throw std::invalid_argument("configuration size does not match the robot");
    for (int i = 0; i < dof; ++i) q[i * FastCollisionChecker::kLanes + lane] = c[i];
  }
  s.kinematics_.computeBatch(q, s.poseScratch_.data());
}

/// isValid / isArmValid: one configuration through the scalar screen.
bool checkOne(fast::CheckerState& s, const Configuration& q, bool armOnly) {
  ++s.checks_;
  if (q.size() != s.kinematics_.dof()) throw std::invalid_argument("configuration size does not match the robot");
  s.kinematics_.computeOne(q.data(), s.poseScratch_.data());
  return s.decide(q, s.poseScratch_.data(), 1, 0, armOnly, nullptr);
}

}  // namespace

bool FastCollisionChecker::isValid(const Configuration& q) { return checkOne(*state_, q, false); }

bool FastCollisionChecker::isArmValid(const Configuration& q) { return checkOne(*state_, q, true); }

void FastCollisionChecker::checkBatch(const Configuration* const* configurations, int count, bool* valid,
                                      double* safeDisplacement, double* pairGaps) {
  fast::CheckerState& s = *state_;
  if (count < 1 || count > kLanes) throw std::invalid_argument("checkBatch: 1 to kLanes configurations");
  const int dof = s.kinematics_.dof();
  if (count == 1) {  // a lone state: the single-lane kinematics is cheaper than a padded batch
    if (configurations[0]->size() != dof) throw std::invalid_argument("configuration size does not match the robot");
    ++s.checks_;
    s.kinematics_.computeOne(configurations[0]->data(), s.poseScratch_.data());
    valid[0] = s.decide(*configurations[0], s.poseScratch_.data(), 1, 0, false, &safeDisplacement[0], pairGaps);
    return;
  }
  loadLanes(s, configurations, count);
  s.checks_ += static_cast<std::size_t>(count);
  s.screenBatch(configurations, count, s.poseScratch_.data(), valid, safeDisplacement, pairGaps);
}

std::size_t FastCollisionChecker::checkCount() const { return state_->checks_; }

int FastCollisionChecker::firstWithValidity(const Configuration* const* configurations, int count, bool wanted) {
  fast::CheckerState& s = *state_;
  bool valid[kLanes];
  double safe[kLanes];
  for (int first = 0; first < count; first += kLanes) {
    const int batch = std::min(kLanes, count - first);
    if (batch == 1) {
      checkBatch(configurations + first, 1, valid, safe);
      if (valid[0] == wanted) return first;
      continue;
    }
    loadLanes(s, configurations + first, batch);
    s.checks_ += static_cast<std::size_t>(batch);
    const int found =
        s.screenBatch(configurations + first, batch, s.poseScratch_.data(), valid, safe, nullptr, &wanted);
    if (found < batch) return first + found;
  }
  return count;
}

void FastCollisionChecker::setMotion(const Configuration& from, const Configuration& to) {
  state_->setMotion(from, to);
}

ScreenResult FastCollisionChecker::screen(const Configuration& q, bool armOnly) { return state_->screen(q, armOnly); }

const FastCheckStatistics& FastCollisionChecker::statistics() const { return state_->statistics_; }
const std::vector<LinkParts>& FastCollisionChecker::links() const { return state_->links_; }
const ExactCollisionChecker& FastCollisionChecker::exact() const { return state_->exact_; }
double FastCollisionChecker::band() const { return state_->band_; }

}  // namespace pmdplan
