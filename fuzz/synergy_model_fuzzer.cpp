#include "fuzz_input.hpp"
#include "pmdplan/synergy/synergy_model_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return pmdplan::fuzz::expectAcceptedOrInputError(
      [&] { pmdplan::parseSynergyModel(pmdplan::fuzz::asText(data, size), "fuzz.model.yaml"); });
}
