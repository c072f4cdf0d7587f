// A posture CSV (`pmdplan synergies --postures`) for the built-in hand, in degrees (the default),
// through a file, as the command reads it.
#include "fuzz_input.hpp"
#include "pmdplan/model/robot_model.hpp"
#include "pmdplan/synergy/posture_csv.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const pmdplan::JointLimits hand = pmdplan::RobotModel::loadBuiltIn("sah_tx90").groupJoints("hand");
  const auto file = pmdplan::fuzz::writeScratch("postures.csv", pmdplan::fuzz::asText(data, size));
  return pmdplan::fuzz::expectAcceptedOrInputError(
      [&] { pmdplan::readPostureCsv(file, hand, pmdplan::PostureUnit::Degrees); });
}
