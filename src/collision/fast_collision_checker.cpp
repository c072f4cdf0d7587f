#include "pmdplan/collision/fast_collision_checker.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <tuple>

#include "pmdplan/collision/convex_distance.hpp"

namespace pmdplan {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr int kValues = BatchedForwardKinematics::kPoseValues;

/// Links that no joint moves: reached from the root through fixed joints only.
std::vector<char> movingLinks(const RobotModel& model) {
  std::vector<char> moving(model.links().size(), 0);
  for (int j : model.jointOrder()) {
    const Joint& joint = model.joints()[static_cast<std::size_t>(j)];
    moving[static_cast<std::size_t>(joint.childLink)] =
        moving[static_cast<std::size_t>(joint.parentLink)] || joint.type != JointType::Fixed;
  }
  return moving;
}

double sphereSphereGap(const double* a, double ra, const double* b, double rb) {
  const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
  return std::sqrt(dx * dx + dy * dy + dz * dz) - ra - rb;
}

/// Joints from the root to `link` (indices into joints()), root first.
std::vector<int> jointChain(const RobotModel& model, int link) {
  std::vector<int> chain;
  for (int l = link; model.links()[static_cast<std::size_t>(l)].parentJoint >= 0;) {
    const int j = model.links()[static_cast<std::size_t>(l)].parentJoint;
    chain.insert(chain.begin(), j);
    l = model.joints()[static_cast<std::size_t>(j)].parentLink;
  }
  return chain;
}

}  // namespace

FastCollisionChecker::FastCollisionChecker(const Task& task, ExactCollisionChecker& exact, double band)
    : exact_(exact),
      band_(band),
      links_(linkParts(*task.robot)),
      obstacles_(obstacleParts(task.obstacles)),
      kinematics_(*task.robot, task.base),
      moving_(movingLinks(*task.robot)) {
  if (&exact.model() != task.robot.get()) throw std::invalid_argument("the exact checker belongs to another task");
  if (!(band > 0.0)) throw std::invalid_argument("the fast checker's band must be positive");
  const std::size_t n = links_.size();
  for (std::size_t l = 0; l < n; ++l) {
    partOffset_.push_back(static_cast<int>(worldParts_.size()));
    worldParts_.resize(worldParts_.size() + links_[l].parts.size());
    if (!links_[l].empty()) boundLinks_.push_back(static_cast<int>(l));
  }
  orderGeometricLinks(*task.robot);
  placed_.assign(n, 0);
  boundPlaced_.assign(n, 0);
  partPlaced_.assign(worldParts_.size(), 0);
  linkPoses_.assign(n * kValues, 0.0);
  boundX_.assign(n, 0.0), boundY_ = boundZ_ = boundX_;
  geometricX_.assign(geometricLinks_.size(), 0.0), geometricY_ = geometricZ_ = geometricX_;
  obstacleGaps_.assign(geometricLinks_.size() * obstacles_.size(), 0.0);
  poseScratch_.resize(kinematics_.batchPoseSize());

  // Pairs no joint moves are decided once, by the exact checker itself (their poses never change).
  exact.kinematics().linkPoses(Configuration::Zero(task.robot->dof()), exactPoses_);
  for (const auto& [a, b] : exact.selfPairs()) {
    const auto ua = static_cast<std::size_t>(a), ub = static_cast<std::size_t>(b);
    if (moving_[ua] || moving_[ub]) {
      selfPairs_.emplace_back(a, b);
      pairIsArm_.push_back(exact.isArmLink(a) && exact.isArmLink(b));
      pairA_.push_back(a);
      pairB_.push_back(b);
      pairRadiusSum_.push_back(links_[ua].boundRadius + links_[ub].boundRadius);
      pairShare_.push_back(1.0 / (moving_[ua] + moving_[ub]));
    } else if (exact.linkPairCollides(exactPoses_, a, b)) {
      staticSelfCollisions_.emplace_back(a, b);
      if (exact.isArmLink(a) && exact.isArmLink(b)) staticArmSelfCollisions_.emplace_back(a, b);
    }
  }
  pairGaps_.assign(selfPairs_.size(), 0.0);
  pairDx_ = pairDy_ = pairDz_ = pairGaps_;
  linkShare_.assign(geometricLinks_.size(), 1.0);
  computeMotionWeights(*task.robot);
  for (std::size_t p = 0; p < pairCount(); ++p) {
    auto links = kinematics_.emptyLinkSet();
    if (p < selfPairs_.size()) {
      const auto [a, b] = selfPairs_[p];
      kinematics_.addWithAncestors(links, a);
      kinematics_.addWithAncestors(links, b);
      const int frame = kinematics_.commonAncestor(a, b);
      auto above = kinematics_.emptyLinkSet(), relative = links;
      kinematics_.addWithAncestors(above, frame);
      for (std::size_t w = 0; w < relative.size(); ++w) relative[w] &= ~above[w];
      pairFrame_.push_back(frame);
      pairRelativeLinks_.push_back(std::move(relative));
    } else {
      kinematics_.addWithAncestors(links, geometricLinks_[(p - selfPairs_.size()) % geometricLinks_.size()]);
    }
    pairLinks_.push_back(std::move(links));
  }
  posedLinks_ = kinematics_.emptyLinkSet();
  prepareLanes();

  for (std::size_t l = 0; l < n; ++l)
    if (!moving_[l] && !links_[l].empty())
      for (std::size_t o = 0; o < obstacles_.size(); ++o)
        if (exact.linkObstacleCollides(exactPoses_, static_cast<int>(l), o))
          staticEnvironmentCollisions_.emplace_back(static_cast<int>(l), o);
}

// The moving links with geometry in depth-first order, so that every link's geometric
// descendants follow it in one run (the batch screen tests a whole subtree against an obstacle
// first).
void FastCollisionChecker::orderGeometricLinks(const RobotModel& model) {
  std::vector<std::vector<int>> children(model.links().size());
  for (int j : model.jointOrder()) {
    const Joint& joint = model.joints()[static_cast<std::size_t>(j)];
    children[static_cast<std::size_t>(joint.parentLink)].push_back(joint.childLink);
  }
  const auto visit = [&](const auto& self, int link, int parent) -> void {
    const auto l = static_cast<std::size_t>(link);
    const bool geometric = moving_[l] && !links_[l].empty();
    const int position = static_cast<int>(geometricLinks_.size());
    if (geometric) {
      geometricLinks_.push_back(link);
      geometricBoundR_.push_back(links_[l].boundRadius);
      geometricParent_.push_back(parent);
      geometricSubtreeEnd_.push_back(0);
    }
    for (int child : children[l]) self(self, child, geometric ? position : parent);
    if (geometric) geometricSubtreeEnd_[static_cast<std::size_t>(position)] = static_cast<int>(geometricLinks_.size());
  };
  visit(visit, model.rootLink(), -1);
}

const ConvexPart* FastCollisionChecker::placedBounds(int link) {
  const auto l = static_cast<std::size_t>(link);
  ConvexPart* world = worldParts_.data() + partOffset_[l];
  if (placed_[l]) return world;
  double* pose = linkPoses_.data() + l * kValues;
  for (int i = 0; i < kValues; ++i) pose[i] = lanePoses_[(link * kValues + i) * laneStride_ + lane_];
  const auto& local = links_[l].parts;
  for (std::size_t p = 0; p < local.size(); ++p) {
    const double* c = local[p].boundCentre;
    double* w = world[p].boundCentre;
    for (int r = 0; r < 3; ++r)
      w[r] = pose[r * 3] * c[0] + pose[r * 3 + 1] * c[1] + pose[r * 3 + 2] * c[2] + pose[9 + r];
    world[p].boundRadius = local[p].boundRadius;
    partPlaced_[static_cast<std::size_t>(partOffset_[l]) + p] = 0;
  }
  placed_[l] = 1;
  return world;
}

const ConvexPart& FastCollisionChecker::placedPart(int link, std::size_t index) {
  const auto l = static_cast<std::size_t>(link);
  const std::size_t k = static_cast<std::size_t>(partOffset_[l]) + index;
  if (!partPlaced_[k]) {
    placePart(links_[l].parts[index], linkPoses_.data() + l * kValues, worldParts_[k]);
    partPlaced_[k] = 1;
  }
  return worldParts_[k];
}

// Part against part; a part first against the other link's bound, each part pair first by its
// bounding spheres. Overlapping as soon as one part pair overlaps; Uncertain if one is too close
// to call and none overlaps; else Apart with the smallest gap.
FastCollisionChecker::Outcome FastCollisionChecker::linkPairContact(int a, int b, double& gap) {
  const ConvexPart* partsA = placedBounds(a);
  const ConvexPart* partsB = placedBounds(b);
  const std::size_t na = links_[static_cast<std::size_t>(a)].parts.size(),
                    nb = links_[static_cast<std::size_t>(b)].parts.size();
  const double boundB[3] = {boundX_[static_cast<std::size_t>(b)], boundY_[static_cast<std::size_t>(b)],
                            boundZ_[static_cast<std::size_t>(b)]};
  const double boundRadiusB = links_[static_cast<std::size_t>(b)].boundRadius;
  bool uncertain = false, enclosures = false;
  gap = kInfinity;
  for (std::size_t i = 0; i < na; ++i) {
    const ConvexPart& pa = partsA[i];
    const double toLink = sphereSphereGap(pa.boundCentre, pa.boundRadius, boundB, boundRadiusB);
    if (toLink > band_) {
      gap = std::min(gap, toLink);
      continue;
    }
    for (std::size_t j = 0; j < nb; ++j) {
      const ConvexPart& pb = partsB[j];
      const double bounds = sphereSphereGap(pa.boundCentre, pa.boundRadius, pb.boundCentre, pb.boundRadius);
      if (bounds > band_) {
        gap = std::min(gap, bounds);
        continue;
      }
      const ConvexPart &worldA = placedPart(a, i), &worldB = placedPart(b, j);
      const PartContact contact = partContact(worldA, worldB, band_);
      if (contact.contact == Contact::Apart) {
        gap = std::min(gap, contact.gap);
        continue;
      }
      // A mesh's enclosure overlapping a part says nothing about the mesh itself (but FCL is
      // asked about such pairs first).
      if (contact.contact == Contact::Overlapping) {
        if (!worldA.enclosure && !worldB.enclosure) return Outcome::Overlapping;
        enclosures = true;
      }
      uncertain = true;
    }
  }
  return enclosures ? Outcome::EnclosuresOverlap : uncertain ? Outcome::Uncertain : Outcome::Apart;
}

FastCollisionChecker::Outcome FastCollisionChecker::linkObstacleContact(int link, std::size_t o, double& gap) {
  const ConvexPart* parts = placedBounds(link);
  const std::size_t count = links_[static_cast<std::size_t>(link)].parts.size();
  const ObstaclePart& obstacle = obstacles_[o];
  bool uncertain = false, enclosures = false;
  gap = kInfinity;
  for (std::size_t i = 0; i < count; ++i) {
    const double bound = sphereGap(obstacle.part, parts[i].boundCentre, parts[i].boundRadius);
    if (bound > band_) {
      gap = std::min(gap, bound);
      continue;
    }
    const ConvexPart& part = placedPart(link, i);
    const PartContact contact = partContact(part, obstacle.part, band_);
    if (contact.contact == Contact::Apart) {
      gap = std::min(gap, contact.gap);
      continue;
    }
    // A mesh's enclosure overlapping a part says nothing about the mesh itself.
    if (contact.contact == Contact::Overlapping) {
      if (obstacle.exact && !part.enclosure) return Outcome::Overlapping;
      enclosures = true;
    }
    uncertain = true;
  }
  return enclosures ? Outcome::EnclosuresOverlap : uncertain ? Outcome::Uncertain : Outcome::Apart;
}

void FastCollisionChecker::beginLane(const double* poses, int stride, int lane) {
  lanePoses_ = poses, laneStride_ = stride, lane_ = lane;
  std::fill(placed_.begin(), placed_.end(), 0);
  std::fill(boundPlaced_.begin(), boundPlaced_.end(), 0);
}

void FastCollisionChecker::placeBound(int link) {
  const auto ul = static_cast<std::size_t>(link);
  const double* c = links_[ul].boundCentre;
  double m[kValues];
  for (int i = 0; i < kValues; ++i) m[i] = lanePoses_[(link * kValues + i) * laneStride_ + lane_];
  boundX_[ul] = m[0] * c[0] + m[1] * c[1] + m[2] * c[2] + m[9];
  boundY_[ul] = m[3] * c[0] + m[4] * c[1] + m[5] * c[2] + m[10];
  boundZ_[ul] = m[6] * c[0] + m[7] * c[1] + m[8] * c[2] + m[11];
  boundPlaced_[ul] = 1;
}

// The geometric stages of one configuration (lane `lane` of poses laid out with `stride` lanes).
// onFlag(Flag) is called for every pair not proven apart and returns true to stop. Returns the
// safe displacement (see ScreenResult) when every pair was proven apart, 0 when some were
// flagged, -1 when stopped. With pairGaps, every pair's gap is written there (0 when flagged).
template <class OnFlag>
double FastCollisionChecker::screenLane(const double* poses, int stride, int lane, bool armOnly, OnFlag&& onFlag,
                                        double* pairGaps) {
  beginLane(poses, stride, lane);
  for (int l : boundLinks_) placeBound(l);
  double safe = kInfinity;
  bool flagged = false;

  // Self: the link bounds of every pair in one branch-free pass (it vectorises), then the pairs
  // whose bounds come within the band, part by part.
  const std::size_t selfCount = selfPairs_.size();
  {
    const int* pa = pairA_.data();
    const int* pb = pairB_.data();
    const double *bx = boundX_.data(), *by = boundY_.data(), *bz = boundZ_.data();
    double* __restrict dx = pairDx_.data();
    double* __restrict dy = pairDy_.data();
    double* __restrict dz = pairDz_.data();
    for (std::size_t p = 0; p < selfCount; ++p)  // gathers
      dx[p] = bx[pa[p]] - bx[pb[p]], dy[p] = by[pa[p]] - by[pb[p]], dz[p] = bz[pa[p]] - bz[pb[p]];
    const double* sum = pairRadiusSum_.data();
    double* __restrict gaps = pairGaps_.data();
    for (std::size_t p = 0; p < selfCount; ++p)
      gaps[p] = std::sqrt(dx[p] * dx[p] + dy[p] * dy[p] + dz[p] * dz[p]) - sum[p];
  }
  for (std::size_t p = 0; p < selfCount; ++p) {
    if (armOnly && !pairIsArm_[p]) continue;
    double gap = pairGaps_[p];
    if (!(gap > band_)) {
      const auto [a, b] = selfPairs_[p];
      const Outcome outcome = linkPairContact(a, b, gap);
      if (outcome != Outcome::Apart) {
        flagged = true;
        if (pairGaps) pairGaps[p] = 0.0;
        if (onFlag(Flag{true, a, b, outcome})) return -1.0;
        continue;
      }
    }
    if (pairGaps) pairGaps[p] = gap;
    safe = std::min(safe, gap * pairShare_[p]);
  }
  if (armOnly) return flagged ? 0.0 : safe;

  // Environment: every moving link against every obstacle (static links were decided once), the
  // link bounds first in one pass per obstacle.
  const std::size_t linkCount = geometricLinks_.size();
  for (std::size_t i = 0; i < linkCount; ++i) {
    const auto l = static_cast<std::size_t>(geometricLinks_[i]);
    geometricX_[i] = boundX_[l], geometricY_[i] = boundY_[l], geometricZ_[i] = boundZ_[l];
  }
  for (std::size_t o = 0; o < obstacles_.size(); ++o)
    sphereGaps(obstacles_[o].part, geometricX_.data(), geometricY_.data(), geometricZ_.data(), geometricBoundR_.data(),
               static_cast<int>(linkCount), obstacleGaps_.data() + o * linkCount);
  for (std::size_t o = 0; o < obstacles_.size(); ++o) {
    const double* gaps = obstacleGaps_.data() + o * linkCount;
    for (std::size_t i = 0; i < linkCount; ++i) {
      double gap = gaps[i];
      if (!(gap > band_)) {
        const int l = geometricLinks_[i];
        const Outcome outcome = linkObstacleContact(l, o, gap);
        if (outcome != Outcome::Apart) {
          flagged = true;
          if (pairGaps) pairGaps[selfCount + o * linkCount + i] = 0.0;
          if (onFlag(Flag{false, l, static_cast<int>(o), outcome})) return -1.0;
          continue;
        }
      }
      if (pairGaps) pairGaps[selfCount + o * linkCount + i] = gap;
      safe = std::min(safe, gap * linkShare_[i]);
    }
  }
  return flagged ? 0.0 : safe;
}

// How far a point of a link can move per unit of each active joint: for every moving joint on its
// chain, the distance from the joint origin to the farthest point of the link's geometry in any
// configuration (the joint offsets down the chain plus the shapes' reach: triangle inequality),
// as SweptDistanceBound does for the whole robot. Mimic joints are charged to their source. For a
// pair of links only the joints below their common ancestor count: the joints above move both
// links rigidly together and do not change their distance.
void FastCollisionChecker::computeMotionWeights(const RobotModel& model) {
  const auto dof = static_cast<std::size_t>(model.dof());
  const auto weightsOf = [&](int link, const std::vector<int>& exclude) {
    std::vector<double> w(dof, 0.0);
    double shapeReach = 0.0;
    for (const auto& placed : model.links()[static_cast<std::size_t>(link)].collisionShapes)
      shapeReach = std::max(shapeReach, placed.pose.translation().norm() + boundingRadius(placed.shape));
    const auto chain = jointChain(model, link);
    for (std::size_t k = 0; k < chain.size(); ++k) {
      const Joint& joint = model.joints()[static_cast<std::size_t>(chain[k])];
      if (joint.type == JointType::Fixed || std::find(exclude.begin(), exclude.end(), chain[k]) != exclude.end())
        continue;
      double reach = shapeReach;
      for (std::size_t below = k + 1; below < chain.size(); ++below)
        reach += model.joints()[static_cast<std::size_t>(chain[below])].origin.translation().norm();
      if (joint.type == JointType::Prismatic) reach = 1.0;
      if (joint.activeIndex >= 0)
        w[static_cast<std::size_t>(joint.activeIndex)] += reach;
      else if (joint.mimicSource >= 0) {
        const int source = model.joints()[static_cast<std::size_t>(joint.mimicSource)].activeIndex;
        if (source >= 0) w[static_cast<std::size_t>(source)] += std::abs(joint.mimicMultiplier) * reach;
      }
    }
    return w;
  };
  linkWeights_.clear();
  for (int l : geometricLinks_) {
    const auto w = weightsOf(l, {});
    linkWeights_.insert(linkWeights_.end(), w.begin(), w.end());
  }
  pairWeights_.clear();
  for (const auto& [a, b] : selfPairs_) {
    const auto chainA = jointChain(model, a), chainB = jointChain(model, b);
    std::vector<int> common;
    for (std::size_t k = 0; k < chainA.size() && k < chainB.size() && chainA[k] == chainB[k]; ++k)
      common.push_back(chainA[k]);
    const auto wa = weightsOf(a, common), wb = weightsOf(b, common);
    for (std::size_t i = 0; i < dof; ++i) pairWeights_.push_back(wa[i] + wb[i]);
  }
}

void FastCollisionChecker::setMotion(const Configuration& from, const Configuration& to) {
  const auto dof = static_cast<std::size_t>(kinematics_.dof());
  std::vector<double> delta(dof);
  for (std::size_t i = 0; i < dof; ++i)
    delta[i] = std::abs(to[static_cast<Eigen::Index>(i)] - from[static_cast<Eigen::Index>(i)]);
  // Shares are 1 / (distance moved over the whole segment), rounded up by a relative 1e-9 so
  // rounding never makes a gap look safer than it is.
  const auto share = [&](const double* w) {
    double rate = 0.0;
    for (std::size_t i = 0; i < dof; ++i) rate += w[i] * delta[i];
    return 1.0 / (rate * (1.0 + 1e-9));
  };
  for (std::size_t p = 0; p < selfPairs_.size(); ++p) pairShare_[p] = share(pairWeights_.data() + p * dof);
  for (std::size_t i = 0; i < geometricLinks_.size(); ++i) linkShare_[i] = share(linkWeights_.data() + i * dof);
}

bool FastCollisionChecker::decide(const Configuration& q, const double* poses, int stride, int lane, bool armOnly,
                                  double* safeDisplacement, double* pairGaps) {
  if (safeDisplacement) *safeDisplacement = 0.0;
  if (armOnly ? !staticArmSelfCollisions_.empty()
              : !(staticSelfCollisions_.empty() && staticEnvironmentCollisions_.empty())) {
    ++statistics_.provenColliding;
    return false;
  }
  // Proven overlaps stop at once; uncertain pairs wait, since a proven overlap may still come.
  uncertain_.clear();
  const double safe = screenLane(
      poses, stride, lane, armOnly,
      [&](const Flag& flag) {
        if (flag.outcome == Outcome::Overlapping) return true;
        uncertain_.push_back(flag);
        return false;
      },
      pairGaps);
  if (safe < 0.0) {
    ++statistics_.provenColliding;
    return false;
  }
  if (uncertain_.empty()) {
    ++statistics_.provenFree;
    if (safeDisplacement) *safeDisplacement = safe;
    return true;
  }
  return confirmUncertain(q);
}

bool FastCollisionChecker::confirmUncertain(const Configuration& q) {
  // Pairs whose mesh enclosures overlap deeply are the likeliest to collide: asked first.
  std::stable_partition(uncertain_.begin(), uncertain_.end(),
                        [](const Flag& f) { return f.outcome == Outcome::EnclosuresOverlap; });
  exact_.kinematics().linkPoses(q, exactPoses_);
  for (const Flag& flag : uncertain_) {
    ++statistics_.pairsConfirmed;
    const bool collides = flag.self
                              ? exact_.linkPairCollides(exactPoses_, flag.a, flag.b)
                              : exact_.linkObstacleCollides(exactPoses_, flag.a, static_cast<std::size_t>(flag.b));
    if (collides) {
      ++statistics_.confirmedColliding;
      return false;
    }
  }
  ++statistics_.confirmedFree;
  return true;
}

bool FastCollisionChecker::isValid(const Configuration& q) {
  ++checks_;
  if (q.size() != kinematics_.dof()) throw std::invalid_argument("configuration size does not match the robot");
  kinematics_.computeOne(q.data(), poseScratch_.data());
  return decide(q, poseScratch_.data(), 1, 0, false, nullptr);
}

bool FastCollisionChecker::isArmValid(const Configuration& q) {
  ++checks_;
  if (q.size() != kinematics_.dof()) throw std::invalid_argument("configuration size does not match the robot");
  kinematics_.computeOne(q.data(), poseScratch_.data());
  return decide(q, poseScratch_.data(), 1, 0, true, nullptr);
}

void FastCollisionChecker::checkBatch(const Configuration* const* configurations, int count, bool* valid,
                                      double* safeDisplacement, double* pairGaps) {
  if (count < 1 || count > kLanes) throw std::invalid_argument("checkBatch: 1 to kLanes configurations");
  const int dof = kinematics_.dof();
  if (count == 1) {  // a lone state: the single-lane kinematics is cheaper than a padded batch
    if (configurations[0]->size() != dof) throw std::invalid_argument("configuration size does not match the robot");
    ++checks_;
    kinematics_.computeOne(configurations[0]->data(), poseScratch_.data());
    valid[0] = decide(*configurations[0], poseScratch_.data(), 1, 0, false, &safeDisplacement[0], pairGaps);
    return;
  }
  double joints[64 * kLanes];
  std::vector<double> wide;
  double* q = joints;
  if (dof > 64) {
    wide.resize(static_cast<std::size_t>(dof) * kLanes);
    q = wide.data();
  }
  for (int lane = 0; lane < kLanes; ++lane) {
    const Configuration& c = *configurations[std::min(lane, count - 1)];  // spare lanes repeat the last
    if (c.size() != dof) throw std::invalid_argument("configuration size does not match the robot");
    for (int i = 0; i < dof; ++i) q[i * kLanes + lane] = c[i];
  }
  kinematics_.computeBatch(q, poseScratch_.data());
  checks_ += static_cast<std::size_t>(count);
  screenBatch(configurations, count, poseScratch_.data(), valid, safeDisplacement, pairGaps);
}

void FastCollisionChecker::poseState(const Configuration& q, const std::size_t* pairs, std::size_t count) {
  if (q.size() != kinematics_.dof()) throw std::invalid_argument("configuration size does not match the robot");
  // Self pairs below one common link are posed relative to it; anything else in the world.
  int frame = count > 0 && pairs[0] < selfPairs_.size() ? pairFrame_[pairs[0]] : -1;
  for (std::size_t k = 1; k < count && frame >= 0; ++k)
    if (pairs[k] >= selfPairs_.size() || pairFrame_[pairs[k]] != frame) frame = -1;
  std::fill(posedLinks_.begin(), posedLinks_.end(), 0);
  for (std::size_t k = 0; k < count; ++k) {
    const auto& links = frame >= 0 ? pairRelativeLinks_[pairs[k]] : pairLinks_[pairs[k]];
    for (std::size_t w = 0; w < links.size(); ++w) posedLinks_[w] |= links[w];
  }
  kinematics_.computeSome(q.data(), poseScratch_.data(), posedLinks_, frame);
  beginLane(poseScratch_.data(), 1, 0);
  posed_ = q;
}

double FastCollisionChecker::testPair(std::size_t pair) {
  const std::size_t selfCount = selfPairs_.size();
  const bool self = pair < selfCount;
  int a, b;
  double gap;
  if (self) {
    std::tie(a, b) = selfPairs_[pair];
    for (const int l : {a, b})
      if (!boundPlaced_[static_cast<std::size_t>(l)]) placeBound(l);
    const double c1[3] = {boundX_[static_cast<std::size_t>(a)], boundY_[static_cast<std::size_t>(a)],
                          boundZ_[static_cast<std::size_t>(a)]};
    const double c2[3] = {boundX_[static_cast<std::size_t>(b)], boundY_[static_cast<std::size_t>(b)],
                          boundZ_[static_cast<std::size_t>(b)]};
    gap = sphereSphereGap(c1, 0.0, c2, 0.0) - pairRadiusSum_[pair];
  } else {
    const std::size_t k = pair - selfCount, linkCount = geometricLinks_.size();
    a = geometricLinks_[k % linkCount];
    b = static_cast<int>(k / linkCount);
    if (!boundPlaced_[static_cast<std::size_t>(a)]) placeBound(a);
    const double c[3] = {boundX_[static_cast<std::size_t>(a)], boundY_[static_cast<std::size_t>(a)],
                         boundZ_[static_cast<std::size_t>(a)]};
    gap = sphereGap(obstacles_[static_cast<std::size_t>(b)].part, c, geometricBoundR_[k % linkCount]);
  }
  if (gap > band_) return gap;
  const Outcome outcome = self ? linkPairContact(a, b, gap) : linkObstacleContact(a, static_cast<std::size_t>(b), gap);
  if (outcome == Outcome::Apart) return gap;
  if (outcome == Outcome::Overlapping) return -1.0;
  exact_.kinematics().linkPoses(posed_, exactPoses_);
  ++statistics_.pairsConfirmed;
  const bool collides = self ? exact_.linkPairCollides(exactPoses_, a, b)
                             : exact_.linkObstacleCollides(exactPoses_, a, static_cast<std::size_t>(b));
  return collides ? -1.0 : 0.0;
}

ScreenResult FastCollisionChecker::screen(const Configuration& q, bool armOnly) {
  if (q.size() != kinematics_.dof()) throw std::invalid_argument("configuration size does not match the robot");
  kinematics_.computeOne(q.data(), poseScratch_.data());
  ScreenResult result;
  result.overlappingSelf = armOnly ? staticArmSelfCollisions_ : staticSelfCollisions_;
  if (!armOnly) result.overlappingObstacle = staticEnvironmentCollisions_;
  const double safe = screenLane(poseScratch_.data(), 1, 0, armOnly, [&](const Flag& flag) {
    const bool overlapping = flag.outcome == Outcome::Overlapping;
    if (flag.self)
      (overlapping ? result.overlappingSelf : result.uncertainSelf).emplace_back(flag.a, flag.b);
    else
      (overlapping ? result.overlappingObstacle : result.uncertainObstacle)
          .emplace_back(flag.a, static_cast<std::size_t>(flag.b));
    return false;
  });
  result.safeDisplacement = result.provenFree() ? std::max(safe, 0.0) : 0.0;
  return result;
}

}  // namespace pmdplan
