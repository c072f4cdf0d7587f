#pragma once
// A named joint with its limits (SI units: rad or m). The shared vocabulary between the robot
// model and the layers that only need names and ranges (synergies, glove mapping).
#include <string>
#include <vector>

namespace pmdplan {

struct JointLimit {
  std::string name;
  double lower = 0.0;
  double upper = 0.0;

  double range() const { return upper - lower; }
  double normalise(double value) const { return (value - lower) / range(); }
  double denormalise(double unit) const { return lower + unit * range(); }
};

using JointLimits = std::vector<JointLimit>;

}  // namespace pmdplan
