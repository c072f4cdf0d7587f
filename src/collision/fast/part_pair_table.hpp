#pragma once
// The batch screen's part pairs (batch_screen.cpp), set up once per task (checker_model.hpp): every
// pair's part pairs in pair order, each with the kernel of its two kinds chosen here, and the
// obstacles' parts as the batch screen lays them out (lane_parts.hpp).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "pmdplan/collision/link_part_model.hpp"

namespace pmdplan::fast {

/// The kernel of a part pair (one header each: capsule_capsule.hpp, capsule_box.hpp, ...). A pair's
/// parts are stored in the order of the kernel's name; a box and a cylinder keep the order of
/// their pair (CylinderBox: the cylinder came first, its axis is tried first), as do two parts of
/// one kind.
enum class PartPairKind : std::uint8_t {
  CapsuleCapsule,
  CapsuleBox,
  CapsuleCylinder,
  BoxBox,
  BoxCylinder,
  CylinderBox,
  CylinderCylinder
};
constexpr int kPartPairKinds = 7;

/// The kernel for parts of kinds `first` and `second`, and whether it takes them swapped.
struct PartPairKernel {
  PartPairKind kind;
  bool swapped;
};
PartPairKernel partPairKernel(ConvexPart::Kind first, ConvexPart::Kind second);

struct PartPair {
  std::uint32_t indexA, indexB;  ///< into PartPairTable::shapes (and the batch screen's placed parts)
  PartPairKind kind;
  double inverseA, inverseB;  ///< capsules: 1 / their cores' squared lengths (0: a point)
};

struct PartPairTable {
  PartPairTable() = default;
  /// The pairs of the checker's order (checker_model.hpp, SelfPairs): the self pairs (links pairA[p]
  /// and pairB[p]), then every link of `geometricLinks` against every obstacle. `partOffset`: per
  /// link, the index of its first part among every link's parts.
  PartPairTable(const std::vector<LinkParts>& links, const std::vector<ObstaclePart>& obstacles,
                const std::vector<int>& partOffset, const std::vector<int>& pairA, const std::vector<int>& pairB,
                const std::vector<int>& geometricLinks);

  std::vector<ConvexPart> shapes;  ///< the link parts (in their links' frames), then the obstacles
  std::vector<PartPair> pairs;
  /// Pair p's part pairs: from pairBegin[p] to pairBegin[p + 1].
  std::vector<std::uint32_t> pairBegin;
  /// Where kind k's list begins in the batch screen's work list (the part pairs counted by kind).
  std::uint32_t kindBegin[kPartPairKinds] = {};
  /// The obstacles' parts as placed parts, [obstacle][value][lane] (lane_parts.hpp): the tail of
  /// the batch screen's placed parts, the same for every batch.
  std::vector<double> obstacleLanes;
};

}  // namespace pmdplan::fast
