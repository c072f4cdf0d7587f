#include "fuzz_input.hpp"
#include "pmdplan/io/files/path_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return pmdplan::fuzz::expectAcceptedOrInputError(
      [&] { pmdplan::parsePathFile(std::string(pmdplan::fuzz::asText(data, size)), "fuzz.path.json"); });
}
