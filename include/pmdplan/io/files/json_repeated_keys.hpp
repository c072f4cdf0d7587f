#pragma once
// JSON objects with a key given twice: nlohmann's parser keeps the last value and says nothing,
// so a file could say one thing to a person reading its top and another to pmdplan. Parsing with
// this callback refuses them instead.
#include <nlohmann/json.hpp>
#include <string>

namespace pmdplan {

/// A parser callback for nlohmann::json::parse(text, callback, ...) that throws
/// InputError(file, field, "given twice ...") at the second occurrence of a key in one object;
/// field is `where` (e.g. "line 3"; may be empty) followed by the key's path ("points[2].time").
nlohmann::json::parser_callback_t refuseRepeatedJsonKeys(const std::string& file, const std::string& where = "");

}  // namespace pmdplan
