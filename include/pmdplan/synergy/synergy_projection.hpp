#pragma once
// Between normalised hand postures and coefficients along a model's directions. An orthonormal
// model projects with D^T; a non-orthogonal (imported) basis by least squares, so both work.
#include <Eigen/Core>

#include "pmdplan/synergy/synergy_model.hpp"

namespace pmdplan {

/// s minimising |D s - (p - b)| for a normalised posture p (exactly D^T (p - b) when orthonormal).
Eigen::VectorXd synergyCoefficients(const SynergyModel& model, const Eigen::VectorXd& normalisedPosture);

/// b + D s (normalised units, not clamped). `coefficients` may be shorter than the number of
/// directions: the first ones are used.
Eigen::VectorXd postureFromCoefficients(const SynergyModel& model, const Eigen::VectorXd& coefficients);

}  // namespace pmdplan
