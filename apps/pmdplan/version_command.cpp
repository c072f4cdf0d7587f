// `pmdplan version`: the program's version.
#include <iostream>

#include "command_registry.hpp"

namespace pmdplan::cli::version_command {
namespace {
const CommandRegistrar registrar{"version", "Print the pmdplan version", [](CLI::App&) {
                                   return [] {
                                     std::cout << "pmdplan 0.1.0\n";
                                     return 0;
                                   };
                                 }};
}  // namespace
}  // namespace pmdplan::cli::version_command
