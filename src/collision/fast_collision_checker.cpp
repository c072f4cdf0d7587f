#include "pmdplan/collision/fast_collision_checker.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

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

double sphereGap(double ax, double ay, double az, double ar, double bx, double by, double bz, double br) {
  const double dx = ax - bx, dy = ay - by, dz = az - bz;
  return std::sqrt(dx * dx + dy * dy + dz * dz) - ar - br;
}

/// Smallest gap between spheres [a, a + na) and [b, b + nb) of the world arrays, each sphere of a
/// first screened against the bounding sphere of b's group.
double smallestPairwiseGap(const double* x, const double* y, const double* z, const double* r, int a, int na, int b, int nb,
                           const double* boundB) {
  double smallest = kInfinity;
  for (int i = a; i < a + na; ++i) {
    const double toBound = sphereGap(x[i], y[i], z[i], r[i], boundB[0], boundB[1], boundB[2], boundB[3]);
    if (toBound > 0.0) {
      smallest = std::min(smallest, toBound);
      continue;
    }
    for (int j = b; j < b + nb; ++j) smallest = std::min(smallest, sphereGap(x[i], y[i], z[i], r[i], x[j], y[j], z[j], r[j]));
    if (smallest <= 0.0) return smallest;
  }
  return smallest;
}

}  // namespace

FastCollisionChecker::FastCollisionChecker(const Task& task, ExactCollisionChecker& exact, const FastCheckerParameters& parameters)
    : exact_(exact),
      spheres_(*task.robot, parameters.spheres),
      environment_(task.obstacles),
      kinematics_(*task.robot, task.base),
      moving_(movingLinks(*task.robot)) {
  if (&exact.model() != task.robot.get()) throw std::invalid_argument("the exact checker belongs to another task");
  const auto& links = spheres_.links();
  const std::size_t n = links.size();
  for (std::size_t l = 0; l < n; ++l) {
    sphereOffset_.push_back(static_cast<int>(worldX_.size()));
    groupOffset_.push_back(static_cast<int>(groupX_.size()));
    worldX_.resize(worldX_.size() + static_cast<std::size_t>(links[l].sphereCount()));
    groupX_.resize(groupX_.size() + static_cast<std::size_t>(links[l].groupCount()));
    if (!links[l].empty() && moving_[l]) geometricLinks_.push_back(static_cast<int>(l));
  }
  worldY_ = worldZ_ = worldX_;
  worldR_.clear();
  for (const auto& link : links) worldR_.insert(worldR_.end(), link.radius.begin(), link.radius.end());
  groupY_ = groupZ_ = groupR_ = groupX_;
  worldBoxes_.resize(groupX_.size());
  worldCapsules_.resize(groupX_.size());
  groupPlaced_.assign(groupX_.size(), 0);
  boxPlaced_.assign(groupX_.size(), 0);
  linkPoses_.assign(n * kValues, 0.0);
  for (std::size_t l = 0; l < n; ++l)
    for (int g = 0; g < links[l].groupCount(); ++g)
      groupR_[static_cast<std::size_t>(groupOffset_[l] + g)] = links[l].groupBounds[static_cast<std::size_t>(g)].radius;
  boundX_.assign(n, 0.0), boundY_ = boundZ_ = boundX_;
  placed_.assign(n, 0);
  poseScratch_.resize(kinematics_.batchPoseSize());

  for (std::size_t l = 0; l < n; ++l)
    if (!links[l].empty()) boundLinks_.push_back(static_cast<int>(l));
  for (int l : geometricLinks_) movingBoundR_.push_back(links[static_cast<std::size_t>(l)].bound.radius);
  movingBoundX_.assign(geometricLinks_.size(), 0.0);
  movingBoundY_ = movingBoundZ_ = movingBoundX_;
  obstacleGaps_.assign(geometricLinks_.size() * environment_.size(), 0.0);

  // Pairs no joint moves are decided once, by the exact checker itself (their poses never change).
  exact.kinematics().linkPoses(Configuration::Zero(task.robot->dof()), exactPoses_);
  for (const auto& [a, b] : exact.selfPairs()) {
    if (moving_[static_cast<std::size_t>(a)] || moving_[static_cast<std::size_t>(b)]) {
      movingSelfPairs_.emplace_back(a, b);
      pairIsArm_.push_back(exact.isArmLink(a) && exact.isArmLink(b));
      pairA_.push_back(a);
      pairB_.push_back(b);
      pairRadiusSum_.push_back(links[static_cast<std::size_t>(a)].bound.radius + links[static_cast<std::size_t>(b)].bound.radius);
      pairShare_.push_back(1.0 / (moving_[static_cast<std::size_t>(a)] + moving_[static_cast<std::size_t>(b)]));
    } else if (exact.linkPairCollides(exactPoses_, a, b)) {
      staticSelfCollisions_.emplace_back(a, b);
      if (exact.isArmLink(a) && exact.isArmLink(b)) staticArmSelfCollisions_.emplace_back(a, b);
    }
  }
  pairGaps_.assign(movingSelfPairs_.size(), 0.0);
  pairDx_ = pairDy_ = pairDz_ = pairGaps_;
  linkShare_.assign(geometricLinks_.size(), 1.0);
  computeMotionWeights(*task.robot);
  for (std::size_t l = 0; l < n; ++l)
    if (!moving_[l] && !links[l].empty())
      for (std::size_t o = 0; o < environment_.size(); ++o)
        if (exact.linkObstacleCollides(exactPoses_, static_cast<int>(l), o)) staticEnvironmentCollisions_.emplace_back(static_cast<int>(l), o);
}

void FastCollisionChecker::placeLink(int link, const double* poses, int stride, int lane) {
  const auto& spheres = spheres_.links()[static_cast<std::size_t>(link)];
  double* m = linkPoses_.data() + link * kValues;
  for (int i = 0; i < kValues; ++i) m[i] = poses[(link * kValues + i) * stride + lane];
  const int groupOffset = groupOffset_[static_cast<std::size_t>(link)];
  for (int g = 0; g < spheres.groupCount(); ++g) {
    const double* c = spheres.groupBounds[static_cast<std::size_t>(g)].centre;
    const auto k = static_cast<std::size_t>(groupOffset + g);
    groupX_[k] = m[0] * c[0] + m[1] * c[1] + m[2] * c[2] + m[9];
    groupY_[k] = m[3] * c[0] + m[4] * c[1] + m[5] * c[2] + m[10];
    groupZ_[k] = m[6] * c[0] + m[7] * c[1] + m[8] * c[2] + m[11];
    groupPlaced_[k] = 0;
    const GroupKind kind = spheres.groupKind[static_cast<std::size_t>(g)];
    if (kind == GroupKind::Capsule) {
      const Capsule& local = spheres.groupCapsules[static_cast<std::size_t>(g)];
      Capsule& world = worldCapsules_[k];
      world.radius = local.radius;
      for (int r = 0; r < 3; ++r) {
        world.a[r] = m[r * 3] * local.a[0] + m[r * 3 + 1] * local.a[1] + m[r * 3 + 2] * local.a[2] + m[9 + r];
        world.b[r] = m[r * 3] * local.b[0] + m[r * 3 + 1] * local.b[1] + m[r * 3 + 2] * local.b[2] + m[9 + r];
      }
    }
    boxPlaced_[k] = 0;  // boxes are turned into the world on first use (placedBox)
  }
  placed_[static_cast<std::size_t>(link)] = 1;
}

const SolidPrimitive& FastCollisionChecker::placedBox(int link, int group) {
  const auto k = static_cast<std::size_t>(groupOffset_[static_cast<std::size_t>(link)] + group);
  SolidPrimitive& world = worldBoxes_[k];
  if (boxPlaced_[k]) return world;
  const SolidPrimitive& local = spheres_.links()[static_cast<std::size_t>(link)].groupBoxes[static_cast<std::size_t>(group)];
  const double* m = linkPoses_.data() + link * kValues;
  world = local;
  world.centre[0] = groupX_[k], world.centre[1] = groupY_[k], world.centre[2] = groupZ_[k];
  for (int r = 0; r < 3; ++r)
    for (int col = 0; col < 3; ++col)
      world.rotation[r * 3 + col] = m[r * 3] * local.rotation[col] + m[r * 3 + 1] * local.rotation[3 + col] + m[r * 3 + 2] * local.rotation[6 + col];
  boxPlaced_[k] = 1;
  return world;
}

int FastCollisionChecker::placeGroup(int link, int group) {
  const auto& spheres = spheres_.links()[static_cast<std::size_t>(link)];
  const int begin = spheres.groupBegin[static_cast<std::size_t>(group)];
  const int offset = sphereOffset_[static_cast<std::size_t>(link)] + begin;
  const auto k = static_cast<std::size_t>(groupOffset_[static_cast<std::size_t>(link)] + group);
  if (groupPlaced_[k]) return offset;
  const double* m = linkPoses_.data() + link * kValues;
  const int count = spheres.groupBegin[static_cast<std::size_t>(group) + 1] - begin;
  const double *lx = spheres.x.data() + begin, *ly = spheres.y.data() + begin, *lz = spheres.z.data() + begin;
  double* __restrict wx = worldX_.data() + offset;
  double* __restrict wy = worldY_.data() + offset;
  double* __restrict wz = worldZ_.data() + offset;
  for (int i = 0; i < count; ++i) {
    wx[i] = m[0] * lx[i] + m[1] * ly[i] + m[2] * lz[i] + m[9];
    wy[i] = m[3] * lx[i] + m[4] * ly[i] + m[5] * lz[i] + m[10];
    wz[i] = m[6] * lx[i] + m[7] * ly[i] + m[8] * lz[i] + m[11];
  }
  groupPlaced_[k] = 1;
  return offset;
}

// The sphere stage of one configuration (lane `lane` of poses laid out with `stride` lanes).
// onFlag(isSelf, a, b) is called for every flagged pair and returns true to stop. Returns the safe
// displacement (see SphereStageVerdict) when nothing was flagged, else 0 (-1 when stopped).
template <class OnFlag>
double FastCollisionChecker::runStage(const double* poses, int stride, int lane, bool armOnly, OnFlag&& onFlag) {
  const auto& links = spheres_.links();
  std::fill(placed_.begin(), placed_.end(), 0);
  for (int l : boundLinks_) {
    const double* c = links[static_cast<std::size_t>(l)].bound.centre;
    double m[kValues];
    for (int i = 0; i < kValues; ++i) m[i] = poses[(l * kValues + i) * stride + lane];
    boundX_[static_cast<std::size_t>(l)] = m[0] * c[0] + m[1] * c[1] + m[2] * c[2] + m[9];
    boundY_[static_cast<std::size_t>(l)] = m[3] * c[0] + m[4] * c[1] + m[5] * c[2] + m[10];
    boundZ_[static_cast<std::size_t>(l)] = m[6] * c[0] + m[7] * c[1] + m[8] * c[2] + m[11];
  }
  for (std::size_t i = 0; i < geometricLinks_.size(); ++i) {
    const auto l = static_cast<std::size_t>(geometricLinks_[i]);
    movingBoundX_[i] = boundX_[l], movingBoundY_[i] = boundY_[l], movingBoundZ_[i] = boundZ_[l];
  }
  double safe = kInfinity;
  bool flagged = false;

  // Self, first the link bounds of every pair in one branch-free pass (it vectorises), then the
  // pairs whose bounds touch, primitive by primitive.
  const std::size_t pairCount = movingSelfPairs_.size();
  {
    const int* pa = pairA_.data();
    const int* pb = pairB_.data();
    const double *bx = boundX_.data(), *by = boundY_.data(), *bz = boundZ_.data();
    double* __restrict dx = pairDx_.data();
    double* __restrict dy = pairDy_.data();
    double* __restrict dz = pairDz_.data();
    for (std::size_t p = 0; p < pairCount; ++p)  // gathers
      dx[p] = bx[pa[p]] - bx[pb[p]], dy[p] = by[pa[p]] - by[pb[p]], dz[p] = bz[pa[p]] - bz[pb[p]];
    const double* sum = pairRadiusSum_.data();
    const double* share = pairShare_.data();
    double* __restrict gaps = pairGaps_.data();
    for (std::size_t p = 0; p < pairCount; ++p) gaps[p] = std::sqrt(dx[p] * dx[p] + dy[p] * dy[p] + dz[p] * dz[p]) - sum[p];
    if (!armOnly) {
      // Four running minima keep the loop free of one long dependency chain.
      double partial[4] = {kInfinity, kInfinity, kInfinity, kInfinity};
      std::size_t p = 0;
      for (; p + 4 <= pairCount; p += 4)
        for (int k = 0; k < 4; ++k) {
          const double g = gaps[p + k];
          partial[k] = std::min(partial[k], g > 0.0 ? g * share[p + k] : kInfinity);
        }
      for (; p < pairCount; ++p) partial[0] = std::min(partial[0], gaps[p] > 0.0 ? gaps[p] * share[p] : kInfinity);
      safe = std::min(std::min(partial[0], partial[1]), std::min(partial[2], partial[3]));
    }
  }
  for (std::size_t p = 0; p < pairCount; ++p) {
    const double linkGap = pairGaps_[p];
    if (linkGap > 0.0) {
      if (armOnly && pairIsArm_[p]) safe = std::min(safe, linkGap * pairShare_[p]);
      continue;
    }
    if (armOnly && !pairIsArm_[p]) continue;
    const auto [a, b] = movingSelfPairs_[p];
    const auto ua = static_cast<std::size_t>(a), ub = static_cast<std::size_t>(b);
    if (!placed_[ua]) placeLink(a, poses, stride, lane);
    if (!placed_[ub]) placeLink(b, poses, stride, lane);
    const auto& la = links[ua];
    const auto& lb = links[ub];
    double pairGap = kInfinity;
    for (int ga = 0; ga < la.groupCount() && pairGap > 0.0; ++ga) {
      const auto ka = static_cast<std::size_t>(groupOffset_[ua] + ga);
      const double boundA[4] = {groupX_[ka], groupY_[ka], groupZ_[ka], groupR_[ka]};
      const double toLink = sphereGap(boundA[0], boundA[1], boundA[2], boundA[3], boundX_[ub], boundY_[ub], boundZ_[ub], lb.bound.radius);
      if (toLink > 0.0) {
        pairGap = std::min(pairGap, toLink);
        continue;
      }
      for (int gb = 0; gb < lb.groupCount() && pairGap > 0.0; ++gb) {
        const auto kb = static_cast<std::size_t>(groupOffset_[ub] + gb);
        const double boundB[4] = {groupX_[kb], groupY_[kb], groupZ_[kb], groupR_[kb]};
        const double groupGap = sphereGap(boundA[0], boundA[1], boundA[2], boundA[3], boundB[0], boundB[1], boundB[2], boundB[3]);
        if (groupGap > 0.0) {
          pairGap = std::min(pairGap, groupGap);
          continue;
        }
        const double gap = groupPairGap(a, ga, b, gb, boundB);
        pairGap = std::min(pairGap, gap);
      }
    }
    if (pairGap > 0.0) {
      safe = std::min(safe, pairGap * pairShare_[p]);
      continue;
    }
    flagged = true;
    if (onFlag(true, a, b)) return -1.0;
  }
  if (armOnly) return flagged ? 0.0 : safe;

  // Environment: every moving link against every obstacle (static links were decided once), the
  // link bounds first in one pass per obstacle.
  const std::size_t linkCount = geometricLinks_.size();
  for (std::size_t o = 0; o < environment_.size(); ++o)
    sphereGaps(environment_.primitive(o), movingBoundX_.data(), movingBoundY_.data(), movingBoundZ_.data(), movingBoundR_.data(),
                      static_cast<int>(linkCount), obstacleGaps_.data() + o * linkCount);
  for (std::size_t o = 0; o < environment_.size(); ++o) {
    const double* gaps = obstacleGaps_.data() + o * linkCount;
    double partial = kInfinity;
    for (std::size_t i = 0; i < linkCount; ++i) partial = std::min(partial, gaps[i] > 0.0 ? gaps[i] * linkShare_[i] : kInfinity);
    safe = std::min(safe, partial);
  }
  for (std::size_t i = 0; i < linkCount; ++i) {
    const int l = geometricLinks_[i];
    const auto ul = static_cast<std::size_t>(l);
    const auto& link = links[ul];
    for (std::size_t o = 0; o < environment_.size(); ++o) {
      if (obstacleGaps_[o * linkCount + i] > 0.0) continue;  // counted in `safe` above
      if (!placed_[ul]) placeLink(l, poses, stride, lane);
      double pairGap = kInfinity;
      for (int g = 0; g < link.groupCount() && pairGap > 0.0; ++g) {
        const auto k = static_cast<std::size_t>(groupOffset_[ul] + g);
        const double groupGap = environment_.gap(o, groupX_[k], groupY_[k], groupZ_[k], groupR_[k]);
        if (groupGap > 0.0) {
          pairGap = std::min(pairGap, groupGap);
          continue;
        }
        const int count = link.groupBegin[static_cast<std::size_t>(g) + 1] - link.groupBegin[static_cast<std::size_t>(g)];
        const SolidPrimitive& obstacle = environment_.primitive(o);
        const GroupKind kind = link.groupKind[static_cast<std::size_t>(g)];
        double gap = -1.0;
        if (kind == GroupKind::Box) {
          // A box: exact against boxes and spheres; against a cylinder the better of two lower
          // bounds (the cylinder's box, then the box's spheres).
          if (obstacle.kind == SolidPrimitive::Kind::Sphere)
            gap = sphereGap(placedBox(l, g), obstacle.centre[0], obstacle.centre[1], obstacle.centre[2], obstacle.size[0]);
          else
            gap = boxGapLowerBound(placedBox(l, g), environment_.boundingBox(o));
        } else if (kind == GroupKind::Capsule && obstacle.kind == SolidPrimitive::Kind::Sphere) {
          const Capsule& c = worldCapsules_[k];
          gap = segmentDistance(c.a, c.b, obstacle.centre, obstacle.centre) - c.radius - obstacle.size[0];
        } else if (kind == GroupKind::Capsule) {
          // The box's (or the cylinder's box's) face normals first; the covering spheres if they
          // do not separate.
          gap = capsuleBoxGapLowerBound(worldCapsules_[k], environment_.boundingBox(o));
        }
        if (!(gap > 0.0) && (kind != GroupKind::Box || obstacle.kind == SolidPrimitive::Kind::Cylinder) &&
            !(kind == GroupKind::Capsule && obstacle.kind == SolidPrimitive::Kind::Sphere)) {
          const int s = placeGroup(l, g);
          gap = environment_.smallestGap(o, worldX_.data() + s, worldY_.data() + s, worldZ_.data() + s, worldR_.data() + s, count);
        }
        pairGap = std::min(pairGap, gap);
      }
      if (pairGap > 0.0) {
        safe = std::min(safe, pairGap * linkShare_[i]);
        continue;
      }
      flagged = true;
      if (onFlag(false, l, static_cast<int>(o))) return -1.0;
    }
  }
  return flagged ? 0.0 : safe;
}

// The gap between two groups of two links (both placed): exact for capsule-capsule, box-box by
// separating axes, a capsule's or sphere group's covering spheres against a box, else sphere pairs.
double FastCollisionChecker::groupPairGap(int a, int ga, int b, int gb, const double* boundB) {
  const auto& la = spheres_.links()[static_cast<std::size_t>(a)];
  const auto& lb = spheres_.links()[static_cast<std::size_t>(b)];
  const auto ka = static_cast<std::size_t>(groupOffset_[static_cast<std::size_t>(a)] + ga);
  const auto kb = static_cast<std::size_t>(groupOffset_[static_cast<std::size_t>(b)] + gb);
  const GroupKind kindA = la.groupKind[static_cast<std::size_t>(ga)], kindB = lb.groupKind[static_cast<std::size_t>(gb)];
  if (kindA == GroupKind::Capsule && kindB == GroupKind::Capsule) {
    const Capsule &ca = worldCapsules_[ka], &cb = worldCapsules_[kb];
    return segmentDistance(ca.a, ca.b, cb.a, cb.b) - ca.radius - cb.radius;
  }
  if (kindA == GroupKind::Box && kindB == GroupKind::Box) return boxGapLowerBound(placedBox(a, ga), placedBox(b, gb));
  const int na = la.groupBegin[static_cast<std::size_t>(ga) + 1] - la.groupBegin[static_cast<std::size_t>(ga)];
  const int nb = lb.groupBegin[static_cast<std::size_t>(gb) + 1] - lb.groupBegin[static_cast<std::size_t>(gb)];
  if (kindA == GroupKind::Box && kindB == GroupKind::Capsule) {
    const double faces = capsuleBoxGapLowerBound(worldCapsules_[kb], placedBox(a, ga));
    if (faces > 0.0) return faces;
  }
  if (kindB == GroupKind::Box && kindA == GroupKind::Capsule) {
    const double faces = capsuleBoxGapLowerBound(worldCapsules_[ka], placedBox(b, gb));
    if (faces > 0.0) return faces;
  }
  if (kindA == GroupKind::Box) {
    const int sb = placeGroup(b, gb);
    return smallestSphereGap(placedBox(a, ga), worldX_.data() + sb, worldY_.data() + sb, worldZ_.data() + sb, worldR_.data() + sb, nb);
  }
  if (kindB == GroupKind::Box) {
    const int sa = placeGroup(a, ga);
    return smallestSphereGap(placedBox(b, gb), worldX_.data() + sa, worldY_.data() + sa, worldZ_.data() + sa, worldR_.data() + sa, na);
  }
  const int sa = placeGroup(a, ga), sb = placeGroup(b, gb);
  return smallestPairwiseGap(worldX_.data(), worldY_.data(), worldZ_.data(), worldR_.data(), sa, na, sb, nb, boundB);
}

namespace {

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
      if (joint.type == JointType::Fixed || std::find(exclude.begin(), exclude.end(), chain[k]) != exclude.end()) continue;
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
  for (const auto& [a, b] : movingSelfPairs_) {
    const auto chainA = jointChain(model, a), chainB = jointChain(model, b);
    std::vector<int> common;
    for (std::size_t k = 0; k < chainA.size() && k < chainB.size() && chainA[k] == chainB[k]; ++k) common.push_back(chainA[k]);
    const auto wa = weightsOf(a, common), wb = weightsOf(b, common);
    for (std::size_t i = 0; i < dof; ++i) pairWeights_.push_back(wa[i] + wb[i]);
  }
}

void FastCollisionChecker::setMotion(const Configuration& from, const Configuration& to) {
  const auto dof = static_cast<std::size_t>(kinematics_.dof());
  std::vector<double> delta(dof);
  for (std::size_t i = 0; i < dof; ++i) delta[i] = std::abs(to[static_cast<Eigen::Index>(i)] - from[static_cast<Eigen::Index>(i)]);
  // Shares are 1 / (distance moved over the whole segment), rounded up by a relative 1e-9 so
  // rounding never makes a gap look safer than it is.
  const auto share = [&](const double* w) {
    double rate = 0.0;
    for (std::size_t i = 0; i < dof; ++i) rate += w[i] * delta[i];
    return 1.0 / (rate * (1.0 + 1e-9));
  };
  for (std::size_t p = 0; p < movingSelfPairs_.size(); ++p) pairShare_[p] = share(pairWeights_.data() + p * dof);
  for (std::size_t i = 0; i < geometricLinks_.size(); ++i) linkShare_[i] = share(linkWeights_.data() + i * dof);
}

bool FastCollisionChecker::decide(const Configuration& q, const double* poses, int stride, int lane, bool armOnly,
                                  double* safeDisplacement) {
  if (safeDisplacement) *safeDisplacement = 0.0;
  if (armOnly ? !staticArmSelfCollisions_.empty() : !(staticSelfCollisions_.empty() && staticEnvironmentCollisions_.empty())) {
    ++statistics_.colliding;
    return false;
  }
  bool posesReady = false;
  bool collides = false;
  const double safe = runStage(poses, stride, lane, armOnly, [&](bool self, int a, int b) {
    if (!posesReady) {
      exact_.kinematics().linkPoses(q, exactPoses_);
      posesReady = true;
    }
    ++statistics_.pairsConfirmed;
    collides = self ? exact_.linkPairCollides(exactPoses_, a, b)
                    : exact_.linkObstacleCollides(exactPoses_, a, static_cast<std::size_t>(b));
    return collides;
  });
  if (collides) {
    ++statistics_.colliding;
    return false;
  }
  if (safe > 0.0) {
    ++statistics_.sphereFree;
    if (safeDisplacement) *safeDisplacement = safe;
  } else {
    ++statistics_.confirmedFree;
  }
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

void FastCollisionChecker::checkBatch(const Configuration* const* configurations, int count, bool* valid, double* safeDisplacement) {
  if (count < 1 || count > kLanes) throw std::invalid_argument("checkBatch: 1 to kLanes configurations");
  const int dof = kinematics_.dof();
  if (count == 1) {  // a lone state: the single-lane kinematics is cheaper than a padded batch
    if (configurations[0]->size() != dof) throw std::invalid_argument("configuration size does not match the robot");
    ++checks_;
    kinematics_.computeOne(configurations[0]->data(), poseScratch_.data());
    valid[0] = decide(*configurations[0], poseScratch_.data(), 1, 0, false, &safeDisplacement[0]);
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
  for (int lane = 0; lane < count; ++lane) {
    ++checks_;
    valid[lane] = decide(*configurations[lane], poseScratch_.data(), kLanes, lane, false, &safeDisplacement[lane]);
  }
}

SphereStageVerdict FastCollisionChecker::sphereStage(const Configuration& q, bool armOnly) {
  if (q.size() != kinematics_.dof()) throw std::invalid_argument("configuration size does not match the robot");
  kinematics_.computeOne(q.data(), poseScratch_.data());
  SphereStageVerdict verdict;
  verdict.selfPairs = armOnly ? staticArmSelfCollisions_ : staticSelfCollisions_;
  if (!armOnly) verdict.obstaclePairs = staticEnvironmentCollisions_;
  const double safe = runStage(poseScratch_.data(), 1, 0, armOnly, [&](bool self, int a, int b) {
    if (self)
      verdict.selfPairs.emplace_back(a, b);
    else
      verdict.obstaclePairs.emplace_back(a, static_cast<std::size_t>(b));
    return false;
  });
  verdict.safeDisplacement = verdict.free() ? std::max(safe, 0.0) : 0.0;
  return verdict;
}

}  // namespace pmdplan
