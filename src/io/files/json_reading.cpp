#include "json_reading.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "pmdplan/core/input_error.hpp"
#include "pmdplan/io/files/json_repeated_keys.hpp"

namespace pmdplan::json_reading {
namespace {

std::string typeName(const nlohmann::json& value) {
  if (value.is_number()) return "a number";
  if (value.is_string()) return "a string";
  if (value.is_array()) return "an array";
  if (value.is_object()) return "an object";
  if (value.is_boolean()) return "a boolean";
  return "null";
}

/// nlohmann's message without the text it read ("...; last read: 'TEXT'", "number overflow parsing
/// 'TEXT'"): its own words and the line and column, never the file's contents.
std::string withoutQuotedText(const std::string& message) {
  for (const char* marker : {"; last read: '", " parsing '"}) {
    const std::size_t at = message.find(marker);
    if (at != std::string::npos) return message.substr(0, at);
  }
  return message;
}

}  // namespace

void Place::fail(const std::string& message) const { throw InputError(file, field, message); }

const nlohmann::json& requireObject(const nlohmann::json& value, const Place& place) {
  if (!value.is_object()) place.fail("expected an object, found " + typeName(value));
  return value;
}

const nlohmann::json& requireArray(const nlohmann::json& value, const Place& place) {
  if (!value.is_array()) place.fail("expected an array, found " + typeName(value));
  return value;
}

void checkKeys(const nlohmann::json& object, const Place& place, const std::vector<const char*>& allowed,
               const std::vector<const char*>& required) {
  for (auto item = object.begin(); item != object.end(); ++item) {
    const bool known =
        std::any_of(allowed.begin(), allowed.end(), [&](const char* name) { return item.key() == name; });
    if (!known) {
      std::string expected;
      for (const char* name : allowed) {
        if (!expected.empty()) expected += ", ";
        expected += name;
      }
      place.key(item.key()).fail("unknown key; expected only " + expected);
    }
  }
  for (const char* name : required)
    if (!object.contains(name)) place.key(name).fail("missing");
}

const nlohmann::json& member(const nlohmann::json& object, const char* name) { return object.at(name); }

std::string readString(const nlohmann::json& value, const Place& place) {
  if (!value.is_string()) place.fail("expected a string, found " + typeName(value));
  return value.get<std::string>();
}

std::uint64_t readUnsigned(const nlohmann::json& value, const Place& place) {
  if (!value.is_number_unsigned())
    place.fail("expected a whole number >= 0, found " + (value.is_number() ? value.dump() : typeName(value)));
  return value.get<std::uint64_t>();
}

nlohmann::json parseDocument(const std::string& text, const std::string& file) {
  try {
    return nlohmann::json::parse(text, refuseRepeatedJsonKeys(file));
  } catch (const nlohmann::json::parse_error& error) {
    throw InputError(file, "", "not valid JSON (" + withoutQuotedText(error.what()) + ")");
  } catch (const nlohmann::json::out_of_range& error) {
    // A number no double holds (1e999): the parser stops at it.
    throw InputError(file, "",
                     "a number is out of range; expected finite numbers (" + withoutQuotedText(error.what()) + ")");
  }
}

double readFinite(const nlohmann::json& value, const Place& place) {
  if (!value.is_number()) place.fail("expected a number, found " + typeName(value));
  const double number = value.get<double>();
  if (!std::isfinite(number)) place.fail("expected a finite number");
  return number;
}

}  // namespace pmdplan::json_reading
