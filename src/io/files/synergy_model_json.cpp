#include "pmdplan/io/files/synergy_model_json.hpp"

namespace pmdplan {

nlohmann::json numberListJson(const Eigen::VectorXd& values) {
  auto list = nlohmann::json::array();
  for (Eigen::Index i = 0; i < values.size(); ++i) list.push_back(values(i));
  return list;
}

nlohmann::json synergyModelJson(const SynergyModel& model) {
  nlohmann::json joints = nlohmann::json::array();
  for (const auto& joint : model.joints) joints.push_back(joint.name);
  nlohmann::json directions = nlohmann::json::array();
  for (int k = 0; k < model.directionCount(); ++k) directions.push_back(numberListJson(model.directions.col(k)));
  return {{"model_joint_names", joints},
          {"own_axis_joints", model.ownAxisJoints},
          {"orthonormal", model.orthonormal},
          {"mean", numberListJson(model.mean)},
          {"directions", directions},
          {"sigma", numberListJson(model.sigma)},
          {"variance_fraction", numberListJson(model.varianceFraction)},
          {"provenance", model.provenance}};
}

}  // namespace pmdplan
