#pragma once
// Where the built-in robots, tasks and synergy models live: $PMDPLAN_DATA_DIR if set, else the
// source tree's data/ (a build used in place), else the installed share/pmdplan/data.
#include <filesystem>
#include <string>

namespace pmdplan {

std::filesystem::path dataDirectory();

/// A built-in task name (`can_on_table`) or a path to a task file.
std::filesystem::path resolveTaskPath(const std::string& nameOrPath);

}  // namespace pmdplan
