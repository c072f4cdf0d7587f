#include "pmdplan/synergy/synergy_model_file.hpp"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <functional>

#include "pmdplan/core/atomic_file.hpp"
#include "pmdplan/core/data_directory.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/core/message_text.hpp"
#include "pmdplan/text/number_text.hpp"
#include "pmdplan/text/yaml_field.hpp"
#include "pmdplan/text/yaml_writing.hpp"

namespace pmdplan {
namespace {

constexpr std::string_view kFormat = "pmdplan-synergy-model";
constexpr double kUnitTolerance = 1e-6;  // file values are rounded; orthonormality to 1e-6 is exact enough

enum class Part { Joints, Mean, OwnAxis, Direction };
/// Names where a part of the model is: "directions[1] (line 12)" for a file, "directions[1]" otherwise.
using Locate = std::function<std::string(Part, int)>;

std::string defaultLocation(Part part, int index) {
  switch (part) {
    case Part::Joints:
      return "joints";
    case Part::Mean:
      return "mean";
    case Part::OwnAxis:
      return "own_axis_joints";
    case Part::Direction:
      return "directions[" + std::to_string(index) + "]";
  }
  return {};
}

void validate(const SynergyModel& model, const std::string& source, const Locate& at) {
  const auto n = model.jointCount();
  if (n == 0) throw InputError(source, at(Part::Joints, 0), "the model covers no joints");
  for (int j = 0; j < n; ++j) {
    const JointLimit& joint = model.joints[static_cast<std::size_t>(j)];
    if (joint.name.empty()) throw InputError(source, at(Part::Joints, j), "a joint without a name");
    if (!(joint.lower < joint.upper))
      throw InputError(source, at(Part::Joints, j),
                       "joint " + fieldKeyText(joint.name) + ": lower must be below upper");
    for (int k = 0; k < j; ++k)
      if (model.joints[static_cast<std::size_t>(k)].name == joint.name)
        throw InputError(source, at(Part::Joints, j), "joint " + fieldKeyText(joint.name) + " listed twice");
  }
  if (model.mean.size() != n)
    throw InputError(source, at(Part::Mean, 0),
                     "mean has " + std::to_string(model.mean.size()) + " values for " + std::to_string(n) + " joints");
  for (int j = 0; j < n; ++j)
    if (!(model.mean(j) >= -1e-9 && model.mean(j) <= 1 + 1e-9))
      throw InputError(source, at(Part::Mean, 0),
                       "mean of " + model.joints[static_cast<std::size_t>(j)].name + " is " +
                           exactNumberText(model.mean(j)) + "; normalised values lie in [0, 1]");
  std::vector<int> ownAxis;
  for (const auto& name : model.ownAxisJoints) {
    const int index = model.jointIndex(name);
    if (index < 0)
      throw InputError(source, at(Part::OwnAxis, 0), "own-axis joint " + quotedText(name) + " is not among the joints");
    ownAxis.push_back(index);
  }
  const auto d = model.directionCount();
  if (model.directions.rows() != n && d > 0)
    throw InputError(source, at(Part::Direction, 0), "directions need one value per joint");
  if (d == 0 && ownAxis.empty()) throw InputError(source, at(Part::Direction, 0), "the model has no directions");
  if (model.sigma.size() != d || model.varianceFraction.size() != d)
    throw InputError(source, at(Part::Direction, 0), "every direction needs a sigma and a variance fraction");
  for (int k = 0; k < d; ++k) {
    if (!(model.sigma(k) >= 0)) throw InputError(source, at(Part::Direction, k), "sigma must be zero or positive");
    if (!(model.varianceFraction(k) >= 0 && model.varianceFraction(k) <= 1 + 1e-9))
      throw InputError(source, at(Part::Direction, k), "variance_fraction must lie in [0, 1]");
    const double length = model.directions.col(k).norm();
    if (std::abs(length - 1) > kUnitTolerance)
      throw InputError(source, at(Part::Direction, k),
                       "direction " + std::to_string(k + 1) + " has length " + exactNumberText(length) +
                           "; directions must be unit vectors");
    for (const int j : ownAxis)
      if (std::abs(model.directions(j, k)) > 1e-9)
        throw InputError(source, at(Part::Direction, k),
                         "direction " + std::to_string(k + 1) + " moves own-axis joint " +
                             model.joints[static_cast<std::size_t>(j)].name +
                             "; own-axis joints stay out of the directions");
  }
  if (d == 0) return;
  if (model.orthonormal) {
    for (int a = 0; a < d; ++a)
      for (int b = 0; b < a; ++b) {
        const double dot = model.directions.col(a).dot(model.directions.col(b));
        if (std::abs(dot) > kUnitTolerance)
          throw InputError(source, at(Part::Direction, a),
                           "directions " + std::to_string(b + 1) + " and " + std::to_string(a + 1) +
                               " are not orthonormal (dot product " + exactNumberText(dot) +
                               "); the model says orthonormal: true — fix the vectors, or set orthonormal: false "
                               "to use them as a non-orthogonal basis (coefficients by least squares)");
      }
    return;
  }
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(model.directions);
  if (svd.singularValues().minCoeff() < 1e-9)
    throw InputError(source, at(Part::Direction, 0),
                     "the directions are linearly dependent; a basis needs independent directions");
}

Eigen::VectorXd numberList(const YamlField& field, const std::string& expected) {
  const std::vector<YamlField> items = field.elements("a list of " + expected);
  Eigen::VectorXd values(static_cast<Eigen::Index>(items.size()));
  for (std::size_t i = 0; i < items.size(); ++i) values(static_cast<Eigen::Index>(i)) = items[i].number(expected);
  return values;
}

std::string numberListText(const Eigen::VectorXd& values) {
  std::string text = "[";
  for (Eigen::Index i = 0; i < values.size(); ++i) text += (i ? ", " : "") + exactNumberText(values(i));
  return text + "]";
}

}  // namespace

void validateSynergyModel(const SynergyModel& model, const std::string& sourceName) {
  validate(model, sourceName, &defaultLocation);
}

SynergyModel parseSynergyModel(std::string_view text, const std::string& file) {
  const YamlField root = parseYamlFile(
      text, file, kFormat,
      {"format", "version", "provenance", "joints", "own_axis_joints", "orthonormal", "mean", "directions"},
      "a synergy model");
  SynergyModel model;
  if (const auto provenance = root.optionalChild("provenance"))
    model.provenance = provenance->text("a provenance text");

  const YamlField jointList = root.child("joints", "a list of {name, lower, upper}");
  const std::vector<YamlField> joints = jointList.elements("a list of joints");
  for (const YamlField& joint : joints) {
    joint.requireMapWithKeys({"name", "lower", "upper"}, "{name, lower, upper}");
    model.joints.push_back({joint.child("name", "a joint name").text("a joint name"),
                            joint.child("lower", "a lower limit in rad").number("a lower limit in rad"),
                            joint.child("upper", "an upper limit in rad").number("an upper limit in rad")});
  }
  const std::optional<YamlField> ownAxis = root.optionalChild("own_axis_joints");
  if (ownAxis && !ownAxis->node().IsNull())
    for (const YamlField& name : ownAxis->elements("a list of joint names"))
      model.ownAxisJoints.push_back(name.text("a joint name"));
  if (const auto orthonormal = root.optionalChild("orthonormal"))
    model.orthonormal = orthonormal->boolean("orthonormal");
  const YamlField mean = root.child("mean", "a list of normalised joint values");
  model.mean = numberList(mean, "normalised joint values");

  const YamlField directionList = root.child("directions", "a list of {sigma, variance_fraction, vector}");
  const std::vector<YamlField> directions = directionList.elements("a list of directions");
  const auto count = static_cast<Eigen::Index>(directions.size());
  model.directions = Eigen::MatrixXd::Zero(model.jointCount(), count);
  model.sigma.resize(count);
  model.varianceFraction.resize(count);
  for (Eigen::Index k = 0; k < count; ++k) {
    const YamlField& direction = directions[static_cast<std::size_t>(k)];
    direction.requireMapWithKeys({"sigma", "variance_fraction", "vector"}, "{sigma, variance_fraction, vector}");
    model.sigma(k) = direction.child("sigma", "a standard deviation").number("a standard deviation");
    model.varianceFraction(k) =
        direction.child("variance_fraction", "a fraction of the variance").number("a fraction of the variance");
    const YamlField vector = direction.child("vector", "a list of one value per joint");
    const Eigen::VectorXd values = numberList(vector, "values");
    if (values.size() != model.jointCount())
      vector.fail(std::to_string(values.size()) + " values for " + std::to_string(model.jointCount()) + " joints");
    model.directions.col(k) = values;
  }

  const auto item = [](const std::vector<YamlField>& items, const YamlField& list, int index) {
    return static_cast<std::size_t>(index) < items.size() ? items[static_cast<std::size_t>(index)].location()
                                                          : list.location();
  };
  validate(model, file, [&](Part part, int index) {
    switch (part) {
      case Part::Joints:
        return item(joints, jointList, index);
      case Part::Mean:
        return mean.location();
      case Part::OwnAxis:
        if (ownAxis) return ownAxis->location();
        break;
      case Part::Direction:
        return item(directions, directionList, index);
    }
    return defaultLocation(part, index);
  });
  return model;
}

SynergyModel loadSynergyModel(const std::filesystem::path& path) {
  return parseSynergyModel(readTextFile(path), path.string());
}

std::string formatSynergyModel(const SynergyModel& model) {
  std::string text =
      yamlFileHeader({"Principal motion directions of a robot hand (pmdplan synergy model). Joint limits in rad;",
                      "mean, vectors and sigma in joint values normalised to [0, 1] by those limits. Own-axis joints",
                      "are sampled over their whole range; along direction i the planner's box half-width is",
                      "lambda_i = kappa * sigma_i."},
                     kFormat, "provenance", model.provenance);
  text += "joints:\n";
  for (const JointLimit& joint : model.joints)
    text += "  - {name: " + joint.name + ", lower: " + exactNumberText(joint.lower) +
            ", upper: " + exactNumberText(joint.upper) + "}\n";
  text += "own_axis_joints: [";
  for (std::size_t i = 0; i < model.ownAxisJoints.size(); ++i) text += (i ? ", " : "") + model.ownAxisJoints[i];
  text += "]\n";
  text += std::string("orthonormal: ") + (model.orthonormal ? "true" : "false") + "\n";
  text += "mean: " + numberListText(model.mean) + "\n";
  text += "directions:\n";
  for (int k = 0; k < model.directionCount(); ++k)
    text += "  - {sigma: " + exactNumberText(model.sigma(k)) +
            ", variance_fraction: " + exactNumberText(model.varianceFraction(k)) +
            ",\n     vector: " + numberListText(model.directions.col(k)) + "}\n";
  return text;
}

void saveSynergyModel(const std::filesystem::path& path, const SynergyModel& model) {
  validateSynergyModel(model, path.string());
  writeFileAtomically(path, formatSynergyModel(model));
}

std::filesystem::path defaultSynergyModelPath(const std::string& robotName) {
  return dataDirectory() / "synergies" / (robotName + "_default.yaml");
}

std::filesystem::path shippedSynergyModelPath(const std::string& robotName) {
  const auto path = defaultSynergyModelPath(robotName);
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error))
    throw InputError(
        "", "--synergies",
        "robot '" + robotName + "' has no shipped synergy model (no " + path.string() +
            "): make one with `pmdplan synergies --postures POSTURES.csv --robot URDF -o MODEL.yaml` and pass "
            "--synergies MODEL.yaml, or plan without synergies with --planner full");
  return path;
}

}  // namespace pmdplan
