#include "pmdplan/synergy/kautham_sah_synergies.hpp"

#include <array>
#include <cmath>

namespace pmdplan {
namespace {

struct KauthamRow {
  const char* joint;
  bool flexion;  // thumb base, proximal and medium joints: Kautham counts them negative
  double mean;
  std::array<double, 4> pmd;
};

// docs/reference_data.md §4, as published (Kautham convention, p = 0 at Kautham's low limit).
constexpr std::array<KauthamRow, 13> kRows{{
    {"thumb_base", true, .3055, {0, 0, 0, 0}},
    {"thumb_abduction", false, .3055, {-.0683, -.0144, .6638, -.2879}},
    {"thumb_proximal", true, .6308, {.2222, -.1323, .6816, .2207}},
    {"thumb_medium", true, .5143, {.3194, -.2335, -.0597, .5468}},
    {"index_abduction", false, .5544, {.2409, .2090, .0137, -.4425}},
    {"index_proximal", true, .5400, {-.4246, -.2023, .1785, .0076}},
    {"index_medium", true, .5075, {.2125, -.5050, -.1633, .0258}},
    {"middle_abduction", false, .5, {0, 0, 0, 0}},
    {"middle_proximal", true, .5579, {-.4884, -.2759, .0215, .0387}},
    {"middle_medium", true, .4118, {.2399, -.4695, -.0470, -.3149}},
    {"ring_abduction", false, .4909, {-.1741, -.1258, .1078, .4037}},
    {"ring_proximal", true, .5407, {-.4451, -.2616, -.1351, -.1768}},
    {"ring_medium", true, .4806, {.1897, -.4554, .0030, -.2791}},
}};
constexpr std::array<double, 4> kSpan{1.6550, 1.4355, 0.8851, 0.7174};

// Kautham's joint limits (docs/reference_data.md §1), degrees, converted to positive flexion.
JointLimit limitOf(const std::string& joint) {
  const double degree = M_PI / 180.0;
  const auto endsWith = [&](const char* suffix) {
    const std::string s(suffix);
    return joint.size() >= s.size() && joint.compare(joint.size() - s.size(), s.size(), s) == 0;
  };
  if (joint == "thumb_base") return {joint, 0.0, 90.0 * degree};
  if (endsWith("_abduction")) return {joint, -15.0 * degree, 15.0 * degree};
  if (endsWith("_proximal")) return {joint, -4.0 * degree, 75.0 * degree};
  return {joint, 4.0 * degree, 75.0 * degree};  // medium
}

KauthamSahSynergies convert() {
  KauthamSahSynergies table;
  table.mean.resize(13);
  table.directions.resize(13, 4);
  table.span = Eigen::Map<const Eigen::Vector4d>(kSpan.data());
  for (int j = 0; j < 13; ++j) {
    const KauthamRow& row = kRows[static_cast<std::size_t>(j)];
    table.joints.emplace_back(row.joint);
    table.limits.push_back(limitOf(row.joint));
    const double sign = row.flexion ? -1.0 : 1.0;
    table.mean(j) = row.flexion ? 1.0 - row.mean : row.mean;
    for (int k = 0; k < 4; ++k) table.directions(j, k) = sign * row.pmd[static_cast<std::size_t>(k)];
  }
  // The published vectors carry four decimals; make them unit length again.
  table.directions.colwise().normalize();
  return table;
}

}  // namespace

const KauthamSahSynergies& kauthamSahSynergies() {
  static const KauthamSahSynergies table = convert();
  return table;
}

}  // namespace pmdplan
