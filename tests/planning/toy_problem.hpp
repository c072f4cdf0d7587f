#pragma once
// A small hand-arm problem with an analytic collision model, for the planner's tests.
//
// Arm: 2 joints, hand: thumb_base + 3 fingers (6 joints). In normalised units u, a wall fills the
// slab 0.45 <= u_shoulder <= 0.55; inside it a configuration is free only in the passage:
// |u_elbow - 0.5| <= 0.05, the thumb tucked (u_thumb <= 0.5), fingers a and b closed together
// (u_a + u_b <= 0.6, |u_a - u_b| <= 0.05) and finger c near its middle (|u_c - 0.5| <= 0.05).
// The start and the goal stand on either side with the hand open, so the path has to close the
// hand to get through: easy along PMD 1 (which moves a and b together), rare for uniform hand
// samples (about 1 in 700). The passage set is convex, so a straight segment is free exactly when
// the points where it enters and leaves the slab are: the motion check is exact, not sampled.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "pmdplan/collision/motion_validator.hpp"
#include "pmdplan/collision/state_validator.hpp"
#include "pmdplan/planning/planner_settings.hpp"
#include "pmdplan/planning/planning_space.hpp"
#include "pmdplan/synergy/synergy_model.hpp"

namespace pmdplan::toy {

inline PlanningSpace space() {
  PlanningSpace s;
  s.joints = {{"shoulder", -1.0, 1.0}, {"elbow", -2.0, 2.0},    {"thumb_base", 0.0, 1.5},
              {"finger_a", 0.0, 1.0},  {"finger_b", -0.5, 0.5}, {"finger_c", -0.3, 0.9}};
  s.armIndices = {0, 1};
  s.handIndices = {2, 3, 4, 5};
  return s;
}

/// Mean 0.5 everywhere, thumb base its own axis, PMD 1 closes fingers a and b together, PMD 2
/// spreads them, PMD 3 moves finger c.
inline SynergyModel synergyModel() {
  const PlanningSpace s = space();
  SynergyModel model;
  for (const int i : s.handIndices) model.joints.push_back(s.joints[static_cast<std::size_t>(i)]);
  model.mean = Eigen::VectorXd::Constant(4, 0.5);
  model.ownAxisJoints = {"thumb_base"};
  const double h = std::sqrt(0.5);
  model.directions = Eigen::MatrixXd::Zero(4, 3);
  model.directions.col(0) << 0.0, h, h, 0.0;
  model.directions.col(1) << 0.0, h, -h, 0.0;
  model.directions.col(2) << 0.0, 0.0, 0.0, 1.0;
  model.sigma = Eigen::Vector3d(0.25, 0.1, 0.05);
  model.varianceFraction = Eigen::Vector3d(0.8, 0.15, 0.05);
  return model;
}

inline Configuration fromUnit(std::initializer_list<double> unit) {
  Eigen::VectorXd u(static_cast<Eigen::Index>(unit.size()));
  Eigen::Index i = 0;
  for (const double v : unit) u[i++] = v;
  return space().denormalise(u);
}

/// The planner's defaults for `mode` with `seed` and a 60 s limit that a test's run never reaches.
inline PlannerSettings withSeed(std::uint64_t seed, HandSamplingMode mode = HandSamplingMode::Synergy) {
  PlannerSettings parameters = PlannerSettings::defaultsFor(mode);
  parameters.seed = seed;
  parameters.timeLimit = 60.0;
  return parameters;
}

inline Configuration start() { return fromUnit({0.1, 0.5, 0.3, 0.8, 0.8, 0.5}); }
inline Configuration goal() { return fromUnit({0.9, 0.5, 0.3, 0.9, 0.7, 0.5}); }

/// The wall and its passage (or, with `passageOpen` false, a wall nothing gets through).
struct Wall {
  bool passageOpen = true;

  bool inSlab(const Eigen::VectorXd& u) const { return u[0] >= 0.45 && u[0] <= 0.55; }
  bool inPassage(const Eigen::VectorXd& u) const {
    return passageOpen && std::abs(u[1] - 0.5) <= 0.05 && u[2] <= 0.5 && u[3] + u[4] <= 0.6 &&
           std::abs(u[3] - u[4]) <= 0.05 && std::abs(u[5] - 0.5) <= 0.05;
  }
  bool armFree(const Eigen::VectorXd& u) const { return u[1] <= 0.95; }
  bool free(const Eigen::VectorXd& u) const { return armFree(u) && (!inSlab(u) || inPassage(u)); }
};

class WallStateValidator : public StateValidator {
 public:
  explicit WallStateValidator(Wall wall = {}) : wall_(wall), space_(space()) {}
  bool isValid(const Configuration& q) override {
    ++checks_;
    return wall_.free(space_.normalise(q));
  }
  bool isArmValid(const Configuration& q) override {
    ++checks_;
    return wall_.armFree(space_.normalise(q));
  }
  std::size_t checkCount() const override { return checks_; }

 private:
  Wall wall_;
  PlanningSpace space_;
  std::size_t checks_ = 0;
};

class WallMotionValidator : public MotionValidator {
 public:
  explicit WallMotionValidator(Wall wall = {}) : wall_(wall), space_(space()) {}
  bool isValid(const Configuration& from, const Configuration& to) override {
    ++calls_;
    states_ += 2;
    const Eigen::VectorXd a = space_.normalise(from);
    const Eigen::VectorXd b = space_.normalise(to);
    if (!wall_.free(a) || !wall_.free(b)) return false;
    const double d = b[0] - a[0];
    double tEnter = 0.0;
    double tLeave = 1.0;
    if (d == 0.0) {
      if (!wall_.inSlab(a)) return true;
    } else {
      tEnter = (0.45 - a[0]) / d;
      tLeave = (0.55 - a[0]) / d;
      if (tEnter > tLeave) std::swap(tEnter, tLeave);
      tEnter = std::max(tEnter, 0.0);
      tLeave = std::min(tLeave, 1.0);
      if (tEnter > tLeave) return true;
    }
    // Convex passage, straight segment: free inside the slab iff free where it enters and leaves.
    return wall_.inPassage(a + tEnter * (b - a)) && wall_.inPassage(a + tLeave * (b - a));
  }
  std::size_t statesChecked() const override { return states_; }
  std::size_t calls() const { return calls_; }

 private:
  Wall wall_;
  PlanningSpace space_;
  std::size_t calls_ = 0;
  std::size_t states_ = 0;
};

/// An independent check of a path: every segment sampled every 1e-4 (normalised) with the state
/// test alone.
inline bool densePathIsFree(const std::vector<Configuration>& path, Wall wall = {}) {
  const PlanningSpace s = space();
  for (std::size_t k = 0; k + 1 < path.size(); ++k) {
    const Eigen::VectorXd a = s.normalise(path[k]);
    const Eigen::VectorXd b = s.normalise(path[k + 1]);
    const int n = std::max(1, static_cast<int>(std::ceil((b - a).norm() / 1e-4)));
    for (int i = 0; i <= n; ++i)
      if (!wall.free(a + (static_cast<double>(i) / n) * (b - a))) return false;
  }
  return true;
}

}  // namespace pmdplan::toy
