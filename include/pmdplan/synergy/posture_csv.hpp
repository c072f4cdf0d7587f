#pragma once
// Hand postures without a glove: a CSV whose header names hand joints and whose rows are postures
// (from a grasp database, a teleoperation log or hand-made key poses), in degrees by default.
#include <Eigen/Core>
#include <filesystem>

#include "pmdplan/core/joint_limit.hpp"

namespace pmdplan {

enum class PostureUnit { Degrees, Radians };

/// One row per posture, one column per joint of `hand` (rad), whatever the CSV's column order.
/// Every hand joint must have a column and every column must be a hand joint; values finite and
/// within the joint's limits (1e-9 rad slack). Blank lines and lines starting with '#' are
/// skipped. Throws InputError naming the file, the line (and column) and the expected form.
Eigen::MatrixXd readPostureCsv(const std::filesystem::path& file, const JointLimits& hand, PostureUnit unit);

}  // namespace pmdplan
