// A task file; its robot is a built-in name or the URDF in the seed corpus' folder. A built-in robot
// is loaded once and kept (the urdf harness fuzzes robot files), so each input costs its own parse.
#include <map>
#include <string>

#include "fuzz_input.hpp"
#include "pmdplan/world/task.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static std::map<std::string, std::shared_ptr<const pmdplan::RobotModel>> robots;
  const auto builtIn = [](const std::string& name) {
    auto& robot = robots[name];
    if (!robot) robot = std::make_shared<const pmdplan::RobotModel>(pmdplan::RobotModel::loadBuiltIn(name));
    return robot;
  };
  const auto file = pmdplan::fuzz::writeScratch("task.yaml", pmdplan::fuzz::asText(data, size));
  return pmdplan::fuzz::expectAcceptedOrInputError([&] { pmdplan::loadTask(file, builtIn); });
}
