#include "pmdplan/synergy/figure7_joint_pairs.hpp"

namespace pmdplan {

const std::vector<Figure7JointPair>& figure7JointPairs() {
  // docs/reference_data.md §4: joints 8 & 11 positive, 6 & 9 positive, 8 & 10 positive, 4 & 10 negative,
  // 0 uncorrelated with 5 and with 12.
  static const std::vector<Figure7JointPair> pairs{
      {"middle_proximal", "ring_proximal", PaperCorrelation::Positive},
      {"index_medium", "middle_medium", PaperCorrelation::Positive},
      {"middle_proximal", "ring_abduction", PaperCorrelation::Positive},
      {"index_abduction", "ring_abduction", PaperCorrelation::Negative},
      {"thumb_base", "index_proximal", PaperCorrelation::Uncorrelated},
      {"thumb_base", "ring_medium", PaperCorrelation::Uncorrelated},
  };
  return pairs;
}

double paperSignOf(const std::string& joint) {
  const auto endsWith = [&](const std::string& suffix) {
    return joint.size() >= suffix.size() && joint.compare(joint.size() - suffix.size(), suffix.size(), suffix) == 0;
  };
  const bool flexion = joint == "thumb_base" || endsWith("_proximal") || endsWith("_medium") || endsWith("_distal");
  return flexion ? -1.0 : 1.0;
}

}  // namespace pmdplan
