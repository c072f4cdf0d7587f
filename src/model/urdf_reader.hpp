#pragma once
// Internal: fills a RobotModel from a URDF file (urdfdom) and its SRDF-style companion (tinyxml2).
#include <filesystem>
#include <optional>

#include "pmdplan/model/robot_model.hpp"

namespace pmdplan {

class RobotModelBuilder {
 public:
  static RobotModel build(const std::filesystem::path& urdf, const std::optional<std::filesystem::path>& srdf);
  /// The configuration layout and the groups' active indices again, after joints became fixed.
  static void reassignActiveOrder(RobotModel& model);

 private:
  static void readUrdf(RobotModel& model, const std::filesystem::path& urdf);
  static void resolveMimics(RobotModel& model);
  static void readSrdf(RobotModel& model, const std::filesystem::path& srdf);
  static void assignActiveOrder(RobotModel& model);
};

}  // namespace pmdplan
