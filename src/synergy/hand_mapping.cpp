#include "pmdplan/synergy/hand_mapping.hpp"

#include <algorithm>

#include "pmdplan/core/input_error.hpp"
#include "pmdplan/core/message_text.hpp"
#include "pmdplan/glove/cyberglove_sensors.hpp"
#include "pmdplan/text/number_text.hpp"

namespace pmdplan {
std::string jointRuleField(const JointRule& rule) {
  const std::string joint = fieldKeyText(rule.joint);  // a key of the mapping file
  return rule.sourceLine > 0 ? "line " + std::to_string(rule.sourceLine) + " (joint " + joint + ")" : "joint " + joint;
}

std::vector<const JointRule*> rulesForJoints(const HandMapping& mapping, const JointLimits& handJoints) {
  std::vector<const JointRule*> rules(handJoints.size(), nullptr);
  for (const JointRule& rule : mapping.rules) {
    const auto joint = std::find_if(handJoints.begin(), handJoints.end(),
                                    [&](const JointLimit& limit) { return limit.name == rule.joint; });
    if (joint == handJoints.end()) {
      std::string names;
      for (const auto& limit : handJoints) names += (names.empty() ? "" : ", ") + limit.name;
      throw InputError(mapping.sourceFile, jointRuleField(rule),
                       "unknown joint " + quotedText(rule.joint) + "; the robot's hand joints are " + names);
    }
    const auto index = static_cast<std::size_t>(joint - handJoints.begin());
    if (rules[index] != nullptr)
      throw InputError(mapping.sourceFile, jointRuleField(rule), "a second rule for joint " + fieldKeyText(rule.joint));
    if (rule.isConstant() && (rule.offset < joint->lower || rule.offset > joint->upper))
      throw InputError(mapping.sourceFile, jointRuleField(rule),
                       "constant " + exactNumberText(rule.offset) + " rad is outside the joint's limits [" +
                           exactNumberText(joint->lower) + ", " + exactNumberText(joint->upper) + "] rad");
    for (const SensorTerm& term : rule.terms)
      if (term.sensor < 0 || term.sensor >= kCyberGloveSensorCount)
        throw InputError(mapping.sourceFile, jointRuleField(rule), "sensor index out of range");
    rules[index] = &rule;
  }
  for (std::size_t j = 0; j < rules.size(); ++j)
    if (rules[j] == nullptr)
      throw InputError(mapping.sourceFile, "joints",
                       "no rule for the robot's hand joint " + handJoints[j].name + " (give it sensors or a constant)");
  return rules;
}

MappedPostures mapToJoints(const Eigen::MatrixXd& sensorAngles, const HandMapping& mapping,
                           const JointLimits& handJoints) {
  const auto rules = rulesForJoints(mapping, handJoints);
  const auto frames = sensorAngles.rows();
  MappedPostures result;
  result.postures.resize(frames, static_cast<Eigen::Index>(handJoints.size()));
  result.clampedPerJoint.assign(handJoints.size(), 0);
  for (std::size_t j = 0; j < handJoints.size(); ++j) {
    const JointRule& rule = *rules[j];
    const JointLimit& limit = handJoints[j];
    auto column = result.postures.col(static_cast<Eigen::Index>(j));
    column.setConstant(rule.offset);
    for (const SensorTerm& term : rule.terms) column += term.gain * sensorAngles.col(term.sensor);
    for (Eigen::Index f = 0; f < frames; ++f) {
      double& value = column(f);
      if (value < limit.lower || value > limit.upper) {
        value = std::clamp(value, limit.lower, limit.upper);
        ++result.clampedPerJoint[j];
      }
    }
    result.clampedValues += result.clampedPerJoint[j];
  }
  return result;
}

}  // namespace pmdplan
