#pragma once
// `pmdplan glove stream`: declared on the `glove` command by glove_command.cpp.
#include <CLI/CLI.hpp>
#include <functional>

namespace pmdplan::cli {

/// Adds the `stream` subcommand to `glove` and returns its action.
std::function<int()> addGloveStreamCommand(CLI::App& glove);

}  // namespace pmdplan::cli
