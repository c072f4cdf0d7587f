// A URDF and its SRDF in one input: the bytes before the first "</robot>" end the URDF (with it),
// the rest is the SRDF (none when empty).
#include "fuzz_input.hpp"
#include "pmdplan/model/robot_model.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text = pmdplan::fuzz::asText(data, size);
  constexpr std::string_view end = "</robot>";
  const auto split = text.find(end);
  const std::string_view urdf = split == std::string_view::npos ? text : text.substr(0, split + end.size());
  const std::string_view srdf = split == std::string_view::npos ? std::string_view() : text.substr(split + end.size());
  const auto urdfFile = pmdplan::fuzz::writeScratch("robot.urdf", urdf);
  std::optional<std::filesystem::path> srdfFile;
  if (!srdf.empty()) srdfFile = pmdplan::fuzz::writeScratch("robot.srdf", srdf);
  return pmdplan::fuzz::expectAcceptedOrInputError([&] { pmdplan::RobotModel::load(urdfFile, srdfFile); });
}
