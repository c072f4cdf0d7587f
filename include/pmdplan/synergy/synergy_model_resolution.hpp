#pragma once
// Which synergy model a command uses for a robot, as one service for every front end (`pmdplan
// plan`, `view`, `glove stream`, Python's pmdplan.plan and pmdplan.human_likeness): the model file
// the user gave, else the robot's shipped model (data/synergies/<robot>_default.yaml), which some
// commands need and others only use when it is there.
#include <filesystem>
#include <optional>
#include <string>

#include "pmdplan/model/robot_model.hpp"
#include "pmdplan/synergy/synergy_model.hpp"

namespace pmdplan {

/// What a command does when no model is given and the robot ships none.
enum class SynergyModelNeed {
  Required,  ///< an InputError (field "--synergies") saying how to make a model or plan without one
  Optional,  ///< no model
};

/// A resolved synergy model and the file it was read from (messages name it).
struct ResolvedSynergyModel {
  std::optional<SynergyModel> model;  ///< nullopt only for SynergyModelNeed::Optional without a model
  std::filesystem::path file;         ///< empty when there is no model

  const SynergyModel* get() const { return model ? &*model : nullptr; }
};

/// The model for robot `robotName`: loadSynergyModel(`given`) (its errors name the file) when
/// `given` is not empty, otherwise the robot's shipped model if it has one; if not, `need` decides
/// (shippedSynergyModelPath's message for Required).
ResolvedSynergyModel resolveSynergyModel(const std::string& robotName, const std::filesystem::path& given,
                                         SynergyModelNeed need);

/// resolveSynergyModel for `robot`, and then, when there is a model, checkSynergyModelFitsHand
/// against the joints of the robot's "hand" group (synergy/hand_fit.hpp), naming the model's file:
/// what a planner that samples with the model needs before it runs.
ResolvedSynergyModel resolveSynergyModelForHand(const RobotModel& robot, const std::filesystem::path& given,
                                                SynergyModelNeed need);

}  // namespace pmdplan
