#include "fuzz_input.hpp"
#include "pmdplan/synergy/hand_mapping_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return pmdplan::fuzz::expectAcceptedOrInputError(
      [&] { pmdplan::parseHandMapping(pmdplan::fuzz::asText(data, size), "fuzz.mapping.yaml"); });
}
