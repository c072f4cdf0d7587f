#include "pmdplan/io/viewer/robot_mimic.hpp"

namespace pmdplan {

std::vector<MimicRelation> mimicRelations(const RobotModel& model) {
  std::vector<MimicRelation> relations;
  const std::vector<Joint>& joints = model.joints();
  for (const Joint& joint : joints) {
    if (joint.mimicSource < 0) continue;
    relations.push_back({joint.name, joints[static_cast<std::size_t>(joint.mimicSource)].name, joint.mimicMultiplier,
                         joint.mimicOffset});
  }
  return relations;
}

}  // namespace pmdplan
