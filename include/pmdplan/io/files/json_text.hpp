#pragma once
// Deterministic JSON text: keys in insertion order, numbers in their shortest exact form, arrays of
// plain values on one line, so equal documents always give equal bytes (nlohmann's own dump
// prints one number per line when indenting, and its float format is its own).
#include <nlohmann/json.hpp>
#include <string>

namespace pmdplan {

/// Two-space indentation, a final newline. Throws std::invalid_argument for non-finite numbers.
std::string formatJson(const nlohmann::ordered_json& document);

}  // namespace pmdplan
