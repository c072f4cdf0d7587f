// pmdplan: a thin shell over the library. Subcommands register themselves (command_registry.hpp).
#include <algorithm>
#include <cstdio>
#include <exception>
#include <iostream>

#include "command_registry.hpp"
#include "option_error.hpp"
#include "pmdplan/core/command_files.hpp"
#include "pmdplan/core/input_error.hpp"

namespace pmdplan::cli {
std::vector<CommandEntry>& commandRegistry() {
  static std::vector<CommandEntry> entries;
  return entries;
}
}  // namespace pmdplan::cli

int main(int argc, char** argv) {
  using namespace pmdplan::cli;
  CLI::App app{
      "pmdplan: human-like motion planning for robot hand-arm systems "
      "with principal motion directions"};
  app.require_subcommand(1);
  auto& entries = commandRegistry();
  std::sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
  std::vector<std::pair<CLI::App*, std::function<int()>>> actions;
  try {
    for (auto& entry : entries) {
      CLI::App* command = app.add_subcommand(entry.name, entry.description);
      actions.emplace_back(command, entry.setup(*command));
    }
  } catch (const std::exception& e) {
    std::cerr << "pmdplan: internal error while setting up commands: " << e.what() << "\n";
    return 3;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    std::cerr << "pmdplan: error: " << optionErrorLine(e, app) << "\n";
    return 2;
  }
  try {
    const pmdplan::CommandFileScope files;  // no output may replace an input or another output
    for (auto& [command, action] : actions)
      if (command->parsed()) return action();
  } catch (const pmdplan::InputError& e) {
    std::cerr << "pmdplan: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "pmdplan: internal error: " << e.what() << "\n";
    return 3;
  }
  return 0;
}
