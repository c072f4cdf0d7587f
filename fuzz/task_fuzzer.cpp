// A task file; its robot is a built-in name or the URDF in the seed corpus' folder.
#include "fuzz_input.hpp"
#include "pmdplan/world/task.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = pmdplan::fuzz::writeScratch("task.yaml", pmdplan::fuzz::asText(data, size));
  return pmdplan::fuzz::expectAcceptedOrInputError([&] { pmdplan::loadTask(file); });
}
