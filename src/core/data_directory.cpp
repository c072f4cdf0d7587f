#include "pmdplan/core/data_directory.hpp"

#include <cstdlib>

#include "pmdplan/core/input_error.hpp"

namespace pmdplan {

std::filesystem::path dataDirectory() {
  if (const char* env = std::getenv("PMDPLAN_DATA_DIR"); env && *env) return env;
  const std::filesystem::path source = PMDPLAN_SOURCE_DATA_DIR;
  if (std::filesystem::is_directory(source)) return source;
  return PMDPLAN_INSTALL_DATA_DIR;
}

std::filesystem::path resolveTaskPath(const std::string& nameOrPath) {
  const std::filesystem::path asPath = nameOrPath;
  if (asPath.has_extension() || asPath.has_parent_path()) {
    if (!std::filesystem::exists(asPath)) throw InputError(nameOrPath, "", "task file not found");
    return asPath;
  }
  const auto builtIn = dataDirectory() / "scenes" / (nameOrPath + ".yaml");
  if (!std::filesystem::exists(builtIn))
    throw InputError("", "task",
                     "'" + nameOrPath + "' is neither a built-in task (" + (dataDirectory() / "scenes").string() +
                         ") nor a task file");
  return builtIn;
}

}  // namespace pmdplan
