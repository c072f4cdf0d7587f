#include "part_pair_table.hpp"

#include <utility>

#include "lane_geometry.hpp"
#include "lane_parts.hpp"

namespace pmdplan::fast {

PartPairKernel partPairKernel(ConvexPart::Kind first, ConvexPart::Kind second) {
  using Kind = ConvexPart::Kind;
  if (first == second)
    return {first == Kind::Capsule ? PartPairKind::CapsuleCapsule
            : first == Kind::Box   ? PartPairKind::BoxBox
                                   : PartPairKind::CylinderCylinder,
            false};
  if (first == Kind::Capsule || second == Kind::Capsule)
    return {first == Kind::Box || second == Kind::Box ? PartPairKind::CapsuleBox : PartPairKind::CapsuleCylinder,
            second == Kind::Capsule};
  return {first == Kind::Box ? PartPairKind::BoxCylinder : PartPairKind::CylinderBox, first == Kind::Cylinder};
}

PartPairTable::PartPairTable(const std::vector<LinkParts>& links, const std::vector<ObstaclePart>& obstacles,
                             const std::vector<int>& partOffset, const std::vector<int>& pairA,
                             const std::vector<int>& pairB, const std::vector<int>& geometricLinks) {
  // Every part, then every pair's part pairs in pair order.
  for (const auto& link : links) shapes.insert(shapes.end(), link.parts.begin(), link.parts.end());
  const auto obstacleBase = static_cast<std::uint32_t>(shapes.size());
  for (const auto& obstacle : obstacles) shapes.push_back(obstacle.part);

  obstacleLanes.assign(obstacles.size() * kPartValues * L, 0.0);
  for (std::size_t o = 0; o < obstacles.size(); ++o) {
    const ConvexPart& part = obstacles[o].part;
    double* out = obstacleLanes.data() + o * kPartValues * L;
    const auto spread = [&](int at, const double* values, int count) {
      for (int v = 0; v < count; ++v)
        for (int l = 0; l < L; ++l) out[(at + v) * L + l] = values[v];
    };
    spread(0, part.a, 3);
    spread(3, part.b, 3);
    spread(kPartAxes, part.axes, 9);
    spread(kPartBound, part.boundCentre, 3);
    spread(kPartOuter, part.outerA, 3);
    spread(kPartOuter + 3, part.outerB, 3);
  }

  // Each part pair with its kernel, counted by kind.
  std::uint32_t kindCounts[kPartPairKinds] = {};
  const auto add = [&](std::uint32_t a, std::uint32_t b) {
    const PartPairKernel kernel = partPairKernel(shapes[a].kind, shapes[b].kind);
    if (kernel.swapped) std::swap(a, b);
    ++kindCounts[static_cast<int>(kernel.kind)];
    pairs.push_back({a, b, kernel.kind, lanes::inverseSquaredLength(shapes[a].a, shapes[a].b),
                     lanes::inverseSquaredLength(shapes[b].a, shapes[b].b)});
  };
  const auto partsOf = [&](int link) {
    const auto first = static_cast<std::uint32_t>(partOffset[static_cast<std::size_t>(link)]);
    return std::pair{first, first + static_cast<std::uint32_t>(links[static_cast<std::size_t>(link)].parts.size())};
  };
  pairBegin.assign(1, 0);
  for (std::size_t p = 0; p < pairA.size(); ++p) {
    const auto [beginA, endA] = partsOf(pairA[p]);
    const auto [beginB, endB] = partsOf(pairB[p]);
    for (std::uint32_t i = beginA; i < endA; ++i)
      for (std::uint32_t j = beginB; j < endB; ++j) add(i, j);
    pairBegin.push_back(static_cast<std::uint32_t>(pairs.size()));
  }
  for (std::size_t o = 0; o < obstacles.size(); ++o)
    for (const int link : geometricLinks) {
      const auto [begin, end] = partsOf(link);
      for (std::uint32_t k = begin; k < end; ++k) add(k, obstacleBase + static_cast<std::uint32_t>(o));
      pairBegin.push_back(static_cast<std::uint32_t>(pairs.size()));
    }
  for (int k = 1; k < kPartPairKinds; ++k) kindBegin[k] = kindBegin[k - 1] + kindCounts[k - 1];
}

}  // namespace pmdplan::fast
