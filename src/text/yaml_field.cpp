#include "pmdplan/text/yaml_field.hpp"

#include <charconv>
#include <cmath>
#include <map>
#include <vector>

#include "pmdplan/core/input_error.hpp"
#include "pmdplan/core/message_text.hpp"
#include "pmdplan/text/number_text.hpp"
#include "yaml_document_check.hpp"

namespace pmdplan {
namespace {

int oneBasedLine(const YAML::Node& node) {
  const YAML::Mark mark = node.Mark();
  return mark.line >= 0 ? mark.line + 1 : 0;
}

/// A value in a message (message_text.hpp): a long one is only measured, so an error never shows a
/// file's contents, and nothing is printed raw.
std::string quoted(std::string_view text) { return quotedText(text); }

std::string describeNode(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Null:
      return "nothing";
    case YAML::NodeType::Sequence:
      return "a list";
    case YAML::NodeType::Map:
      return "a map";
    case YAML::NodeType::Scalar:
      return quoted(node.Scalar());
    default:
      return "an undefined value";
  }
}

std::string joinKeys(std::initializer_list<std::string_view> keys) {
  std::string joined;
  for (const auto key : keys) joined += (joined.empty() ? "" : ", ") + std::string(key);
  return joined;
}

}  // namespace

std::string joinFieldPath(const std::string& parent, std::string_view key) {
  const std::string step = fieldKeyText(key);
  return parent.empty() ? step : parent + "." + step;
}

YAML::Node parseYamlDocument(std::string_view text, const std::string& file) {
  if (text.find_first_not_of(" \t\r\n") == std::string_view::npos)
    throw InputError(file, "line 1", "empty file; expected a YAML document");
  // Checked as written first: yaml-cpp would build a cycle from an alias inside its own anchor,
  // and every walk of the nodes would then go round it for ever.
  checkYamlDocument(text, file);
  try {
    return YAML::Load(std::string(text));
  } catch (const YAML::Exception& error) {
    throw InputError(
        file, "line " + std::to_string(error.mark.line + 1) + ", column " + std::to_string(error.mark.column + 1),
        "YAML syntax error: " + error.msg);
  }
}

YamlField parseYamlFile(std::string_view text, const std::string& file, std::string_view format,
                        std::initializer_list<std::string_view> keys, const std::string& expected) {
  const YamlField root(file, parseYamlDocument(text, file));
  root.requireMapWithKeys(keys, expected);
  if (const auto given = root.optionalChild("format"); given) {
    if (given->text("the file format") != format)
      given->fail(quoted(given->node().Scalar()) + " is not a " + std::string(format) + " file");
  }
  if (const auto version = root.optionalChild("version"); version) {
    if (!version->node().IsScalar() || version->node().Scalar() != "1")
      version->fail("unsupported version " + describeNode(version->node()) + "; expected 1");
  }
  return root;
}

YamlField::YamlField(std::string file, YAML::Node root) : YamlField(std::move(file), "", root) {}

YamlField::YamlField(std::string file, std::string path, YAML::Node node)
    : file_(std::move(file)), path_(std::move(path)), node_(node), line_(oneBasedLine(node)) {}

std::string YamlField::location() const {
  std::string field = path_.empty() ? std::string("document") : path_;
  if (line_ > 0) field += " (line " + std::to_string(line_) + ")";
  return field;
}

void YamlField::fail(const std::string& message) const { throw InputError(file_, location(), message); }

std::vector<std::pair<std::string, YamlField>> YamlField::mapEntries(const std::string& expected) const {
  if (!node_.IsMap()) fail("expected " + expected + ", got " + describeNode(node_));
  std::vector<std::pair<std::string, YamlField>> entries;
  std::map<std::string, int> firstLine;
  for (auto it = node_.begin(); it != node_.end(); ++it) {
    const YAML::Node key = it->first;
    if (!key.IsScalar()) {
      at(path_, key).fail("map keys must be plain names, got " + describeNode(key));
    }
    const std::string name = key.Scalar();
    YamlField keyField = at(joinFieldPath(path_, name), key);
    if (const auto previous = firstLine.find(name); previous != firstLine.end()) {
      keyField.fail("given twice (first on line " + std::to_string(previous->second) + "); each key may appear once");
    }
    firstLine.emplace(name, keyField.line());
    entries.emplace_back(name, at(joinFieldPath(path_, name), it->second));
  }
  return entries;
}

void YamlField::requireMapWithKeys(std::initializer_list<std::string_view> allowed, const std::string& expected,
                                   const std::string& unknownKeyLabel) const {
  if (!node_.IsMap()) fail("expected " + expected + ", got " + describeNode(node_));
  for (auto it = node_.begin(); it != node_.end(); ++it) {
    const YAML::Node key = it->first;
    if (!key.IsScalar()) continue;  // mapEntries below reports it
    bool known = false;
    for (const auto candidate : allowed) known = known || key.Scalar() == candidate;
    if (!known) {
      at(joinFieldPath(path_, key.Scalar()), key)
          .fail(unknownKeyLabel + " " + quoted(key.Scalar()) + "; expected " + expected +
                " (keys: " + joinKeys(allowed) + ")");
    }
  }
  mapEntries(expected);  // rejects repeated and non-scalar keys
}

bool YamlField::has(std::string_view key) const { return node_.IsMap() && node_[std::string(key)].IsDefined(); }

YamlField YamlField::child(std::string_view key, const std::string& expected) const {
  if (auto found = optionalChild(key)) return *found;
  // Report the missing key at the line of the map that should hold it.
  YamlField missing = at(joinFieldPath(path_, key), node_);
  missing.fail("missing; expected " + expected);
}

std::optional<YamlField> YamlField::optionalChild(std::string_view key) const {
  if (!node_.IsMap()) return std::nullopt;
  const YAML::Node value = node_[std::string(key)];
  if (!value.IsDefined()) return std::nullopt;
  return at(joinFieldPath(path_, key), value);
}

std::vector<YamlField> YamlField::elements(const std::string& expected) const {
  if (!node_.IsSequence()) fail("expected " + expected + ", got " + describeNode(node_));
  std::vector<YamlField> result;
  for (std::size_t i = 0; i < node_.size(); ++i) {
    result.push_back(at(path_ + "[" + std::to_string(i) + "]", node_[i]));
  }
  return result;
}

std::string YamlField::text(const std::string& expected) const {
  if (!node_.IsScalar()) fail("expected " + expected + ", got " + describeNode(node_));
  return node_.Scalar();
}

double YamlField::number(const std::string& expected) const {
  if (!node_.IsScalar()) fail("expected " + expected + ", got " + describeNode(node_));
  // A quoted scalar is a string in YAML even if it looks like a number.
  if (node_.Tag() == "!") fail("expected " + expected + ", got the quoted string " + quoted(node_.Scalar()));
  std::string_view digits = node_.Scalar();
  if (digits == ".nan" || digits == ".NaN" || digits == ".NAN" || digits == ".inf" || digits == ".Inf" ||
      digits == ".INF" || digits == "-.inf" || digits == "-.Inf" || digits == "-.INF" || digits == "+.inf" ||
      digits == "+.Inf" || digits == "+.INF") {
    fail("expected " + expected + ", got " + quoted(digits) + ", which is not a finite number");
  }
  if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
  double value = 0.0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (error == std::errc::result_out_of_range) {
    fail("expected " + expected + ", got " + quoted(node_.Scalar()) + ", which is out of range");
  }
  if (error != std::errc() || end != digits.data() + digits.size()) {
    fail("expected " + expected + ", got " + quoted(node_.Scalar()));
  }
  if (!std::isfinite(value)) {
    fail("expected " + expected + ", got " + quoted(node_.Scalar()) + ", which is not a finite number");
  }
  return value;
}

double YamlField::positiveNumber(const std::string& expected) const {
  const double value = number(expected);
  if (!(value > 0.0)) {
    fail("expected " + expected + ", got " + messageNumberText(value));
  }
  return value;
}

bool YamlField::boolean(const std::string& expected) const {
  if (node_.IsScalar() && node_.Tag() != "!") {
    if (node_.Scalar() == "true") return true;
    if (node_.Scalar() == "false") return false;
  }
  fail("expected " + expected + " (true or false), got " + describeNode(node_));
}

Eigen::Vector3d YamlField::vector3(const std::string& expected) const {
  const auto items = elements(expected);
  if (items.size() != 3) {
    fail("expected " + expected + ", got a list of " + std::to_string(items.size()) + " values (need exactly 3)");
  }
  return {items[0].number(expected), items[1].number(expected), items[2].number(expected)};
}

Eigen::Vector3d YamlField::positiveVector3(const std::string& expected) const {
  const auto items = elements(expected);
  if (items.size() != 3) {
    fail("expected " + expected + ", got a list of " + std::to_string(items.size()) + " values (need exactly 3)");
  }
  return {items[0].positiveNumber(expected), items[1].positiveNumber(expected), items[2].positiveNumber(expected)};
}

}  // namespace pmdplan
