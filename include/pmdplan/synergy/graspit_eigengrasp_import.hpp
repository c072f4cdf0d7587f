#pragma once
// GraspIt! eigengrasp files as synergy models. A file holds <EigenGrasps dimensions="n"> with an
// <ORIGIN> (<DimVals d0=".." …/>), optional per-dimension <NORM> factors, and <EG> entries of
// <EigenValue value=".."/> and <DimVals …/>; GraspIt moves DOF d by origin[d] + norm[d]·(E^T a)[d].
// The file names no joints: the caller says which robot joint each dimension drives.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "pmdplan/core/joint_limit.hpp"
#include "pmdplan/synergy/synergy_model.hpp"

namespace pmdplan {

struct GraspItImport {
  SynergyModel model;
  /// What the import had to do or assume, in words for the user (normalised vectors, a
  /// non-orthogonal basis, joints not in the file held at mid-range, ignored amplitude limits).
  std::vector<std::string> notes;
};

/// `dimensionJoints[d]` names the robot joint of dimension d; `handJoints` are the robot's hand
/// joints the model covers. Directions are the eigengrasps scaled into normalised joint units and
/// normalised, ordered by eigenvalue; sigma_i = sqrt(eigenvalue_i) · |v_i| (v_i the eigengrasp in
/// normalised units). Joints of `handJoints` that no dimension drives are held at mid-range.
/// Throws InputError naming the file and line of malformed XML, a dimension count that differs from
/// the joint list, unknown joints, an origin beyond a joint limit and a rank-deficient basis.
GraspItImport importGraspItEigengrasps(const std::filesystem::path& path,
                                       const std::vector<std::string>& dimensionJoints, const JointLimits& handJoints);
GraspItImport parseGraspItEigengrasps(std::string_view xml, const std::string& sourceName,
                                      const std::vector<std::string>& dimensionJoints, const JointLimits& handJoints);

}  // namespace pmdplan
