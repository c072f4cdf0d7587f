#include "pmdplan/glove/glove_calibration_file.hpp"

#include "pmdplan/core/atomic_file.hpp"
#include "pmdplan/core/message_text.hpp"
#include "pmdplan/text/number_text.hpp"
#include "pmdplan/text/yaml_field.hpp"
#include "pmdplan/text/yaml_writing.hpp"

namespace pmdplan {
namespace {

constexpr std::string_view kFormat = "pmdplan-glove-calibration";

/// A sensor named by `field` (a map key or a value): its index in cyberGloveSensorNames().
int sensorByName(const YamlField& field, const std::string& name) {
  const int index = cyberGloveSensorIndex(name);
  if (index < 0)
    field.fail("unknown sensor " + quotedText(name) + "; expected one of " + std::string(cyberGloveSensorList()));
  return index;
}

int sensorAt(const YamlField& field) { return sensorByName(field, field.text("a sensor name")); }

}  // namespace

GloveCalibration parseGloveCalibration(std::string_view text, const std::string& file) {
  const YamlField root = parseYamlFile(
      text, file, kFormat, {"format", "version", "description", "sensors", "cross_terms"}, "a glove calibration");
  GloveCalibration calibration;
  if (const auto description = root.optionalChild("description"))
    calibration.description = description->text("a description");

  const YamlField sensors = root.child("sensors", "a map of the 22 sensors, each {gain, offset}");
  std::array<bool, kCyberGloveSensorCount> seen{};
  for (const auto& [name, entry] : sensors.mapEntries("a map of sensors")) {
    const auto index = static_cast<std::size_t>(sensorByName(entry, name));
    if (seen[index]) entry.fail("sensor listed twice");
    seen[index] = true;
    entry.requireMapWithKeys({"gain", "offset"}, "{gain, offset}");
    calibration.sensors[index].gain = entry.child("gain", "a gain in rad/count").number("a gain in rad/count");
    calibration.sensors[index].offset = entry.child("offset", "an offset in rad").number("an offset in rad");
  }
  for (std::size_t s = 0; s < seen.size(); ++s)
    if (!seen[s])
      sensors.fail("no calibration for sensor " + std::string(cyberGloveSensorNames()[s]) +
                   "; every one of the 22 sensors needs {gain, offset}");

  if (const auto terms = root.optionalChild("cross_terms"); terms && !terms->node().IsNull()) {
    for (const YamlField& term : terms->elements("a list of {sensor, from, gain}")) {
      term.requireMapWithKeys({"sensor", "from", "gain"}, "{sensor, from, gain}");
      CalibrationCrossTerm cross;
      cross.sensor = sensorAt(term.child("sensor", "a sensor name"));
      cross.from = sensorAt(term.child("from", "a sensor name"));
      cross.gain = term.child("gain", "a gain in rad/count").number("a gain in rad/count");
      calibration.crossTerms.push_back(cross);
    }
  }
  return calibration;
}

GloveCalibration loadGloveCalibration(const std::filesystem::path& path) {
  return parseGloveCalibration(readTextFile(path), path.string());
}

std::string formatGloveCalibration(const GloveCalibration& calibration) {
  std::string text = yamlFileHeader({"CyberGlove calibration: angle [rad] = gain [rad/count] * raw + offset [rad]",
                                     "(+ gain [rad/count] * raw of `from` for each cross term)."},
                                    kFormat, "description", calibration.description);
  text += "sensors:\n";
  for (int s = 0; s < kCyberGloveSensorCount; ++s) {
    const SensorCalibration& sensor = calibration.sensors[static_cast<std::size_t>(s)];
    text += "  " + std::string(cyberGloveSensorNames()[static_cast<std::size_t>(s)]) +
            ": {gain: " + exactNumberText(sensor.gain) + ", offset: " + exactNumberText(sensor.offset) + "}\n";
  }
  if (calibration.crossTerms.empty()) return text + "cross_terms: []\n";
  text += "cross_terms:\n";
  for (const CalibrationCrossTerm& term : calibration.crossTerms)
    text += "  - {sensor: " + std::string(cyberGloveSensorNames()[static_cast<std::size_t>(term.sensor)]) +
            ", from: " + std::string(cyberGloveSensorNames()[static_cast<std::size_t>(term.from)]) +
            ", gain: " + exactNumberText(term.gain) + "}\n";
  return text;
}

}  // namespace pmdplan
