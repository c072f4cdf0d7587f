#include "pmdplan/text/yaml_writing.hpp"

namespace pmdplan {

std::string yamlQuoted(std::string_view value) {
  std::string out = "\"";
  for (const char c : value) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\t':
        out += "\\t";
        break;
      default:
        out += c;
    }
  }
  return out + "\"";
}

std::string yamlFileHeader(std::initializer_list<std::string_view> commentLines, std::string_view format,
                           std::string_view describingKey, std::string_view describingValue) {
  std::string text;
  for (const std::string_view line : commentLines) {
    text += "# ";
    text += line;
    text += '\n';
  }
  text += "format: " + std::string(format) + "\nversion: 1\n";
  text += std::string(describingKey) + ": " + yamlQuoted(describingValue) + "\n";
  return text;
}

}  // namespace pmdplan
