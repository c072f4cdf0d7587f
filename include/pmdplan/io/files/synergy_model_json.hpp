#pragma once
// A synergy model as JSON, the form `pmdplan synergies --json` prints (under "model" for a fit):
// {model_joint_names, own_axis_joints, orthonormal, mean, directions (one list per PMD), sigma,
// variance_fraction, provenance}; normalised joint units, as in the model file.
#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "pmdplan/synergy/synergy_model.hpp"

namespace pmdplan {

/// [v0, v1, ...].
nlohmann::json numberListJson(const Eigen::VectorXd& values);

nlohmann::json synergyModelJson(const SynergyModel& model);

}  // namespace pmdplan
