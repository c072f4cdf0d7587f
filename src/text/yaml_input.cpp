#include "pmdplan/text/yaml_input.hpp"

#include <algorithm>
#include <set>
#include <vector>

#include "pmdplan/core/input_error.hpp"
#include "pmdplan/text/number_text.hpp"

namespace pmdplan::yaml_input {
namespace {
std::string where(const std::string& context) { return context.empty() ? "" : " (" + context + ")"; }
constexpr std::size_t kMaxYamlNodes = 10'000'000;

/// yaml-cpp keeps both entries of a repeated key and answers lookups with the first: refuse them.
void rejectRepeatedKeys(const YAML::Node& node, const std::string& file) {
  std::vector<YAML::Node> pending{node};
  std::size_t visited = 0;
  while (!pending.empty()) {
    if (++visited > kMaxYamlNodes)  // aliases can repeat a subtree exponentially often
      throw InputError(
          file, "document",
          "more than " + std::to_string(kMaxYamlNodes) + " values (through aliases?), the most pmdplan reads");
    const YAML::Node current = pending.back();
    pending.pop_back();
    if (current.IsSequence())
      for (const auto& item : current) pending.push_back(item);
    if (!current.IsMap()) continue;
    std::set<std::string> seen;
    for (const auto& entry : current) {
      if (entry.first.IsScalar() && !seen.insert(entry.first.Scalar()).second)
        throw InputError(file, lineOf(entry.first),
                         "key '" + entry.first.Scalar() + "' is given twice; each key may appear once");
      pending.push_back(entry.second);
    }
  }
}
}  // namespace

YAML::Node parseDocument(std::string_view text, const std::string& file) {
  if (text.find_first_not_of(" \t\r\n") == std::string_view::npos)
    throw InputError(file, "line 1", "empty file; expected a YAML document");
  try {
    YAML::Node root = YAML::Load(std::string(text));
    if (!root.IsMap()) throw InputError(file, "line 1", "expected a YAML map of keys at the top level");
    rejectRepeatedKeys(root, file);
    return root;
  } catch (const YAML::Exception& e) {
    throw InputError(file, "line " + std::to_string(e.mark.line + 1), "YAML syntax error: " + e.msg);
  }
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
