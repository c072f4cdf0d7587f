#include "fuzz_input.hpp"
#include "pmdplan/glove/glove_calibration_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return pmdplan::fuzz::expectAcceptedOrInputError(
      [&] { pmdplan::parseGloveCalibration(pmdplan::fuzz::asText(data, size), "fuzz.calibration.yaml"); });
}
