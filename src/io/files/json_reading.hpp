#pragma once
// Checked access to parsed JSON for the io readers: every mismatch is an InputError naming the
// file and the full key path ("points[2].positions").
#include <cstdint>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "pmdplan/core/message_text.hpp"

namespace pmdplan::json_reading {

/// Where a value sits: the file and the key path to it.
struct Place {
  const std::string& file;
  std::string field;

  /// A key from the file is shown as message_text.hpp's fieldKeyText shows it.
  Place key(const std::string& name) const {
    const std::string step = fieldKeyText(name);
    return {file, field.empty() ? step : field + "." + step};
  }
  Place index(std::size_t i) const { return {file, field + "[" + std::to_string(i) + "]"}; }
  [[noreturn]] void fail(const std::string& message) const;
};

/// The parsed document; InputError naming `file` for text that is not JSON (its line and column,
/// never the text there), holds a number no double holds (1e999) or repeats a key in one object
/// (json_repeated_keys.hpp).
nlohmann::json parseDocument(const std::string& text, const std::string& file);
const nlohmann::json& requireObject(const nlohmann::json& value, const Place& place);
const nlohmann::json& requireArray(const nlohmann::json& value, const Place& place);
/// Every key of `object` must be in `allowed`, and every key of `required` present.
void checkKeys(const nlohmann::json& object, const Place& place, const std::vector<const char*>& allowed,
               const std::vector<const char*>& required);
/// The member `name`, which checkKeys has made sure exists.
const nlohmann::json& member(const nlohmann::json& object, const char* name);

std::string readString(const nlohmann::json& value, const Place& place);
std::uint64_t readUnsigned(const nlohmann::json& value, const Place& place);
double readFinite(const nlohmann::json& value, const Place& place);

}  // namespace pmdplan::json_reading
