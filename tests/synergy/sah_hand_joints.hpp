#pragma once
// The SAH hand joints of the built-in sah_tx90 robot (docs/reference_data.md §1, positive flexion), built here so the
// synergy tests do not depend on the robot model.
#include <numbers>

#include "pmdplan/core/joint_limit.hpp"

namespace pmdplan::test {

inline JointLimits sahHandJoints() {
  constexpr double deg = std::numbers::pi / 180.0;
  JointLimits joints{{"thumb_base", 0, 90 * deg}};
  for (const char* finger : {"thumb", "index", "middle", "ring"}) {
    const std::string name = finger;
    if (name != "thumb")
      joints.push_back({name + "_abduction", -15 * deg, 15 * deg});
    else
      joints.push_back({"thumb_abduction", -15 * deg, 15 * deg});
    joints.push_back({name + "_proximal", -4 * deg, 75 * deg});
    joints.push_back({name + "_medium", 4 * deg, 75 * deg});
  }
  return joints;
}

}  // namespace pmdplan::test
