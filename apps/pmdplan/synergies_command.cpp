// `pmdplan synergies REC [--calibration F] [--mapping F] [-o model.yaml] [--json]`: a glove
// recording through calibration, mapping and PCA to a synergy model; prints the cumulative
// variance (the paper's Fig. 10) and the correlations of the paper's Fig. 7 joint pairs.
// `pmdplan synergies --postures P.csv --robot URDF`: the same PCA from hand joint postures.
// `pmdplan synergies --from-graspit FILE.xml --joints j1,j2,… -o model.yaml`: imports GraspIt
// eigengrasps. `pmdplan synergies --show model.yaml`: checks and prints a model file.
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "command_registry.hpp"
#include "package_path_option.hpp"
#include "pmdplan/core/atomic_file.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/glove/glove_calibration_file.hpp"
#include "pmdplan/glove/glove_recording_file.hpp"
#include "pmdplan/io/figures/synergy_plots.hpp"
#include "pmdplan/io/files/synergy_model_json.hpp"
#include "pmdplan/model/robot_model.hpp"
#include "pmdplan/synergy/figure7_joint_pairs.hpp"
#include "pmdplan/synergy/graspit_eigengrasp_import.hpp"
#include "pmdplan/synergy/hand_mapping_file.hpp"
#include "pmdplan/synergy/posture_csv.hpp"
#include "pmdplan/synergy/recording_analysis.hpp"
#include "pmdplan/synergy/synergy_model_file.hpp"

namespace pmdplan::cli::synergies_command {
namespace {

struct Options {
  std::string recording;
  std::string format = "auto";
  std::string calibration;
  std::string mapping;
  std::string robot = "sah_tx90";
  std::vector<std::string> ownAxis;
  std::string output;
  bool json = false;
  std::string graspit;
  std::vector<std::string> graspitJoints;
  std::string show;
  std::string plots;
  std::string postures;
  std::string units = "deg";
};

std::string fileName(const std::filesystem::path& path) { return path.filename().string(); }

std::vector<std::string> ownAxisJoints(const Options& o, const JointLimits& hand) {
  if (o.ownAxis.size() == 1 && o.ownAxis.front() == "none") return {};
  if (!o.ownAxis.empty()) return o.ownAxis;
  // The paper keeps the SAH thumb base as an axis of its own (Sect. 4.2).
  for (const auto& joint : hand)
    if (joint.name == "thumb_base") return {"thumb_base"};
  return {};
}

void printModel(const SynergyModel& model) {
  std::cout << model.provenance << "\n"
            << model.jointCount() << " joints, " << model.directionCount() << " directions ("
            << (model.orthonormal ? "orthonormal" : "NOT orthonormal: coefficients by least squares") << ")";
  if (!model.ownAxisJoints.empty()) {
    std::cout << "; own axis:";
    for (const auto& name : model.ownAxisJoints) std::cout << " " << name;
  }
  std::cout << "\n  dir   sigma   variance %   cumulative %   box half-width at kappa 2\n";
  double cumulative = 0;
  for (int k = 0; k < model.directionCount(); ++k) {
    cumulative += model.varianceFraction(k);
    std::printf("  %3d  %6.4f   %9.2f   %12.2f   %8.4f\n", k + 1, model.sigma(k), 100 * model.varianceFraction(k),
                100 * cumulative, model.boxHalfWidths(2.0)(k));
  }
}

/// --plots DIR: the figures (without postures, as from --show or an import, only the variance).
void writePlots(const Options& o, const SynergyModel& model, const Eigen::MatrixXd& postures,
                const JointLimits& joints) {
  if (o.plots.empty()) return;
  for (const auto& file : writeSynergyPlots(o.plots, model, postures, joints))
    std::cerr << "wrote " << file.string() << "\n";
}

int runShow(const Options& o) {
  const SynergyModel model = loadSynergyModel(o.show);
  writePlots(o, model, {}, model.joints);
  if (o.json) {
    std::cout << synergyModelJson(model).dump(2) << "\n";
    return 0;
  }
  std::cout << o.show << ": ";
  printModel(model);
  return 0;
}

int runGraspIt(const Options& o) {
  if (o.graspitJoints.empty())
    throw InputError("", "--joints",
                     "GraspIt files carry no joint names: give --joints j1,j2,... (one robot joint per dimension)");
  const GraspItImport imported =
      importGraspItEigengrasps(o.graspit, o.graspitJoints, RobotModel::loadByNameOrPath(o.robot).groupJoints("hand"));
  if (!o.output.empty()) saveSynergyModel(o.output, imported.model);
  writePlots(o, imported.model, {}, imported.model.joints);
  if (o.json) {
    nlohmann::json out = synergyModelJson(imported.model);
    out["notes"] = imported.notes;
    if (!o.output.empty()) out["model_file"] = o.output;
    std::cout << out.dump(2) << "\n";
    return 0;
  }
  printModel(imported.model);
  for (const auto& note : imported.notes) std::cout << "note: " << note << "\n";
  if (!o.output.empty()) std::cout << "wrote " << o.output << "\n";
  return 0;
}

int runPostures(const Options& o) {
  const JointLimits hand = RobotModel::loadByNameOrPath(o.robot).groupJoints("hand");
  if (o.units != "deg" && o.units != "rad")
    throw InputError("", "--units", "expected deg or rad, got '" + o.units + "'");
  const Eigen::MatrixXd postures =
      readPostureCsv(o.postures, hand, o.units == "deg" ? PostureUnit::Degrees : PostureUnit::Radians);
  SynergyFitSettings fitOptions;
  fitOptions.ownAxisJoints = ownAxisJoints(o, hand);
  const std::string provenance = "hand postures " + fileName(o.postures) + " (" + std::to_string(postures.rows()) +
                                 " postures); PCA over joints normalised to [0, 1] by the limits of " +
                                 fileName(std::filesystem::path(o.robot));
  const SynergyFit fit = fitSynergyModel(postures, hand, fitOptions, {o.postures, "postures", provenance});
  if (!o.output.empty()) saveSynergyModel(o.output, fit.model);
  writePlots(o, fit.model, postures, hand);
  if (o.json) {
    nlohmann::json out = {{"frames", fit.frames},
                          {"pca_joint_names", fit.pcaJoints},
                          {"constant_joints", fit.constantJoints},
                          {"cumulative_variance", numberListJson(fit.cumulativeVariance)},
                          {"model", synergyModelJson(fit.model)}};
    if (!o.output.empty()) out["model_file"] = o.output;
    std::cout << out.dump(2) << "\n";
    return 0;
  }
  std::cout << o.postures << ": " << fit.frames << " postures of " << hand.size() << " hand joints\n";
  printModel(fit.model);
  if (fitOptions.ownAxisJoints.empty())
    std::cout
        << "note: no own-axis joint; the paper keeps the thumb's opposition joint out of the PCA as an axis of its "
           "own: name it with --own-axis JOINT\n";
  if (!o.output.empty()) std::cout << "wrote " << o.output << "\n";
  return 0;
}

void checkOutputs(const Options& o);

int runRecording(const Options& o) {
  const JointLimits hand = RobotModel::loadByNameOrPath(o.robot).groupJoints("hand");
  const GloveRecording recording = readGloveRecording(o.recording, o.format);
  const std::filesystem::path calibrationPath = recordingCalibrationPath(o.recording, o.calibration);
  const GloveCalibration calibration = loadGloveCalibration(calibrationPath);
  const std::filesystem::path mappingPath =
      o.mapping.empty() ? defaultHandMappingPath() : std::filesystem::path(o.mapping);
  const HandMapping mapping = loadHandMapping(mappingPath);
  checkOutputs(o);  // again, now against the calibration, mapping and robot read (command_files.hpp)
  SynergyFitSettings fitOptions;
  fitOptions.ownAxisJoints = ownAxisJoints(o, hand);
  const bool synthetic = !recording.notes.empty() && recording.notes.front().rfind("SYNTHETIC", 0) == 0;
  // File names only, so a model's provenance does not depend on where the files were.
  const std::string provenance = std::string(synthetic ? "SYNTHETIC operator data (not human): " : "") +
                                 "glove recording " + fileName(o.recording) + " (" +
                                 std::to_string(recording.frameCount()) + " frames), calibration " +
                                 fileName(calibrationPath) + ", mapping " + fileName(mappingPath) +
                                 "; PCA over joints normalised to [0, 1] by the limits of " + o.robot;
  const RecordingAnalysis analysis = analyseRecording(recording, calibration, mapping, hand, fitOptions, provenance);
  const SynergyFit& fit = analysis.fit;
  if (!o.output.empty()) saveSynergyModel(o.output, fit.model);
  if (!o.plots.empty())
    writePlots(o, fit.model, mapToJoints(calibrate(recording, calibration), mapping, hand).postures, hand);

  const auto varying = [&](const std::string& name) -> Eigen::Index {
    for (std::size_t i = 0; i < fit.varyingJoints.size(); ++i)
      if (fit.varyingJoints[i] == name) return static_cast<Eigen::Index>(i);
    return -1;
  };
  nlohmann::json pairs = nlohmann::json::array();
  for (const auto& pair : figure7JointPairs()) {
    const auto a = varying(pair.first), b = varying(pair.second);
    if (a < 0 || b < 0) continue;
    const double r = fit.correlation(a, b);
    pairs.push_back({{"first", pair.first},
                     {"second", pair.second},
                     {"r", r},
                     {"r_paper_signs", r * paperSignOf(pair.first) * paperSignOf(pair.second)},
                     {"paper", pair.paper == PaperCorrelation::Positive   ? "positive"
                               : pair.paper == PaperCorrelation::Negative ? "negative"
                                                                          : "uncorrelated"}});
  }

  if (o.json) {
    nlohmann::json correlation = nlohmann::json::array();
    for (Eigen::Index i = 0; i < fit.correlation.rows(); ++i)
      correlation.push_back(numberListJson(fit.correlation.row(i).transpose()));
    nlohmann::json clampedPerJoint = nlohmann::json::object();
    for (std::size_t j = 0; j < hand.size(); ++j) clampedPerJoint[hand[j].name] = analysis.clampedPerJoint[j];
    nlohmann::json out = {{"frames", fit.frames},
                          {"synthetic", synthetic},
                          {"clamped_values", analysis.clampedValues},
                          {"clamped_per_joint", clampedPerJoint},
                          {"joint_names", fit.varyingJoints},
                          {"pca_joint_names", fit.pcaJoints},
                          {"constant_joints", fit.constantJoints},
                          {"cumulative_variance", numberListJson(fit.cumulativeVariance)},
                          {"correlation", correlation},
                          {"figure7_pairs", pairs}};
    out["model"] = synergyModelJson(fit.model);
    if (!o.output.empty()) out["model_file"] = o.output;
    std::cout << out.dump(2) << "\n";
    return 0;
  }

  std::cout << o.recording << ": " << fit.frames << " frames (" << recording.dataLocation << ")"
            << (synthetic ? ", SYNTHETIC operator data (not human)" : "") << "\n"
            << "calibration " << calibrationPath.string() << ", mapping " << mappingPath.string() << ", robot "
            << o.robot << "\n";
  std::printf("%lld joint values clamped at a limit (%.2f %% of %d frames x %zu joints)\n", analysis.clampedValues,
              100.0 * static_cast<double>(analysis.clampedValues) /
                  (static_cast<double>(fit.frames) * static_cast<double>(hand.size())),
              fit.frames, hand.size());
  std::cout << "PCA over " << fit.pcaJoints.size() << " joints normalised to [0, 1]";
  if (!fitOptions.ownAxisJoints.empty()) {
    std::cout << "; own axis:";
    for (const auto& name : fitOptions.ownAxisJoints) std::cout << " " << name;
  }
  if (!fit.constantJoints.empty()) {
    std::cout << "; constant, left out:";
    for (const auto& name : fit.constantJoints) std::cout << " " << name;
  }
  std::cout << "\n\n PMDs   variance %   cumulative %     (paper, Fig. 10: 42.19, 77.12, 84.71 % for 1, 2, 3)\n";
  for (int k = 0; k < fit.model.directionCount(); ++k)
    std::printf(" %4d   %10.2f   %12.2f\n", k + 1, 100 * fit.model.varianceFraction(k),
                100 * fit.cumulativeVariance(k));
  std::cout
      << "\nCorrelations of the paper's Fig. 7 joint pairs (r here; [r in the paper's signs, flexion negative])\n";
  for (const auto& pair : pairs)
    std::printf("  %-16s ~ %-16s %+6.3f  [%+6.3f]  paper: %s\n", pair["first"].get<std::string>().c_str(),
                pair["second"].get<std::string>().c_str(), pair["r"].get<double>(), pair["r_paper_signs"].get<double>(),
                pair["paper"].get<std::string>().c_str());
  if (!o.output.empty()) std::cout << "\nwrote " << o.output << "\n";
  return 0;
}

/// Every output is checked before any work, so a bad one leaves the others as they were.
void checkOutputs(const Options& o) {
  const std::initializer_list<std::filesystem::path> inputs{o.recording, o.calibration, o.mapping, o.graspit, o.show};
  if (!o.output.empty()) checkOutputPath(o.output, "-o", inputs);
  if (o.plots.empty()) return;
  createOutputFolder(o.plots, "--plots");
  for (const char* figure : {"cumulative_variance.svg", "joint_pairs.svg"})
    checkOutputPath(std::filesystem::path(o.plots) / figure, "--plots", inputs);
}

int run(const Options& o) {
  const int modes = !o.recording.empty() + !o.graspit.empty() + !o.show.empty() + !o.postures.empty();
  if (modes != 1)
    throw InputError("", "REC",
                     "give exactly one of: a glove recording, --postures FILE.csv (hand joint postures, no glove), "
                     "--from-graspit FILE.xml, --show MODEL.yaml");
  checkOutputs(o);
  StagedOutputs staged;  // the model and the figures renamed together, once all are written
  const int code = !o.show.empty()       ? runShow(o)
                   : !o.postures.empty() ? runPostures(o)
                   : !o.graspit.empty()  ? runGraspIt(o)
                                         : runRecording(o);
  staged.commit();
  return code;
}

const CommandRegistrar registrar{
    "synergies", "Glove recording -> principal motion directions (or import GraspIt eigengrasps, or show a model)",
    [](CLI::App& app) {
      auto o = std::make_shared<Options>();
      addPackagePathOption(app);
      app.add_option("recording", o->recording, "Glove recording: CSV, or a raw 'G'-reply stream (.bin/.raw/.serial)");
      app.add_option("--format", o->format, "Recording format: csv, serial or auto (by extension; default)");
      app.add_option("--calibration", o->calibration, "Calibration YAML (default: REC's name with .calibration.yaml)");
      app.add_option("--mapping", o->mapping,
                     "Sensor -> joint mapping YAML (default data/glove/cyberglove22_to_sah.yaml)");
      app.add_option("--robot", o->robot, "Built-in robot name or .urdf file (default sah_tx90)");
      app.add_option("--own-axis", o->ownAxis,
                     "Joints kept as axes of their own (default thumb_base if the hand has it; 'none')")
          ->delimiter(',');
      app.add_option("-o,--output", o->output, "Synergy model file to write (YAML)");
      app.add_flag("--json", o->json, "Print JSON instead of text");
      app.add_option("--from-graspit", o->graspit,
                     "Import a GraspIt eigengrasp XML file instead of reading a recording");
      app.add_option("--joints", o->graspitJoints, "With --from-graspit: the robot joint of each dimension, in order")
          ->delimiter(',');
      app.add_option("--show", o->show, "Check and print a synergy model file");
      app.add_option("--postures", o->postures,
                     "PCA of hand joint postures from a CSV (header: hand joint names; no glove)");
      app.add_option("--units", o->units, "With --postures: deg (default) or rad");
      app.add_option(
          "--plots", o->plots,
          "Write the figures as SVG into this folder (Fig. 10 variance; Fig. 7 joint pairs from a recording)");
      return [o] { return run(*o); };
    }};

}  // namespace
}  // namespace pmdplan::cli::synergies_command
