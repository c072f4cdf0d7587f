#include "pmdplan/text/yaml_input.hpp"

#include <algorithm>
#include <vector>

#include "pmdplan/core/input_error.hpp"
#include "pmdplan/text/number_text.hpp"
#include "pmdplan/text/yaml_field.hpp"

namespace pmdplan::yaml_input {
namespace {
std::string where(const std::string& context) { return context.empty() ? "" : " (" + context + ")"; }
}  // namespace

YAML::Node parseDocument(std::string_view text, const std::string& file) {
  YAML::Node root = parseYamlDocument(text, file);
  if (!root.IsMap()) throw InputError(file, "line 1", "expected a YAML map of keys at the top level");
  return root;
}

std::string lineOf(const YAML::Node& node) {
  const int line = node.Mark().line;
  return line < 0 ? std::string("line ?") : "line " + std::to_string(line + 1);
}

YAML::Node required(const YAML::Node& map, const std::string& key, const std::string& file,
                    const std::string& context) {
  const YAML::Node value = map[key];
  if (!value.IsDefined() || value.IsNull())
    throw InputError(file, lineOf(map) + where(context), "missing key '" + key + "'");
  return value;
}

void expectMap(const YAML::Node& node, const std::string& file, const std::string& context) {
  if (!node.IsMap()) throw InputError(file, lineOf(node) + where(context), "expected a map of keys");
}

void expectSequence(const YAML::Node& node, const std::string& file, const std::string& context) {
  if (!node.IsSequence()) throw InputError(file, lineOf(node) + where(context), "expected a list");
}

void rejectUnknownKeys(const YAML::Node& map, std::initializer_list<std::string_view> known, const std::string& file,
                       const std::string& context) {
  for (const auto& entry : map) {
    const std::string key = entry.first.Scalar();
    if (std::find(known.begin(), known.end(), key) != known.end()) continue;
    std::string expected;
    for (const auto name : known) expected += (expected.empty() ? "" : ", ") + std::string(name);
    throw InputError(file, lineOf(entry.first) + where(context),
                     "unknown key '" + key + "'; expected one of: " + expected);
  }
}

double number(const YAML::Node& node, const std::string& file, const std::string& context) {
  const auto value = node.IsScalar() ? parseFiniteNumber(node.Scalar()) : std::nullopt;
  if (!value)
    throw InputError(
        file, lineOf(node) + where(context),
        "'" + (node.IsScalar() ? node.Scalar() : std::string("(not a value)")) + "' is not a finite number");
  return *value;
}

std::string text(const YAML::Node& node, const std::string& file, const std::string& context) {
  if (!node.IsScalar()) throw InputError(file, lineOf(node) + where(context), "expected a text value");
  return node.Scalar();
}

bool boolean(const YAML::Node& node, const std::string& file, const std::string& context) {
  if (node.IsScalar() && node.Scalar() == "true") return true;
  if (node.IsScalar() && node.Scalar() == "false") return false;
  throw InputError(file, lineOf(node) + where(context), "expected true or false");
}

void checkFormat(const YAML::Node& root, std::string_view expectedFormat, const std::string& file) {
  if (const YAML::Node format = root["format"]; format.IsDefined()) {
    if (text(format, file, "format") != expectedFormat)
      throw InputError(file, lineOf(format) + " (format)",
                       "'" + format.Scalar() + "' is not a " + std::string(expectedFormat) + " file");
  }
  if (const YAML::Node version = root["version"]; version.IsDefined()) {
    if (!version.IsScalar() || version.Scalar() != "1")
      throw InputError(file, lineOf(version) + " (version)", "unsupported version; expected 1");
  }
}

}  // namespace pmdplan::yaml_input
