#include "pmdplan/synergy/graspit_eigengrasp_import.hpp"

#include <tinyxml2.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "pmdplan/core/atomic_file.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/core/message_text.hpp"
#include "pmdplan/synergy/synergy_model_file.hpp"
#include "pmdplan/text/number_text.hpp"

namespace pmdplan {
namespace {

using tinyxml2::XMLElement;

std::string lineOf(const XMLElement* element) { return "line " + std::to_string(element->GetLineNum()); }

/// GraspIt's <DimVals d0=".." d1=".."/>: a missing dN counts as 0, as in GraspIt.
Eigen::VectorXd readDimVals(const XMLElement* parent, int dimensions, const std::string& file,
                            const std::string& what) {
  const XMLElement* values = parent->FirstChildElement("DimVals");
  if (values == nullptr) throw InputError(file, lineOf(parent) + " (" + what + ")", "missing <DimVals d0=\"..\" .../>");
  Eigen::VectorXd vector = Eigen::VectorXd::Zero(dimensions);
  for (const tinyxml2::XMLAttribute* attribute = values->FirstAttribute(); attribute; attribute = attribute->Next()) {
    const std::string name = attribute->Name();
    const auto index = name.size() > 1 && name[0] == 'd' ? parseWholeNumber(name.substr(1)) : std::nullopt;
    if (!index || *index >= dimensions)
      throw InputError(file, lineOf(values) + " (" + what + ")",
                       "attribute " + quotedText(name) + " is not d0 .. d" + std::to_string(dimensions - 1));
    const auto value = parseFiniteNumber(attribute->Value());
    if (!value)
      throw InputError(file, lineOf(values) + " (" + what + "." + fieldKeyText(name) + ")",
                       quotedText(attribute->Value()) + " is not a number");
    vector(static_cast<Eigen::Index>(*index)) = *value;
  }
  return vector;
}

struct Eigengrasp {
  Eigen::VectorXd values;
  double eigenvalue = 0.5;
  int line = 0;
  bool hasEigenvalue = false;
  bool hasLimits = false;
};

std::string joinNumbers(const std::vector<int>& numbers) {
  std::string text;
  for (const int n : numbers) text += (text.empty() ? "" : ", ") + std::to_string(n);
  return text;
}

}  // namespace

GraspItImport parseGraspItEigengrasps(std::string_view xml, const std::string& file,
                                      const std::vector<std::string>& dimensionJoints, const JointLimits& handJoints) {
  tinyxml2::XMLDocument document;
  if (document.Parse(xml.data(), xml.size()) != tinyxml2::XML_SUCCESS)
    throw InputError(file, "line " + std::to_string(document.ErrorLineNum()),
                     std::string("XML error: ") + document.ErrorStr());
  const XMLElement* root = document.RootElement();
  if (root == nullptr || std::string(root->Name()) != "EigenGrasps")
    throw InputError(file, root ? lineOf(root) : "line 1", "expected an <EigenGrasps dimensions=\"n\"> root element");
  const char* dimensionsText = root->Attribute("dimensions");
  const auto parsedDimensions = dimensionsText ? parseWholeNumber(dimensionsText) : std::nullopt;
  const int dimensions = parsedDimensions && *parsedDimensions <= 1000 ? static_cast<int>(*parsedDimensions) : 0;
  if (dimensions <= 0)
    throw InputError(file, lineOf(root) + " (dimensions)", "expected a whole number of dimensions from 1 to 1000");
  if (static_cast<std::size_t>(dimensions) != dimensionJoints.size())
    throw InputError(file, lineOf(root) + " (dimensions)",
                     "the file has " + std::to_string(dimensions) + " dimensions but " +
                         std::to_string(dimensionJoints.size()) +
                         " joints were named (--joints names one robot joint per dimension)");

  // Which hand joint each dimension drives.
  std::vector<int> jointOf(static_cast<std::size_t>(dimensions));
  for (std::size_t d = 0; d < dimensionJoints.size(); ++d) {
    const auto it = std::find_if(handJoints.begin(), handJoints.end(),
                                 [&](const JointLimit& j) { return j.name == dimensionJoints[d]; });
    if (it == handJoints.end()) {
      std::string names;
      for (const auto& joint : handJoints) names += (names.empty() ? "" : ", ") + joint.name;
      throw InputError(
          "", "joints",
          "'" + dimensionJoints[d] + "' (dimension " + std::to_string(d) + ") is not one of the hand joints " + names);
    }
    jointOf[d] = static_cast<int>(it - handJoints.begin());
    for (std::size_t e = 0; e < d; ++e)
      if (jointOf[e] == jointOf[d])
        throw InputError("", "joints", "joint " + dimensionJoints[d] + " is named for two dimensions");
  }

  GraspItImport result;
  std::vector<Eigengrasp> grasps;
  for (const XMLElement* eg = root->FirstChildElement("EG"); eg; eg = eg->NextSiblingElement("EG")) {
    Eigengrasp grasp;
    grasp.line = eg->GetLineNum();
    const std::string what = "eigengrasp " + std::to_string(grasps.size() + 1);
    grasp.values = readDimVals(eg, dimensions, file, what);
    if (const XMLElement* value = eg->FirstChildElement("EigenValue")) {
      const char* text = value->Attribute("value");
      const auto number = text ? parseFiniteNumber(text) : std::nullopt;
      if (!number || *number < 0)
        throw InputError(file, lineOf(value) + " (" + what + ")", "EigenValue needs value=\"x\" with x >= 0");
      grasp.eigenvalue = *number;
      grasp.hasEigenvalue = true;
    }
    grasp.hasLimits = eg->FirstChildElement("Limits") != nullptr;
    if (grasp.values.norm() == 0) throw InputError(file, lineOf(eg) + " (" + what + ")", "an eigengrasp of all zeros");
    grasps.push_back(std::move(grasp));
  }
  if (grasps.empty()) throw InputError(file, lineOf(root), "no <EG> eigengrasps in the file");

  Eigen::VectorXd norm = Eigen::VectorXd::Ones(dimensions);
  if (const XMLElement* normElement = root->FirstChildElement("NORM")) {
    norm = readDimVals(normElement, dimensions, file, "NORM");
    for (int d = 0; d < dimensions; ++d)
      if (norm(d) == 0)
        throw InputError(file, lineOf(normElement) + " (NORM)", "normalisation factor d" + std::to_string(d) + " is 0");
  }

  SynergyModel& model = result.model;
  model.joints = handJoints;
  model.mean = Eigen::VectorXd::Constant(static_cast<Eigen::Index>(handJoints.size()), 0.5);
  if (const XMLElement* origin = root->FirstChildElement("ORIGIN")) {
    const Eigen::VectorXd values = readDimVals(origin, dimensions, file, "ORIGIN");
    for (int d = 0; d < dimensions; ++d) {
      const JointLimit& joint = handJoints[static_cast<std::size_t>(jointOf[static_cast<std::size_t>(d)])];
      const double unit = joint.normalise(values(d));
      if (unit < -1e-9 || unit > 1 + 1e-9)
        throw InputError(file, lineOf(origin->FirstChildElement("DimVals")) + " (ORIGIN.d" + std::to_string(d) + ")",
                         "origin " + exactNumberText(values(d)) + " rad is beyond the limits [" +
                             exactNumberText(joint.lower) + ", " + exactNumberText(joint.upper) + "] of " + joint.name);
      model.mean(jointOf[static_cast<std::size_t>(d)]) = std::clamp(unit, 0.0, 1.0);
    }
  } else {
    result.notes.push_back("the file has no <ORIGIN>: the mean posture is mid-range, as GraspIt does");
  }

  // Sort by eigenvalue (largest first), keeping the file's order among equals.
  std::vector<std::size_t> order(grasps.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return grasps[a].eigenvalue > grasps[b].eigenvalue; });
  if (!std::is_sorted(order.begin(), order.end()))
    result.notes.push_back("eigengrasps reordered by eigenvalue, largest first");

  const auto count = static_cast<Eigen::Index>(grasps.size());
  model.directions = Eigen::MatrixXd::Zero(model.jointCount(), count);
  model.sigma.resize(count);
  model.varianceFraction.resize(count);
  double eigenvalueSum = 0;
  for (const auto& grasp : grasps) eigenvalueSum += grasp.eigenvalue;
  std::vector<int> defaulted, limited;
  for (Eigen::Index k = 0; k < count; ++k) {
    const Eigengrasp& grasp = grasps[order[static_cast<std::size_t>(k)]];
    const int fileNumber = static_cast<int>(order[static_cast<std::size_t>(k)]) + 1;
    if (!grasp.hasEigenvalue) defaulted.push_back(fileNumber);
    if (grasp.hasLimits) limited.push_back(fileNumber);
    // GraspIt normalises each eigengrasp, then moves DOF d by norm[d] times the amplitude.
    const Eigen::VectorXd unitInFile = grasp.values.normalized();
    Eigen::VectorXd inJointUnits = Eigen::VectorXd::Zero(model.jointCount());
    for (int d = 0; d < dimensions; ++d) {
      const int j = jointOf[static_cast<std::size_t>(d)];
      inJointUnits(j) = norm(d) * unitInFile(d) / handJoints[static_cast<std::size_t>(j)].range();
    }
    const double length = inJointUnits.norm();
    if (length == 0) throw InputError(file, "line " + std::to_string(grasp.line), "an eigengrasp that moves no joint");
    model.directions.col(k) = inJointUnits / length;
    model.sigma(k) = std::sqrt(grasp.eigenvalue) * length;
    model.varianceFraction(k) = eigenvalueSum > 0 ? grasp.eigenvalue / eigenvalueSum : 0.0;
  }
  if (!defaulted.empty())
    result.notes.push_back("eigengrasps " + joinNumbers(defaulted) +
                           " have no <EigenValue>: GraspIt's default 0.5 used");
  if (!limited.empty())
    result.notes.push_back("amplitude <Limits> of eigengrasps " + joinNumbers(limited) +
                           " ignored: the planner's box half-widths are kappa * sigma");
  result.notes.push_back(
      "eigengrasps scaled from joint units (rad) to normalised joint units and normalised to unit length; "
      "sigma = sqrt(eigenvalue) * scaled length; variance fractions are shares of the file's eigenvalues");

  double worstCosine = 0;
  for (Eigen::Index a = 0; a < count; ++a)
    for (Eigen::Index b = 0; b < a; ++b)
      worstCosine = std::max(worstCosine, std::abs(model.directions.col(a).dot(model.directions.col(b))));
  model.orthonormal = worstCosine <= 1e-9;
  if (!model.orthonormal)
    result.notes.push_back("the directions are not orthogonal in normalised joint units (largest |cos| " +
                           exactNumberText(std::round(worstCosine * 1e4) / 1e4) +
                           "): the model is marked orthonormal: false and coefficients are found by least squares");

  std::vector<std::string> held;
  for (std::size_t j = 0; j < handJoints.size(); ++j)
    if (std::find(jointOf.begin(), jointOf.end(), static_cast<int>(j)) == jointOf.end())
      held.push_back(handJoints[j].name);
  if (!held.empty()) {
    std::string names;
    for (const auto& name : held) names += (names.empty() ? "" : ", ") + name;
    result.notes.push_back("joints no dimension drives are held at mid-range: " + names);
  }
  model.provenance = "GraspIt eigengrasps " + std::filesystem::path(file).filename().string() + " (" +
                     std::to_string(dimensions) + " dimensions, " + std::to_string(count) + " eigengrasps)";
  validateSynergyModel(model, file);
  return result;
}

GraspItImport importGraspItEigengrasps(const std::filesystem::path& path,
                                       const std::vector<std::string>& dimensionJoints, const JointLimits& handJoints) {
  return parseGraspItEigengrasps(readTextFile(path), path.string(), dimensionJoints, handJoints);
}

}  // namespace pmdplan
