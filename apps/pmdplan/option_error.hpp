#pragma once
// A command-line parse error from CLI11, written in the one form every pmdplan error has
// (docs/robustness.md): "<option>: <what was wrong; what was expected>" on one line, instead of
// CLI11's own texts ("Could not convert: --x = abc", "At Most 1 required but received 2").
#include <CLI/CLI.hpp>
#include <string>

namespace pmdplan::cli {

/// The line after "pmdplan: error: " for `error`, raised while `app` parsed the command line.
std::string optionErrorLine(const CLI::ParseError& error, const CLI::App& app);

}  // namespace pmdplan::cli
