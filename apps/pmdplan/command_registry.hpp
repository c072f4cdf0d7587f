#pragma once
// Each subcommand lives in its own file and registers itself here with a static
// CommandRegistrar; main() only parses and dispatches. Exit codes: 0 done, 1 not solved,
// 2 bad input (an InputError or a CLI parse error), 3 internal error.
#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

namespace pmdplan::cli {

/// Called once with the subcommand to declare its options; returns the action run after parsing.
using CommandSetup = std::function<std::function<int()>(CLI::App& command)>;

struct CommandEntry {
  std::string name;
  std::string description;
  CommandSetup setup;
};

std::vector<CommandEntry>& commandRegistry();

/// For unsigned options (--seed): CLI11 would read "-1" as 2^64 - 1.
inline CLI::Validator wholeNumber() {
  return CLI::Validator(
      [](const std::string& text) {
        if (!text.empty() && text.find_first_not_of("0123456789") == std::string::npos) return std::string();
        return "expected a whole number >= 0, got '" + text + "'";
      },
      "UINT");
}

/// A whole number from `lowest` to `highest`, said in those words (CLI::PositiveNumber printed its
/// range as a 309-digit number).
inline CLI::Validator wholeNumberFrom(long long lowest, long long highest) {
  return CLI::Validator(
      [lowest, highest](const std::string& text) {
        const std::string expected =
            "expected a whole number from " + std::to_string(lowest) + " to " + std::to_string(highest);
        if (text.empty() || text.size() > 18 || text.find_first_not_of("0123456789") != std::string::npos)
          return expected;
        const long long value = std::stoll(text);
        return value >= lowest && value <= highest ? std::string() : expected;
      },
      "UINT");
}

struct CommandRegistrar {
  CommandRegistrar(std::string name, std::string description, CommandSetup setup) {
    commandRegistry().push_back({std::move(name), std::move(description), std::move(setup)});
  }
};

}  // namespace pmdplan::cli
