// The fast checker's narrow phase, one configuration (a lane of posed links) at a time: link
// against link or obstacle, part against part (partContact, convex_distance.hpp), each first by
// the bounding spheres; the parts placed in the world on first use; FCL for the pairs it leaves.
#include <algorithm>
#include <limits>

#include "checker_state.hpp"
#include "pmdplan/collision/fast/convex_distance.hpp"

namespace pmdplan::fast {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr int kValues = BatchedForwardKinematics::kPoseValues;

}  // namespace

const ConvexPart* CheckerState::placedBounds(int link) {
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

const ConvexPart& CheckerState::placedPart(int link, std::size_t index) {
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
CheckerState::Outcome CheckerState::linkPairContact(int a, int b, double& gap) {
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

CheckerState::Outcome CheckerState::linkObstacleContact(int link, std::size_t o, double& gap) {
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

void CheckerState::beginLane(const double* poses, int stride, int lane) {
  lanePoses_ = poses, laneStride_ = stride, lane_ = lane;
  std::fill(placed_.begin(), placed_.end(), 0);
  std::fill(boundPlaced_.begin(), boundPlaced_.end(), 0);
}

void CheckerState::placeBound(int link) {
  const auto ul = static_cast<std::size_t>(link);
  const double* c = links_[ul].boundCentre;
  double m[kValues];
  for (int i = 0; i < kValues; ++i) m[i] = lanePoses_[(link * kValues + i) * laneStride_ + lane_];
  boundX_[ul] = m[0] * c[0] + m[1] * c[1] + m[2] * c[2] + m[9];
  boundY_[ul] = m[3] * c[0] + m[4] * c[1] + m[5] * c[2] + m[10];
  boundZ_[ul] = m[6] * c[0] + m[7] * c[1] + m[8] * c[2] + m[11];
  boundPlaced_[ul] = 1;
}

bool CheckerState::confirmUncertain(const Configuration& q) {
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

}  // namespace pmdplan::fast
