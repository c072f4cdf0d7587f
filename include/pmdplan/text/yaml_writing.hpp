#pragma once
// Writing our YAML files: the header every one of them opens with, and quoted strings.
#include <initializer_list>
#include <string>
#include <string_view>

namespace pmdplan {

/// A double-quoted YAML string with the characters YAML needs escaped.
std::string yamlQuoted(std::string_view value);

/// The opening of one of our YAML files: each comment line after "# ", then `format: <format>`,
/// `version: 1` and `<describingKey>: <describingValue quoted>` ("description", "provenance").
std::string yamlFileHeader(std::initializer_list<std::string_view> commentLines, std::string_view format,
                           std::string_view describingKey, std::string_view describingValue);

}  // namespace pmdplan
