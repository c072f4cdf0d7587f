#include "pmdplan/synergy/hand_mapping_file.hpp"

#include "pmdplan/core/atomic_file.hpp"
#include "pmdplan/core/data_directory.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/glove/cyberglove_sensors.hpp"
#include "pmdplan/text/number_text.hpp"
#include "pmdplan/text/yaml_input.hpp"
#include "pmdplan/text/yaml_writing.hpp"

namespace pmdplan {
namespace {
constexpr std::string_view kFormat = "pmdplan-hand-mapping";

JointRule readRule(const YAML::Node& node, const std::string& file, const std::string& context) {
  yaml_input::expectMap(node, file, context);
  yaml_input::rejectUnknownKeys(node, {"joint", "sensors", "offset", "constant"}, file, context);
  JointRule rule;
  rule.sourceLine = node.Mark().line + 1;
  rule.joint = yaml_input::text(yaml_input::required(node, "joint", file, context), file, context + ".joint");
  const std::string where = "line " + std::to_string(rule.sourceLine) + " (joint " + rule.joint + ")";
  const YAML::Node sensors = node["sensors"];
  const YAML::Node constant = node["constant"];
  if (sensors.IsDefined() == constant.IsDefined())
    throw InputError(file, where, "give either sensors: {NAME: gain, ...} or constant: VALUE, not both or neither");
  if (constant.IsDefined()) {
    if (node["offset"].IsDefined())
      throw InputError(file, where, "a constant joint takes no offset; put the value in constant");
    rule.offset = yaml_input::number(constant, file, context + ".constant");
    return rule;
  }
  yaml_input::expectMap(sensors, file, context + ".sensors");
  if (sensors.size() == 0) throw InputError(file, where, "sensors is empty; give at least one sensor or a constant");
  for (const auto& entry : sensors) {
    const std::string name = yaml_input::text(entry.first, file, context + ".sensors");
    const int sensor = cyberGloveSensorIndex(name);
    if (sensor < 0)
      throw InputError(file, yaml_input::lineOf(entry.first) + " (joint " + rule.joint + ")",
                       "unknown sensor '" + name + "'; expected one of " + std::string(cyberGloveSensorList()));
    for (const SensorTerm& earlier : rule.terms)
      if (earlier.sensor == sensor)
        throw InputError(file, yaml_input::lineOf(entry.first) + " (joint " + rule.joint + ")",
                         "sensor " + name + " listed twice");
    rule.terms.push_back({sensor, yaml_input::number(entry.second, file, context + ".sensors." + name)});
  }
  if (const YAML::Node offset = node["offset"]; offset.IsDefined())
    rule.offset = yaml_input::number(offset, file, context + ".offset");
  return rule;
}
}  // namespace

HandMapping parseHandMapping(std::string_view text, const std::string& file) {
  const YAML::Node root = yaml_input::parseDocument(text, file);
  yaml_input::rejectUnknownKeys(root, {"format", "version", "description", "joints"}, file, "");
  yaml_input::checkFormat(root, kFormat, file);
  HandMapping mapping;
  mapping.sourceFile = file;
  if (const YAML::Node description = root["description"]; description.IsDefined())
    mapping.description = yaml_input::text(description, file, "description");
  const YAML::Node joints = yaml_input::required(root, "joints", file, "");
  yaml_input::expectSequence(joints, file, "joints");
  for (std::size_t i = 0; i < joints.size(); ++i) {
    JointRule rule = readRule(joints[i], file, "joints[" + std::to_string(i) + "]");
    for (const JointRule& earlier : mapping.rules)
      if (earlier.joint == rule.joint)
        throw InputError(file, "line " + std::to_string(rule.sourceLine) + " (joint " + rule.joint + ")",
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
