#pragma once
// Reading the `obstacles:` list of a task file. Internal to world/.
#include <filesystem>
#include <vector>

#include "pmdplan/text/yaml_field.hpp"
#include "pmdplan/world/task.hpp"

namespace pmdplan {

/// Every obstacle of the list, with unique names; relative mesh paths are resolved against
/// `taskDirectory` and must name an existing file.
std::vector<Obstacle> readObstacles(const YamlField& list, const std::filesystem::path& taskDirectory);

}  // namespace pmdplan
