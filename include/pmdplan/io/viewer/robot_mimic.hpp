#pragma once
// The mimic table of a path file, from a robot model's coupled joints.
#include <vector>

#include "pmdplan/io/files/path_file.hpp"
#include "pmdplan/model/robot_model.hpp"

namespace pmdplan {

/// One entry per mimic joint, in the model's joint order.
std::vector<MimicRelation> mimicRelations(const RobotModel& model);

}  // namespace pmdplan
