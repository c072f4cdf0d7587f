#include "pmdplan/glove/glove_calibration_file.hpp"

#include "pmdplan/core/atomic_file.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/text/number_text.hpp"
#include "pmdplan/text/yaml_input.hpp"
#include "pmdplan/text/yaml_writing.hpp"

namespace pmdplan {
namespace {

constexpr std::string_view kFormat = "pmdplan-glove-calibration";

int sensorByName(const YAML::Node& node, const std::string& file, const std::string& context) {
  const std::string name = yaml_input::text(node, file, context);
  const int index = cyberGloveSensorIndex(name);
  if (index < 0)
    throw InputError(file, yaml_input::lineOf(node) + " (" + context + ")",
                     "unknown sensor '" + name + "'; expected one of " + std::string(cyberGloveSensorList()));
  return index;
}

}  // namespace

GloveCalibration parseGloveCalibration(std::string_view text, const std::string& file) {
  const YAML::Node root = yaml_input::parseDocument(text, file);
  yaml_input::rejectUnknownKeys(root, {"format", "version", "description", "sensors", "cross_terms"}, file, "");
  yaml_input::checkFormat(root, kFormat, file);
  GloveCalibration calibration;
  if (const YAML::Node description = root["description"]; description.IsDefined())
    calibration.description = yaml_input::text(description, file, "description");

  const YAML::Node sensors = yaml_input::required(root, "sensors", file, "");
  yaml_input::expectMap(sensors, file, "sensors");
  std::array<bool, kCyberGloveSensorCount> seen{};
  for (const auto& entry : sensors) {
    const int index = sensorByName(entry.first, file, "sensors");
    const std::string context = "sensors." + entry.first.Scalar();
    if (seen[static_cast<std::size_t>(index)])
      throw InputError(file, yaml_input::lineOf(entry.first) + " (" + context + ")", "sensor listed twice");
    seen[static_cast<std::size_t>(index)] = true;
    yaml_input::expectMap(entry.second, file, context);
    yaml_input::rejectUnknownKeys(entry.second, {"gain", "offset"}, file, context);
    SensorCalibration& sensor = calibration.sensors[static_cast<std::size_t>(index)];
    sensor.gain =
        yaml_input::number(yaml_input::required(entry.second, "gain", file, context), file, context + ".gain");
    sensor.offset =
        yaml_input::number(yaml_input::required(entry.second, "offset", file, context), file, context + ".offset");
  }
  for (int s = 0; s < kCyberGloveSensorCount; ++s)
    if (!seen[static_cast<std::size_t>(s)])
      throw InputError(file, yaml_input::lineOf(sensors) + " (sensors)",
                       "no calibration for sensor " +
                           std::string(cyberGloveSensorNames()[static_cast<std::size_t>(s)]) +
                           "; every one of the 22 sensors needs {gain, offset}");

  if (const YAML::Node terms = root["cross_terms"]; terms.IsDefined() && !terms.IsNull()) {
    yaml_input::expectSequence(terms, file, "cross_terms");
    for (std::size_t i = 0; i < terms.size(); ++i) {
      const YAML::Node term = terms[i];
      const std::string context = "cross_terms[" + std::to_string(i) + "]";
      yaml_input::expectMap(term, file, context);
      yaml_input::rejectUnknownKeys(term, {"sensor", "from", "gain"}, file, context);
      CalibrationCrossTerm cross;
      cross.sensor = sensorByName(yaml_input::required(term, "sensor", file, context), file, context + ".sensor");
      cross.from = sensorByName(yaml_input::required(term, "from", file, context), file, context + ".from");
      cross.gain = yaml_input::number(yaml_input::required(term, "gain", file, context), file, context + ".gain");
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
