#include "pmdplan/collision/fast/fast_collision_checker.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "batch_screen.hpp"
#include "checker_model.hpp"
#include "checker_scratch.hpp"
#include "scalar_screen.hpp"

namespace pmdplan {
namespace {

std::unique_ptr<fast::CheckerScratch> scratchFor(const std::shared_ptr<const fast::CheckerModel>& model,
                                                 const ExactCollisionChecker& exact) {
  if (!model) throw std::invalid_argument("the fast checker needs a model");
  if (!model->fits(exact)) throw std::invalid_argument("the exact checker does not fit the fast checker's model");
  return std::make_unique<fast::CheckerScratch>(*model, exact);
}

}  // namespace

FastCollisionChecker::FastCollisionChecker(const Task& task, ExactCollisionChecker& exact, double band)
    : model_(std::make_shared<const fast::CheckerModel>(task, exact, band)),
      scratch_(std::make_unique<fast::CheckerScratch>(*model_, exact)),
      simdLevel_(widestSimdLevel()),
      pairs_(*model_, *scratch_) {}

FastCollisionChecker::FastCollisionChecker(std::shared_ptr<const fast::CheckerModel> model,
                                           ExactCollisionChecker& exact)
    : model_(std::move(model)),
      scratch_(scratchFor(model_, exact)),
      simdLevel_(widestSimdLevel()),
      pairs_(*model_, *scratch_) {}

FastCollisionChecker::~FastCollisionChecker() = default;

SimdLevel FastCollisionChecker::simdLevel() const { return simdLevel_; }

void FastCollisionChecker::setSimdLevel(SimdLevel level) {
  const bool known = level == SimdLevel::sse2 || level == SimdLevel::avx2 || level == SimdLevel::avx512;
  if (!known || laneWidth(level) > laneWidth(widestSimdLevel()))
    throw std::invalid_argument(std::string("SIMD level ") + (known ? simdLevelName(level) : "unknown") +
                                ": this CPU runs sse2 to " + simdLevelName(widestSimdLevel()));
  simdLevel_ = level;
}

namespace {

/// The batch's joint values into the kinematics' lanes (spare lanes repeat the last configuration),
/// then its forward kinematics into the scratch's poses.
void loadLanes(const fast::CheckerModel& model, fast::CheckerScratch& scratch,
               const Configuration* const* configurations, int count) {
  const int dof = model.dof();
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
  model.kinematics().computeBatch(q, scratch.poses());
}

/// isValid / isArmValid, and a lone state of checkBatch: one configuration through the scalar
/// screen.
bool checkOne(const fast::CheckerModel& model, fast::CheckerScratch& scratch, const Configuration& q, bool armOnly,
              double* safeDisplacement = nullptr, double* pairGaps = nullptr) {
  if (q.size() != model.dof()) throw std::invalid_argument("configuration size does not match the robot");
  model.kinematics().computeOne(q.data(), scratch.poses());
  return fast::decide(model, scratch, q, scratch.poses(), 1, 0, armOnly, safeDisplacement, pairGaps);
}

}  // namespace

bool FastCollisionChecker::isValid(const Configuration& q) {
  ++checks_;
  return checkOne(*model_, *scratch_, q, false);
}

bool FastCollisionChecker::isArmValid(const Configuration& q) {
  ++checks_;
  return checkOne(*model_, *scratch_, q, true);
}

void FastCollisionChecker::checkBatch(const Configuration* const* configurations, int count, bool* valid,
                                      double* safeDisplacement, double* pairGaps) {
  if (count < 1 || count > kLanes) throw std::invalid_argument("checkBatch: 1 to kLanes configurations");
  if (count == 1) {  // a lone state: the single-lane kinematics is cheaper than a padded batch
    if (configurations[0]->size() != model_->dof())
      throw std::invalid_argument("configuration size does not match the robot");
    ++checks_;
    valid[0] = checkOne(*model_, *scratch_, *configurations[0], false, &safeDisplacement[0], pairGaps);
    return;
  }
  loadLanes(*model_, *scratch_, configurations, count);
  checks_ += static_cast<std::size_t>(count);
  fast::screenBatch(*model_, *scratch_, simdLevel_, configurations, count, scratch_->poses(), valid, safeDisplacement,
                    pairGaps);
}

std::size_t FastCollisionChecker::checkCount() const { return checks_; }

int FastCollisionChecker::firstWithValidity(const Configuration* const* configurations, int count, bool wanted) {
  bool valid[kLanes];
  double safe[kLanes];
  for (int first = 0; first < count; first += kLanes) {
    const int batch = std::min(kLanes, count - first);
    if (batch == 1) {
      checkBatch(configurations + first, 1, valid, safe);
      if (valid[0] == wanted) return first;
      continue;
    }
    loadLanes(*model_, *scratch_, configurations + first, batch);
    checks_ += static_cast<std::size_t>(batch);
    const int found = fast::screenBatch(*model_, *scratch_, simdLevel_, configurations + first, batch,
                                        scratch_->poses(), valid, safe, nullptr, &wanted);
    if (found < batch) return first + found;
  }
  return count;
}

void FastCollisionChecker::setMotion(const Configuration& from, const Configuration& to) {
  fast::MotionShares& shares = scratch_->shares();
  model_->motionWeights().motionShares(from, to, shares.pair, shares.link);
}

ScreenResult FastCollisionChecker::screen(const Configuration& q, bool armOnly) {
  return fast::screen(*model_, *scratch_, q, armOnly);
}

const FastCheckStatistics& FastCollisionChecker::statistics() const { return scratch_->statistics(); }
const std::vector<LinkParts>& FastCollisionChecker::links() const { return model_->links(); }
const ExactCollisionChecker& FastCollisionChecker::exact() const { return scratch_->exact(); }
double FastCollisionChecker::band() const { return model_->band(); }

}  // namespace pmdplan
