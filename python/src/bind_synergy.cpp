// pmdplan.SynergyModel and pmdplan.fit_synergies: principal motion directions fitted from posture
// arrays, loaded and saved as model files, and the maps between postures (radians, the model's
// joints) and coefficients along the directions (normalised units, as in the model file).
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "bindings.hpp"
#include "conversions.hpp"
#include "pmdplan/core/command_files.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/synergy/synergy_fit.hpp"
#include "pmdplan/synergy/synergy_model_file.hpp"
#include "pmdplan/synergy/synergy_model_resolution.hpp"
#include "pmdplan/synergy/synergy_projection.hpp"
#include "pmdplan/synergy/synergy_readout.hpp"

namespace pmdplan::python {
namespace {

PySynergyModel modelOf(SynergyModel model, std::string source) {
  return PySynergyModel{std::make_shared<const SynergyModel>(std::move(model)), std::move(source)};
}

std::vector<int> identitySlots(const SynergyModel& model) {
  std::vector<int> slots(model.joints.size());
  for (std::size_t i = 0; i < slots.size(); ++i) slots[i] = static_cast<int>(i);
  return slots;
}

Eigen::VectorXd normalised(const SynergyModel& model, const Eigen::VectorXd& posture) {
  Eigen::VectorXd unit(posture.size());
  for (int j = 0; j < model.jointCount(); ++j)
    unit[j] = model.joints[static_cast<std::size_t>(j)].normalise(posture[j]);
  return unit;
}

Eigen::VectorXd denormalised(const SynergyModel& model, const Eigen::VectorXd& unit) {
  Eigen::VectorXd posture(unit.size());
  for (int j = 0; j < model.jointCount(); ++j)
    posture[j] = model.joints[static_cast<std::size_t>(j)].denormalise(unit[j]);
  return posture;
}

/// The lower or upper limit of every model joint (radians).
Eigen::VectorXd jointBounds(const SynergyModel& model, double JointLimit::*bound) {
  Eigen::VectorXd values(model.jointCount());
  for (int j = 0; j < values.size(); ++j) values[j] = model.joints[static_cast<std::size_t>(j)].*bound;
  return values;
}

int directionsArgument(const SynergyModel& model, int directions) {
  if (directions < 0 || directions > model.directionCount())
    throw InputError("", "directions", "expected 0 to " + std::to_string(model.directionCount()) + " directions");
  return directions;
}

/// The posture's point in the subspace of the own axes plus the first `directions` PMDs (radians).
Eigen::VectorXd projected(const SynergyModel& model, const Eigen::VectorXd& posture, int directions) {
  const Eigen::VectorXd unit = normalised(model, posture);
  Eigen::VectorXd deviation = unit - model.mean;
  for (const auto& name : model.ownAxisJoints) deviation[model.jointIndex(name)] = 0.0;
  Eigen::VectorXd inSubspace = Eigen::VectorXd::Zero(unit.size());
  if (directions > 0) {
    const auto basis = model.directions.leftCols(directions);
    const Eigen::VectorXd s = model.orthonormal ? Eigen::VectorXd(basis.transpose() * deviation)
                                                : Eigen::VectorXd(basis.colPivHouseholderQr().solve(deviation));
    inSubspace = basis * s;
  }
  return denormalised(model, unit - deviation + inSubspace);
}

JointLimits fitJointsFrom(py::handle joints) {
  if (py::isinstance<PyRobot>(joints)) {
    const RobotModel& robot = *joints.cast<const PyRobot&>().model;
    if (!robot.hasGroup("hand"))
      throw InputError(robot.urdfPath().string(), "groups", "the robot has no 'hand' group to fit synergies for");
    return robot.groupJoints("hand");
  }
  JointLimits limits;
  try {
    for (const auto& [name, lower, upper] : joints.cast<std::vector<std::tuple<std::string, double, double>>>())
      limits.push_back(JointLimit{name, lower, upper});
  } catch (const py::cast_error&) {
    throw InputError("", "joints", "expected a Robot (its hand group) or a list of (name, lower, upper) in radians");
  }
  for (const auto& joint : limits)
    if (!(joint.upper > joint.lower))
      throw InputError("", "joints", "joint '" + joint.name + "': expected lower < upper");
  return limits;
}

void bindModel(py::module_& m) {
  py::class_<PySynergyModel>(
      m, "SynergyModel",
      "Principal motion directions of a hand: mean posture, directions ordered by variance, their sigma;\n"
      "all in joint values normalised to [0, 1] by the model's joint limits. Postures passed in and\n"
      "returned are radians for the model's joints (joint_names order, or a dict).")
      .def_static(
          "load", [](const std::filesystem::path& path) { return modelOf(loadSynergyModel(path), path.string()); },
          py::arg("path"),
          "Reads a synergy model file (YAML); raises InputError naming the file and key for malformed content.")
      .def_static(
          "default_for",
          [](const std::string& robot) {
            ResolvedSynergyModel shipped = resolveSynergyModel(robot, {}, SynergyModelNeed::Required);
            return modelOf(std::move(*shipped.model), shipped.file.string());
          },
          py::arg("robot_name"), "The robot's shipped model (data/synergies/<robot>_default.yaml).")
      .def(
          "save",
          [](const PySynergyModel& s, const std::filesystem::path& path) {
            const CommandFileScope files;  // the output rule of the CLI (core/command_files.hpp)
            saveSynergyModel(path, *s.model);
          },
          py::arg("path"),
          "Writes the model file (atomically; numbers in their shortest exact form, so it loads back identical).")
      .def(
          "to_yaml", [](const PySynergyModel& s) { return formatSynergyModel(*s.model); }, "The model file's text.")
      .def_property_readonly(
          "source", [](const PySynergyModel& s) { return s.source; }, "The file it was read from, if any.")
      .def_property_readonly("joint_names",
                             [](const PySynergyModel& s) {
                               std::vector<std::string> names;
                               for (const auto& joint : s.model->joints) names.push_back(joint.name);
                               return names;
                             })
      .def_property_readonly("lower", [](const PySynergyModel& s) { return jointBounds(*s.model, &JointLimit::lower); })
      .def_property_readonly("upper", [](const PySynergyModel& s) { return jointBounds(*s.model, &JointLimit::upper); })
      .def_property_readonly("own_axis_joints", [](const PySynergyModel& s) { return s.model->ownAxisJoints; })
      .def_property_readonly(
          "mean", [](const PySynergyModel& s) { return Eigen::VectorXd(s.model->mean); }, "b, normalised units.")
      .def_property_readonly(
          "directions", [](const PySynergyModel& s) { return Eigen::MatrixXd(s.model->directions); },
          "(joints, directions): column i is PMD i+1.")
      .def_property_readonly("sigma", [](const PySynergyModel& s) { return Eigen::VectorXd(s.model->sigma); })
      .def_property_readonly("variance_fraction",
                             [](const PySynergyModel& s) { return Eigen::VectorXd(s.model->varianceFraction); })
      .def_property_readonly(
          "cumulative_variance",
          [](const PySynergyModel& s) {
            Eigen::VectorXd cumulative = s.model->varianceFraction;
            for (Eigen::Index i = 1; i < cumulative.size(); ++i) cumulative[i] += cumulative[i - 1];
            return cumulative;
          },
          "Share of the variance held by the first 1, 2, ... directions (the paper's Fig. 10).")
      .def_property_readonly("orthonormal", [](const PySynergyModel& s) { return s.model->orthonormal; })
      .def_property_readonly("provenance", [](const PySynergyModel& s) { return s.model->provenance; })
      .def_property_readonly("direction_count", [](const PySynergyModel& s) { return s.model->directionCount(); })
      .def(
          "coefficients",
          [](const PySynergyModel& s, py::handle posture) {
            return synergyCoefficients(
                *s.model, normalised(*s.model, jointValuesFrom(s.model->joints, posture, "posture", false)));
          },
          py::arg("posture"),
          "Coefficients along every direction of a posture (least squares for a non-orthonormal basis).")
      .def(
          "posture",
          [](const PySynergyModel& s, const Eigen::VectorXd& coefficients) {
            if (coefficients.size() > s.model->directionCount())
              throw InputError("", "coefficients",
                               "expected at most " + std::to_string(s.model->directionCount()) + " coefficients");
            return denormalised(*s.model, postureFromCoefficients(*s.model, coefficients));
          },
          py::arg("coefficients"),
          "mean + D s in radians (the first len(s) directions; own axes at their mean; not clamped).")
      .def(
          "project",
          [](const PySynergyModel& s, py::handle posture, int directions) {
            return projected(*s.model, jointValuesFrom(s.model->joints, posture, "posture", false),
                             directionsArgument(*s.model, directions));
          },
          py::arg("posture"), py::arg("directions") = 4,
          "The nearest posture in the subspace the planner samples: own axes (kept) plus the first `directions` PMDs.")
      .def(
          "distance_from_subspace",
          [](const PySynergyModel& s, py::handle posture) {
            const Eigen::VectorXd values = jointValuesFrom(s.model->joints, posture, "posture", false);
            return Eigen::VectorXd(synergyReadout(*s.model, identitySlots(*s.model), values).distanceFromSubspace);
          },
          py::arg("posture"),
          "Entry k: normalised distance of the posture from the own axes plus the first k PMDs (k = 0 ... count).")
      .def("__repr__", [](const PySynergyModel& s) {
        return "<pmdplan.SynergyModel " + std::to_string(s.model->jointCount()) + " joints, " +
               std::to_string(s.model->directionCount()) + " directions>";
      });
}

void bindFit(py::module_& m) {
  m.def(
      "fit_synergies",
      [](const Eigen::MatrixXd& postures, py::handle joints, std::vector<std::string> ownAxisJoints,
         double constantTolerance, std::string provenance) {
        const JointLimits limits = fitJointsFrom(joints);
        if (postures.cols() != static_cast<Eigen::Index>(limits.size()))
          throw InputError(
              "", "postures",
              "expected an array of shape (frames, " + std::to_string(limits.size()) + "): one column per joint");
        SynergyFitSettings options;
        options.ownAxisJoints = std::move(ownAxisJoints);
        options.constantTolerance = constantTolerance;
        SynergyFit fit;
        {
          py::gil_scoped_release release;
          fit = fitSynergyModel(postures, limits, options, PostureSource{"", "postures", provenance});
        }
        py::dict result;
        result["model"] = modelOf(std::move(fit.model), "");
        result["frames"] = fit.frames;
        result["pca_joints"] = fit.pcaJoints;
        result["constant_joints"] = fit.constantJoints;
        result["varying_joints"] = fit.varyingJoints;
        result["correlation"] = fit.correlation;
        result["cumulative_variance"] = fit.cumulativeVariance;
        return result;
      },
      py::arg("postures"), py::arg("joints"), py::arg("own_axis_joints") = std::vector<std::string>{},
      py::arg("constant_tolerance") = 1e-12, py::arg("provenance") = "fitted from a numpy array",
      "PCA of postures (frames, joints) in radians: joints is a Robot (its hand group) or [(name, lower, upper)].\n"
      "Returns {'model': SynergyModel, 'frames', 'pca_joints', 'constant_joints', 'varying_joints', 'correlation',\n"
      "'cumulative_variance'}. Own-axis joints (SAH: thumb_base) stay out of the PCA; raises InputError for bad data.");
}

}  // namespace

PySynergyModel synergyModelArgument(const Task& task, py::handle synergies) {
  if (py::isinstance<PySynergyModel>(synergies)) return synergies.cast<PySynergyModel>();
  const std::filesystem::path given =
      synergies.is_none() ? std::filesystem::path() : std::filesystem::path(py::str(synergies).cast<std::string>());
  ResolvedSynergyModel resolved;
  try {
    resolved = resolveSynergyModelForHand(*task.robot, given, SynergyModelNeed::Required);
  } catch (const InputError& e) {
    if (!e.file().empty()) throw;
    throw InputError("", "synergies", e.message());  // the argument's name, not the CLI's flag
  }
  return modelOf(std::move(*resolved.model), resolved.file.string());
}

void bindSynergies(py::module_& m) {
  bindModel(m);
  bindFit(m);
}

}  // namespace pmdplan::python
