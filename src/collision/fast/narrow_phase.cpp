// The fast checker's narrow phase (narrow_phase.hpp): link against link or obstacle, part against
// part (partContact, convex_distance.hpp), each first by the bounding spheres; the parts placed in
// the world on first use; FCL for the pairs it leaves.
#include "narrow_phase.hpp"

#include <algorithm>
#include <limits>

#include "checker_model.hpp"
#include "checker_scratch.hpp"
#include "pmdplan/collision/fast/convex_distance.hpp"

namespace pmdplan::fast {
namespace {

constexpr double kNarrowInfinity = std::numeric_limits<double>::infinity();
constexpr int kNarrowValues = BatchedForwardKinematics::kPoseValues;

/// The link's parts with their bounding spheres placed (the rest of each part is not yet).
const ConvexPart* placedBounds(const CheckerModel& model, LaneScratch& s, int link) {
  const auto l = static_cast<std::size_t>(link);
  const auto offset = static_cast<std::size_t>(model.partOffset()[l]);
  ConvexPart* world = s.worldParts.data() + offset;
  if (s.placed[l]) return world;
  double* pose = s.linkPoses.data() + l * kNarrowValues;
  for (int i = 0; i < kNarrowValues; ++i) pose[i] = s.poses[(link * kNarrowValues + i) * s.stride + s.lane];
  const auto& local = model.links()[l].parts;
  for (std::size_t p = 0; p < local.size(); ++p) {
    const double* c = local[p].boundCentre;
    double* w = world[p].boundCentre;
    for (int r = 0; r < 3; ++r)
      w[r] = pose[r * 3] * c[0] + pose[r * 3 + 1] * c[1] + pose[r * 3 + 2] * c[2] + pose[9 + r];
    world[p].boundRadius = local[p].boundRadius;
    s.partPlaced[offset + p] = 0;
  }
  s.placed[l] = 1;
  return world;
}

/// Part `index` of the link, all of it placed (placedBounds first).
const ConvexPart& placedPart(const CheckerModel& model, LaneScratch& s, int link, std::size_t index) {
  const auto l = static_cast<std::size_t>(link);
  const std::size_t k = static_cast<std::size_t>(model.partOffset()[l]) + index;
  if (!s.partPlaced[k]) {
    placePart(model.links()[l].parts[index], s.linkPoses.data() + l * kNarrowValues, s.worldParts[k]);
    s.partPlaced[k] = 1;
  }
  return s.worldParts[k];
}

}  // namespace

// Part against part; a part first against the other link's bound, each part pair first by its
// bounding spheres. Overlapping as soon as one part pair overlaps; Uncertain if one is too close
// to call and none overlaps; else Apart with the smallest gap.
Outcome linkPairContact(const CheckerModel& model, CheckerScratch& scratch, int a, int b, double& gap) {
  LaneScratch& s = scratch.lane();
  const double band = model.band();
  const ConvexPart* partsA = placedBounds(model, s, a);
  const ConvexPart* partsB = placedBounds(model, s, b);
  const auto ua = static_cast<std::size_t>(a), ub = static_cast<std::size_t>(b);
  const std::size_t na = model.links()[ua].parts.size(), nb = model.links()[ub].parts.size();
  const double boundB[3] = {s.boundX[ub], s.boundY[ub], s.boundZ[ub]};
  const double boundRadiusB = model.links()[ub].boundRadius;
  bool uncertain = false, enclosures = false;
  gap = kNarrowInfinity;
  for (std::size_t i = 0; i < na; ++i) {
    const ConvexPart& pa = partsA[i];
    const double toLink = sphereSphereGap(pa.boundCentre, pa.boundRadius, boundB, boundRadiusB);
    if (toLink > band) {
      gap = std::min(gap, toLink);
      continue;
    }
    for (std::size_t j = 0; j < nb; ++j) {
      const ConvexPart& pb = partsB[j];
      const double bounds = sphereSphereGap(pa.boundCentre, pa.boundRadius, pb.boundCentre, pb.boundRadius);
      if (bounds > band) {
        gap = std::min(gap, bounds);
        continue;
      }
      const ConvexPart &worldA = placedPart(model, s, a, i), &worldB = placedPart(model, s, b, j);
      const PartContact contact = partContact(worldA, worldB, band);
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

Outcome linkObstacleContact(const CheckerModel& model, CheckerScratch& scratch, int link, std::size_t o, double& gap) {
  LaneScratch& s = scratch.lane();
  const double band = model.band();
  const ConvexPart* parts = placedBounds(model, s, link);
  const std::size_t count = model.links()[static_cast<std::size_t>(link)].parts.size();
  const ObstaclePart& obstacle = model.obstacles()[o];
  bool uncertain = false, enclosures = false;
  gap = kNarrowInfinity;
  for (std::size_t i = 0; i < count; ++i) {
    const double bound = sphereGap(obstacle.part, parts[i].boundCentre, parts[i].boundRadius);
    if (bound > band) {
      gap = std::min(gap, bound);
      continue;
    }
    const ConvexPart& part = placedPart(model, s, link, i);
    const PartContact contact = partContact(part, obstacle.part, band);
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

void beginLane(const CheckerModel&, CheckerScratch& scratch, const double* poses, int stride, int lane) {
  LaneScratch& s = scratch.lane();
  s.poses = poses, s.stride = stride, s.lane = lane;
  std::fill(s.placed.begin(), s.placed.end(), 0);
  std::fill(s.boundPlaced.begin(), s.boundPlaced.end(), 0);
}

void placeBound(const CheckerModel& model, CheckerScratch& scratch, int link) {
  LaneScratch& s = scratch.lane();
  const auto ul = static_cast<std::size_t>(link);
  const double* c = model.links()[ul].boundCentre;
  double m[kNarrowValues];
  for (int i = 0; i < kNarrowValues; ++i) m[i] = s.poses[(link * kNarrowValues + i) * s.stride + s.lane];
  s.boundX[ul] = m[0] * c[0] + m[1] * c[1] + m[2] * c[2] + m[9];
  s.boundY[ul] = m[3] * c[0] + m[4] * c[1] + m[5] * c[2] + m[10];
  s.boundZ[ul] = m[6] * c[0] + m[7] * c[1] + m[8] * c[2] + m[11];
  s.boundPlaced[ul] = 1;
}

bool confirmUncertain(const CheckerModel&, CheckerScratch& scratch, const Configuration& q) {
  std::vector<Flag>& uncertain = scratch.uncertain();
  FastCheckStatistics& statistics = scratch.statistics();
  const ExactCollisionChecker& exact = scratch.exact();
  // Pairs whose mesh enclosures overlap deeply are the likeliest to collide: asked first.
  std::stable_partition(uncertain.begin(), uncertain.end(),
                        [](const Flag& f) { return f.outcome == Outcome::EnclosuresOverlap; });
  exact.kinematics().linkPoses(q, scratch.exactPoses());
  for (const Flag& flag : uncertain) {
    ++statistics.pairsConfirmed;
    const bool collides =
        flag.self ? exact.linkPairCollides(scratch.exactPoses(), flag.a, flag.b)
                  : exact.linkObstacleCollides(scratch.exactPoses(), flag.a, static_cast<std::size_t>(flag.b));
    if (collides) {
      ++statistics.confirmedColliding;
      return false;
    }
  }
  ++statistics.confirmedFree;
  return true;
}

}  // namespace pmdplan::fast
