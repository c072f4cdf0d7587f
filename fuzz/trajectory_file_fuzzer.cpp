// A trajectory file (`pmdplan plan --trajectory`, `pmdplan time`) as `pmdplan view` reads it: the
// format test, the parser and the conversion to the path it shows. The parser is called on every
// input, not only on those the format test accepts, so mutations of any field reach it.
#include "fuzz_input.hpp"
#include "pmdplan/io/files/trajectory_file.hpp"
#include "pmdplan/io/viewer/viewer_data.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(pmdplan::fuzz::asText(data, size));
  pmdplan::isTrajectoryFileText(text);
  return pmdplan::fuzz::expectAcceptedOrInputError(
      [&] { pmdplan::trajectoryAsPathFile(pmdplan::parseTrajectoryFile(text, "fuzz.trajectory.json")); });
}
