#include "pmdplan/synergy/hand_mapping_file.hpp"

#include "pmdplan/core/atomic_file.hpp"
#include "pmdplan/core/data_directory.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/core/message_text.hpp"
#include "pmdplan/glove/cyberglove_sensors.hpp"
#include "pmdplan/text/number_text.hpp"
#include "pmdplan/text/yaml_field.hpp"
#include "pmdplan/text/yaml_writing.hpp"

namespace pmdplan {
namespace {
constexpr std::string_view kFormat = "pmdplan-hand-mapping";

JointRule readRule(const YamlField& node) {
  node.requireMapWithKeys({"joint", "sensors", "offset", "constant"}, "{joint, sensors, offset} or {joint, constant}");
  JointRule rule;
  rule.sourceLine = node.line();
  rule.joint = node.child("joint", "a joint name").text("a joint name");
  const std::string where = jointRuleField(rule);
  const std::optional<YamlField> sensors = node.optionalChild("sensors");
  const std::optional<YamlField> constant = node.optionalChild("constant");
  const std::optional<YamlField> offset = node.optionalChild("offset");
  if (sensors.has_value() == constant.has_value())
    throw InputError(node.file(), where,
                     "give either sensors: {NAME: gain, ...} or constant: VALUE, not both or neither");
  if (constant) {
    if (offset) throw InputError(node.file(), where, "a constant joint takes no offset; put the value in constant");
    rule.offset = constant->number("a joint value in rad");
    return rule;
  }
  const auto terms = sensors->mapEntries("a map of sensor names to gains");
  if (terms.empty()) throw InputError(node.file(), where, "sensors is empty; give at least one sensor or a constant");
  for (const auto& [name, gain] : terms) {
    const int sensor = cyberGloveSensorIndex(name);
    if (sensor < 0)
      throw InputError(
          node.file(), "line " + std::to_string(gain.line()) + " (joint " + fieldKeyText(rule.joint) + ")",
          "unknown sensor " + quotedText(name) + "; expected one of " + std::string(cyberGloveSensorList()));
    rule.terms.push_back({sensor, gain.number("a gain")});
  }
  if (offset) rule.offset = offset->number("an offset in rad");
  return rule;
}
}  // namespace

HandMapping parseHandMapping(std::string_view text, const std::string& file) {
  const YamlField root =
      parseYamlFile(text, file, kFormat, {"format", "version", "description", "joints"}, "a hand mapping");
  HandMapping mapping;
  mapping.sourceFile = file;
  if (const auto description = root.optionalChild("description"))
    mapping.description = description->text("a description");
  for (const YamlField& node : root.child("joints", "a list of joint rules").elements("a list of joint rules")) {
    JointRule rule = readRule(node);
    for (const JointRule& earlier : mapping.rules)
      if (earlier.joint == rule.joint)
        throw InputError(file, jointRuleField(rule),
                         "joint listed twice (first on line " + std::to_string(earlier.sourceLine) + ")");
    mapping.rules.push_back(std::move(rule));
  }
  return mapping;
}

HandMapping loadHandMapping(const std::filesystem::path& path) {
  return parseHandMapping(readTextFile(path), path.string());
}

std::string formatHandMapping(const HandMapping& mapping) {
  std::string text =
      yamlFileHeader({"Glove sensors -> robot hand joints, angles in rad: joint = offset + sum of gain * sensor angle,",
                      "or a constant; values beyond a joint limit are clamped (and counted)."},
                     kFormat, "description", mapping.description);
  text += "joints:\n";
  for (const JointRule& rule : mapping.rules) {
    text += "  - {joint: " + rule.joint;
    if (rule.isConstant()) {
      text += ", constant: " + exactNumberText(rule.offset) + "}\n";
      continue;
    }
    text += ", sensors: {";
    for (std::size_t t = 0; t < rule.terms.size(); ++t)
      text += (t ? ", " : "") + std::string(cyberGloveSensorNames()[static_cast<std::size_t>(rule.terms[t].sensor)]) +
              ": " + exactNumberText(rule.terms[t].gain);
    text += "}";
    if (rule.offset != 0.0) text += ", offset: " + exactNumberText(rule.offset);
    text += "}\n";
  }
  return text;
}

std::filesystem::path defaultHandMappingPath() { return dataDirectory() / "glove" / "cyberglove22_to_sah.yaml"; }

}  // namespace pmdplan
