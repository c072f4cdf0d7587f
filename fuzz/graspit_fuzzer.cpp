// GraspIt eigengrasps for the built-in hand, the four dimensions of the test files.
#include "fuzz_input.hpp"
#include "pmdplan/model/robot_model.hpp"
#include "pmdplan/synergy/graspit_eigengrasp_import.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const pmdplan::JointLimits hand = pmdplan::RobotModel::loadBuiltIn("sah_tx90").groupJoints("hand");
  static const std::vector<std::string> joints{"thumb_base", "index_proximal", "middle_proximal", "ring_proximal"};
  return pmdplan::fuzz::expectAcceptedOrInputError(
      [&] { pmdplan::parseGraspItEigengrasps(pmdplan::fuzz::asText(data, size), "fuzz.xml", joints, hand); });
}
