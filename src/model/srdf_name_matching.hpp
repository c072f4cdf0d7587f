#pragma once
// Internal: the URDF name an SRDF (MoveIt's, as shipped) means. MoveIt configurations are often
// written for an unprefixed robot while the URDF carries a prefix (xacro's arm_id or prefix:
// "left_" + "panda_joint1"), or the other way round.
#include <string>
#include <vector>

namespace pmdplan {

struct SrdfNameMatch {
  int index = -1;                       ///< into the URDF names, or -1
  std::vector<std::string> candidates;  ///< when ambiguous: the URDF names it could mean
};

/// The exact name, else the one URDF name that is `srdfName` with a prefix added or removed.
SrdfNameMatch matchSrdfName(const std::vector<std::string>& urdfNames, const std::string& srdfName);

/// "unknown joint 'x'" plus what fixes it: the candidates to choose from, or `pmdplan robot init`.
std::string unmatchedSrdfName(const SrdfNameMatch& match, const std::string& kind, const std::string& srdfName);

}  // namespace pmdplan
