#pragma once
// From calibrated glove sensors to robot-hand joints: each joint is a linear function of one or
// more sensor angles, or a constant. The paper's Table 1 is data/glove/cyberglove22_to_sah.yaml.
// Values beyond a joint limit are clamped to it and counted.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "pmdplan/core/joint_limit.hpp"

namespace pmdplan {

struct SensorTerm {
  int sensor = 0;     ///< index in cyberGloveSensorNames()
  double gain = 0.0;  ///< joint rad per sensor rad
};

/// joint = offset + sum of gain * angle(sensor); a constant joint has no terms.
struct JointRule {
  std::string joint;
  std::vector<SensorTerm> terms;
  double offset = 0.0;  ///< rad (the value itself for a constant joint)
  int sourceLine = 0;   ///< line in the mapping file, for messages (0 if not from a file)

  bool isConstant() const { return terms.empty(); }
};

/// Where a rule is, for the InputError field: "line N (joint NAME)", or "joint NAME" for a rule
/// not read from a file.
std::string jointRuleField(const JointRule& rule);

struct HandMapping {
  std::vector<JointRule> rules;
  std::string description;
  std::string sourceFile;  ///< for messages
};

struct MappedPostures {
  /// One row per frame, one column per robot hand joint (in the order given), rad, within limits.
  Eigen::MatrixXd postures;
  /// How many joint values were beyond a limit and clamped, in all and per joint.
  long long clampedValues = 0;
  std::vector<long long> clampedPerJoint;
};

/// The rule for each of `handJoints`, in that order (pointers into `mapping`). Throws InputError naming the mapping
/// file and line for a rule about a joint the robot does not have, a joint without a rule or with two, and a constant
/// outside the joint's limits.
std::vector<const JointRule*> rulesForJoints(const HandMapping& mapping, const JointLimits& handJoints);

/// Maps calibrated sensor angles (one row per frame, 22 columns, rad) to the robot hand joints.
MappedPostures mapToJoints(const Eigen::MatrixXd& sensorAngles, const HandMapping& mapping,
                           const JointLimits& handJoints);

}  // namespace pmdplan
