#pragma once
// The joint pairs whose correlations the paper shows in its Fig. 7, with the sign the paper
// reports. The paper's joint values use Kautham's signs (flexion negative; docs/reference_data.md §1, §4); ours use
// positive flexion, so a pair of one flexion joint and one abduction joint changes sign.
#include <string>
#include <vector>

namespace pmdplan {

enum class PaperCorrelation { Positive, Negative, Uncorrelated };

struct Figure7JointPair {
  std::string first;
  std::string second;
  PaperCorrelation paper;
};

const std::vector<Figure7JointPair>& figure7JointPairs();

/// +1 or -1: the factor from our sign convention to the paper's for a SAH joint (-1 for thumb_base
/// and the proximal, medium and distal joints, whose flexion Kautham counts negative).
double paperSignOf(const std::string& joint);

}  // namespace pmdplan
