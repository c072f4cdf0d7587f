// A joint-limits file (ours or MoveIt's joint_limits.yaml) for the built-in robot, which is loaded
// once and kept, so each input costs its own parse.
#include "fuzz_input.hpp"
#include "pmdplan/trajectory/joint_motion_limits.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const pmdplan::RobotModel robot = pmdplan::RobotModel::loadBuiltIn("sah_tx90");
  const auto file = pmdplan::fuzz::writeScratch("limits.yaml", pmdplan::fuzz::asText(data, size));
  return pmdplan::fuzz::expectAcceptedOrInputError([&] { pmdplan::jointMotionLimits(robot, file); });
}
