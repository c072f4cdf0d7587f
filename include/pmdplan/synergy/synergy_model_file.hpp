#pragma once
// Synergy model files (YAML): the joints with their limits (rad), the own-axis joints, the mean
// posture b and the directions with their sigma and variance fraction, all in normalised units.
// Numbers are written in their shortest exact form, so a file loads back to identical values.
#include <filesystem>
#include <string>
#include <string_view>

#include "pmdplan/synergy/synergy_model.hpp"

namespace pmdplan {

/// Throws InputError naming the file, line and key for malformed content: sizes that disagree,
/// a mean outside [0, 1], negative sigma, an own-axis joint with a component in a direction, and
/// directions that are not orthonormal in a file that says `orthonormal: true` (or that are
/// linearly dependent in any file).
SynergyModel loadSynergyModel(const std::filesystem::path& path);
SynergyModel parseSynergyModel(std::string_view text, const std::string& sourceName);

std::string formatSynergyModel(const SynergyModel& model);
void saveSynergyModel(const std::filesystem::path& path, const SynergyModel& model);

/// The same checks loadSynergyModel() applies, for models built in code; throws InputError
/// naming `sourceName`.
void validateSynergyModel(const SynergyModel& model, const std::string& sourceName);

/// data/synergies/<robot>_default.yaml.
std::filesystem::path defaultSynergyModelPath(const std::string& robotName);
/// The same, which must exist: otherwise InputError naming --synergies with how to make a model.
std::filesystem::path shippedSynergyModelPath(const std::string& robotName);

}  // namespace pmdplan
