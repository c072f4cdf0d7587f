#pragma once
// A configuration: one value per active joint (radians or metres), arm first then hand, in the
// order RobotModel::activeJoints() defines. Mimic joints are derived, never stored.
#include <Eigen/Core>

namespace pmdplan {
using Configuration = Eigen::VectorXd;
}  // namespace pmdplan
