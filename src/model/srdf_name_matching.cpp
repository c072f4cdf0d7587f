#include "srdf_name_matching.hpp"

namespace pmdplan {
namespace {

bool endsWith(const std::string& text, const std::string& tail) {
  return text.size() > tail.size() && text.compare(text.size() - tail.size(), tail.size(), tail) == 0;
}

}  // namespace

SrdfNameMatch matchSrdfName(const std::vector<std::string>& urdfNames, const std::string& srdfName) {
  SrdfNameMatch match;
  for (std::size_t i = 0; i < urdfNames.size(); ++i)
    if (urdfNames[i] == srdfName) {
      match.index = static_cast<int>(i);
      return match;
    }
  std::vector<int> found;
  for (std::size_t i = 0; i < urdfNames.size(); ++i)
    if (!srdfName.empty() && (endsWith(urdfNames[i], srdfName) || endsWith(srdfName, urdfNames[i]))) {
      found.push_back(static_cast<int>(i));
      match.candidates.push_back(urdfNames[i]);
    }
  if (found.size() == 1) match.index = found.front();
  return match;
}

std::string unmatchedSrdfName(const SrdfNameMatch& match, const std::string& kind, const std::string& srdfName) {
  std::string text = "unknown " + kind + " '" + srdfName + "'";
  if (!match.candidates.empty()) {
    std::string names;
    for (const auto& name : match.candidates) names += (names.empty() ? "" : ", ") + name;
    return text + " (the URDF has " + names + ": write the one meant in the SRDF)";
  }
  return text +
         " (not in the URDF; write an SRDF for this URDF with `pmdplan robot init URDF --arm J1,J2,... "
         "--palm LINK`)";
}

}  // namespace pmdplan
