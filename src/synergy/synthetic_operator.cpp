#include "pmdplan/synergy/synthetic_operator.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

#include "deterministic_random.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/glove/cyberglove_sensors.hpp"
#include "pmdplan/synergy/kautham_sah_synergies.hpp"
#include "synthetic_latent_basis.hpp"
#include "synthetic_latent_motion.hpp"

namespace pmdplan {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;
constexpr int kLowestCount = 1;  // the glove sends 1..255
constexpr int kHighestCount = 255;
// Raw counts the synthetic calibration leaves beyond the joint range on each side, as a share of the
// range: a real operator's hand goes past what the robot can do, and those frames are clamped.
constexpr double kRangeMargin = 0.5;
// The synthetic glove's thumb-roll reading picks up thumb abduction (as a real CyberGlove's does);
// its calibration carries the cross term that removes it, in counts of ThumbRotate per count of ThumbAb.
constexpr double kThumbCrossTalk = 0.1;

/// How a sensor not driven by a latent joint moves: a function of the joint angles (rad) plus
/// some smooth noise of its own, and the range its synthetic calibration covers.
struct OtherSensor {
  const char* sensor;
  double lowDeg;
  double highDeg;
  double noiseDeg;
  std::function<double(const std::function<double(const char*)>& joint)> angle;
};

const std::vector<OtherSensor>& otherSensors() {
  // Distal joints follow about 2/3 of the middle joint (the usual human DIP-PIP coupling); the
  // little finger follows the ring finger; palm arch and wrist wander on their own.
  static const std::vector<OtherSensor> sensors{
      {"ThumbAb", -20, 80, 6, [](const auto& q) { return 30 * kDegree - q("thumb_abduction"); }},
      {"IndexDIJ", -30, 110, 4, [](const auto& q) { return 0.67 * q("index_medium"); }},
      {"MiddleDIJ", -30, 110, 4, [](const auto& q) { return 0.67 * q("middle_medium"); }},
      {"RingDIJ", -30, 110, 4, [](const auto& q) { return 0.67 * q("ring_medium"); }},
      {"PinkieMPJ", -40, 120, 5, [](const auto& q) { return q("ring_proximal"); }},
      {"PinkiePIJ", -30, 120, 5, [](const auto& q) { return q("ring_medium"); }},
      {"PinkieDIJ", -30, 110, 4, [](const auto& q) { return 0.67 * q("ring_medium"); }},
      {"PinkieRingAb", -30, 50, 3, [](const auto& q) { return 10 * kDegree + 0.8 * q("ring_abduction"); }},
      {"PalmArch", -20, 60, 4, [](const auto& q) { return 10 * kDegree + 0.15 * q("ring_proximal"); }},
      {"WristPitch", -90, 90, 20, [](const auto&) { return 0.0; }},
      {"WristYaw", -50, 50, 10, [](const auto&) { return 0.0; }},
  };
  return sensors;
}

int countFor(double angle, const SensorCalibration& calibration, double crossAngle = 0.0) {
  const double counts = std::round((angle - calibration.offset - crossAngle) / calibration.gain);
  return static_cast<int>(std::clamp(counts, double(kLowestCount), double(kHighestCount)));
}

}  // namespace

const std::vector<double>& syntheticOperatorVarianceFractions() {
  static const std::vector<double> fractions{0.4219, 0.3493, 0.0759, 0.045, 0.025, 0.020,
                                             0.017,  0.014,  0.012,  0.011, 0.0089};
  return fractions;
}

SyntheticGloveSession synthesiseGloveSession(const SyntheticOperatorSettings& parameters, const HandMapping& mapping,
                                             const JointLimits& handJoints) {
  if (parameters.frames < 1 || parameters.frames > kMaxSyntheticFrames)
    throw InputError(
        "", "frames",
        "expected 1 to " + std::to_string(kMaxSyntheticFrames) + " frames, got " + std::to_string(parameters.frames));
  if (!(parameters.sampleRateHz > 0) || !(parameters.timeConstantS > 0) || !(parameters.totalVariance > 0))
    throw InputError("", "synthetic operator", "sample rate, time constant and total variance must be positive");
  const KauthamSahSynergies& table = kauthamSahSynergies();
  const auto limitOf = [&](const std::string& name) -> const JointLimit& {
    const auto it =
        std::find_if(handJoints.begin(), handJoints.end(), [&](const JointLimit& j) { return j.name == name; });
    if (it == handJoints.end())
      throw InputError("", "robot", "the synthetic operator models the SAH hand; the robot has no joint " + name);
    return *it;
  };

  // Latent joints: the table's joints that its PMDs move (all but thumb_base and middle_abduction).
  std::vector<int> latentRows;
  for (int j = 0; j < static_cast<int>(table.joints.size()); ++j)
    if (table.directions.row(j).norm() > 0) latentRows.push_back(j);
  const auto latentCount = static_cast<Eigen::Index>(latentRows.size());
  const auto& fractions = syntheticOperatorVarianceFractions();
  if (static_cast<std::size_t>(latentCount) != fractions.size())
    throw std::logic_error("synthetic operator: latent joint count differs from the variance spectrum");
  Eigen::MatrixXd pmds(latentCount, table.directions.cols());
  Eigen::VectorXd mean(latentCount);
  int thumbAbductionRow = -1;
  for (Eigen::Index r = 0; r < latentCount; ++r) {
    const int j = latentRows[static_cast<std::size_t>(r)];
    pmds.row(r) = table.directions.row(j);
    mean(r) = table.mean(j);
    if (table.joints[static_cast<std::size_t>(j)] == "thumb_abduction") thumbAbductionRow = static_cast<int>(r);
  }
  LatentBasisSettings basisSettings;
  basisSettings.pmds = pmds;
  basisSettings.variances = Eigen::Map<const Eigen::VectorXd>(fractions.data(), latentCount) * parameters.totalVariance;
  basisSettings.thumbRollRow = thumbAbductionRow;
  for (Eigen::Index r = 0; r < latentCount; ++r) {
    const std::string& joint = table.joints[static_cast<std::size_t>(latentRows[static_cast<std::size_t>(r)])];
    if (joint.rfind("thumb_", 0) != 0) basisSettings.fingerRows.push_back(static_cast<int>(r));
  }
  const Eigen::MatrixXd basis = latentBasis(basisSettings);

  // Invert the mapping for each latent joint: one sensor drives it, and drives no other latent joint.
  std::vector<int> sensorOfLatent(static_cast<std::size_t>(latentCount));
  std::vector<const JointRule*> ruleOfLatent(static_cast<std::size_t>(latentCount));
  std::vector<bool> driven(kCyberGloveSensorCount, false);
  for (Eigen::Index r = 0; r < latentCount; ++r) {
    const std::string& joint = table.joints[static_cast<std::size_t>(latentRows[static_cast<std::size_t>(r)])];
    limitOf(joint);
    const auto rule =
        std::find_if(mapping.rules.begin(), mapping.rules.end(), [&](const JointRule& x) { return x.joint == joint; });
    if (rule == mapping.rules.end())
      throw InputError(mapping.sourceFile, "joints", "the synthetic operator needs a rule for joint " + joint);
    const std::string where = jointRuleField(*rule);
    if (rule->terms.size() != 1 || rule->terms.front().gain == 0)
      throw InputError(
          mapping.sourceFile, where,
          "the synthetic operator inverts the mapping, so joint " + joint + " must follow exactly one sensor");
    const int sensor = rule->terms.front().sensor;
    if (driven[static_cast<std::size_t>(sensor)])
      throw InputError(mapping.sourceFile, where,
                       "sensor " + std::string(cyberGloveSensorNames()[static_cast<std::size_t>(sensor)]) +
                           " already drives another glove-driven joint; the synthetic operator cannot invert that");
    driven[static_cast<std::size_t>(sensor)] = true;
    sensorOfLatent[static_cast<std::size_t>(r)] = sensor;
    ruleOfLatent[static_cast<std::size_t>(r)] = &*rule;
  }

  DeterministicRandom random(parameters.seed);
  LatentMotionSettings settings;
  settings.frames = parameters.frames;
  settings.sampleRateHz = parameters.sampleRateHz;
  settings.timeConstantS = parameters.timeConstantS;
  settings.primitiveShare = parameters.primitiveShare;
  for (const double fraction : fractions) settings.variances.push_back(fraction * parameters.totalVariance);
  const Eigen::MatrixXd latent = generateLatentMotion(settings, random);
  const Eigen::MatrixXd unitPostures = (latent * basis.transpose()).rowwise() + mean.transpose();

  const int frames = parameters.frames;
  Eigen::MatrixXd sensorAngles = Eigen::MatrixXd::Zero(frames, kCyberGloveSensorCount);
  SyntheticGloveSession session;
  GloveCalibration& calibration = session.calibration;
  const int thumbRotate = cyberGloveSensorIndex("ThumbRotate");
  const int thumbAb = cyberGloveSensorIndex("ThumbAb");
  const auto calibrateRange = [&](int sensor, double low, double high) {
    // ThumbRotate's counts leave room for the cross-talk its calibration removes.
    const double usable =
        (kHighestCount - kLowestCount) - (sensor == thumbRotate ? kThumbCrossTalk * kHighestCount : 0.0);
    SensorCalibration& entry = calibration.sensors[static_cast<std::size_t>(sensor)];
    entry.gain = (high - low) / usable;
    entry.offset = low - entry.gain * kLowestCount;
  };

  Eigen::MatrixXd jointAngles(frames, latentCount);
  for (Eigen::Index r = 0; r < latentCount; ++r) {
    const JointLimit& limit = limitOf(table.joints[static_cast<std::size_t>(latentRows[static_cast<std::size_t>(r)])]);
    const JointRule& rule = *ruleOfLatent[static_cast<std::size_t>(r)];
    const double gain = rule.terms.front().gain;
    const int sensor = sensorOfLatent[static_cast<std::size_t>(r)];
    jointAngles.col(r) = (unitPostures.col(r).array() * limit.range() + limit.lower).matrix();
    sensorAngles.col(sensor) = ((jointAngles.col(r).array() - rule.offset) / gain).matrix();
    const double atLower = (limit.lower - rule.offset) / gain;
    const double atUpper = (limit.upper - rule.offset) / gain;
    const double width = std::abs(atUpper - atLower);
    calibrateRange(sensor, std::min(atLower, atUpper) - kRangeMargin * width,
                   std::max(atLower, atUpper) + kRangeMargin * width);
  }

  const auto jointColumn = [&](const std::string& name) -> Eigen::Index {
    for (Eigen::Index r = 0; r < latentCount; ++r)
      if (table.joints[static_cast<std::size_t>(latentRows[static_cast<std::size_t>(r)])] == name) return r;
    throw std::logic_error("synthetic operator: no latent joint " + name);
  };
  for (int sensor = 0; sensor < kCyberGloveSensorCount; ++sensor) {
    if (driven[static_cast<std::size_t>(sensor)]) continue;
    const std::string_view name = cyberGloveSensorNames()[static_cast<std::size_t>(sensor)];
    const auto model = std::find_if(otherSensors().begin(), otherSensors().end(),
                                    [&](const OtherSensor& s) { return name == s.sensor; });
    // A sensor that a custom mapping leaves out of both lists just wanders around mid-range.
    const OtherSensor fallback{"", -30, 110, 10, [](const auto&) { return 40 * kDegree; }};
    const OtherSensor& other = model != otherSensors().end() ? *model : fallback;
    const Eigen::VectorXd noise = ornsteinUhlenbeck(frames, parameters.sampleRateHz, parameters.timeConstantS, random);
    for (int f = 0; f < frames; ++f) {
      const auto joint = [&](const char* jointName) { return jointAngles(f, jointColumn(jointName)); };
      sensorAngles(f, sensor) = other.angle(joint) + other.noiseDeg * kDegree * noise(f);
    }
    calibrateRange(sensor, other.lowDeg * kDegree, other.highDeg * kDegree);
  }
  const bool crossTalk = thumbRotate >= 0 && thumbAb >= 0 && driven[static_cast<std::size_t>(thumbRotate)];
  if (crossTalk)
    calibration.crossTerms.push_back(
        {thumbRotate, thumbAb, -kThumbCrossTalk * calibration.sensors[static_cast<std::size_t>(thumbRotate)].gain});

  GloveRecording& recording = session.recording;
  recording.frames.resize(static_cast<std::size_t>(frames));
  recording.timeS.resize(static_cast<std::size_t>(frames));
  for (int f = 0; f < frames; ++f) {
    GloveFrame& frame = recording.frames[static_cast<std::size_t>(f)];
    for (int sensor = 0; sensor < kCyberGloveSensorCount; ++sensor)
      if (sensor != thumbRotate || !crossTalk)
        frame[static_cast<std::size_t>(sensor)] = static_cast<std::uint8_t>(
            countFor(sensorAngles(f, sensor), calibration.sensors[static_cast<std::size_t>(sensor)]));
    if (crossTalk) {
      // The reading carries the cross-talk; calibration (gain·raw + offset + cross gain·raw[ThumbAb]) removes it.
      const double crossAngle = calibration.crossTerms.front().gain * frame[static_cast<std::size_t>(thumbAb)];
      frame[static_cast<std::size_t>(thumbRotate)] = static_cast<std::uint8_t>(countFor(
          sensorAngles(f, thumbRotate), calibration.sensors[static_cast<std::size_t>(thumbRotate)], crossAngle));
    }
    recording.timeS[static_cast<std::size_t>(f)] = f / parameters.sampleRateHz;
  }
  const std::string seedText = std::to_string(parameters.seed);
  recording.notes = {
      "SYNTHETIC glove recording: made by pmdplan's synthetic operator, NOT captured from a human hand.",
      "Latent synergies from the SAH PMD table of docs/reference_data.md sect. 4 (paper Sect. 4), smooth random motion "
      "mixed with",
      "open/close, spread, opposition and pinch primitives; seed " + seedText + ", " + std::to_string(frames) +
          " frames at " + std::to_string(static_cast<int>(parameters.sampleRateHz)) + " Hz; raw CyberGlove counts.",
  };
  recording.source = "synthetic operator (seed " + seedText + ")";
  recording.dataLocation = "frames 1-" + std::to_string(frames);
  calibration.description = "SYNTHETIC calibration of pmdplan's synthetic glove operator (seed " + seedText +
                            "); not the calibration of a real glove";
  return session;
}

}  // namespace pmdplan
