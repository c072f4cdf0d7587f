#include "fuzz_input.hpp"
#include "pmdplan/glove/glove_csv.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return pmdplan::fuzz::expectAcceptedOrInputError(
      [&] { pmdplan::parseGloveCsv(pmdplan::fuzz::asText(data, size), "fuzz.csv"); });
}
