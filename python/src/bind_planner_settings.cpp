// pmdplan.PlannerSettings: every field of PlannerSettings (planning/planner_settings.hpp),
// bound one by one. The only file of the module that names the fields, so that a change of the
// parameter struct is adapted here alone.
#include <pybind11/stl.h>

#include <optional>
#include <sstream>

#include "bindings.hpp"
#include "planner_settings.hpp"
#include "pmdplan/bench/planner_roster.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/core/sequences/sample_sequence.hpp"

namespace pmdplan::python {
namespace {

std::string growthName(ArmBoxGrowth growth) { return growth == ArmBoxGrowth::Linear ? "linear" : "factorial"; }

ArmBoxGrowth growthFrom(const std::string& name) {
  if (name == "factorial") return ArmBoxGrowth::Factorial;
  if (name == "linear") return ArmBoxGrowth::Linear;
  throw InputError("", "arm_box_growth", "'" + name + "' is not a growth; expected factorial or linear");
}

HandSamplingMode modeFrom(const std::string& planner) {
  const auto entry = findPlanner(planner);
  if (!entry || entry->family != PlannerFamily::PmdRoadmap)
    throw InputError("", "--planner",
                     "'" + planner + "' is not a planner; expected pmd, full, pmd-lazy or pmd-connect");
  return entry->mode;
}

}  // namespace

PlannerSettings plannerParametersFrom(py::handle settings, HandSamplingMode mode, std::optional<std::uint64_t> seed,
                                        std::optional<double> timeLimit) {
  PlannerSettings parameters = PlannerSettings::defaultsFor(mode);
  if (!settings.is_none()) {
    try {
      parameters = settings.cast<PlannerSettings>();
    } catch (const py::cast_error&) {
      throw InputError("", "settings", "expected a pmdplan.PlannerSettings");
    }
  }
  if (seed) parameters.seed = *seed;
  if (timeLimit) parameters.timeLimit = *timeLimit;
  return parameters;
}

std::uint64_t seedOf(const PlannerSettings& parameters) { return parameters.seed; }

double defaultTimeLimit() { return PlannerSettings{}.timeLimit; }

void checkPlannerParameters(const PlannerSettings& parameters) {
  try {
    parameters.check();
  } catch (const InputError& e) {
    throw InputError("", "--" + e.field(), e.message());  // the field as the CLI names it
  }
}

void bindPlannerSettings(py::module_& m) {
  py::class_<PlannerSettings>(m, "PlannerSettings",
                                "Settings of the PMD roadmap planner (Algorithm 4); defaults from the paper's Table 3.")
      .def(py::init([](const std::string& planner) { return PlannerSettings::defaultsFor(modeFrom(planner)); }),
           py::arg("planner") = "pmd",
           "Table 3's values for planner 'pmd', 'pmd-lazy' or 'pmd-connect' (n_A = n_H = 10) or 'full' (20).")
      .def_readwrite("initial_arm_half_size", &PlannerSettings::rhoA,
                     "rho_a: initial half-size of the arm hypercubes, normalised units (Table 3: 0.001).")
      .def_property(
          "arm_box_growth", [](const PlannerSettings& p) { return growthName(p.rhoAGrowth); },
          [](PlannerSettings& p, const std::string& name) { p.rhoAGrowth = growthFrom(name); },
          "'factorial' (rho_a(k) = k rho_a(k-1), Algorithm 4 read literally) or 'linear' (k rho_a(1)).")
      .def_readwrite("neighbour_count", &PlannerSettings::neighbours,
                     "K: most neighbours a new sample is connected to (10).")
      .def_readwrite("neighbour_threshold_factor", &PlannerSettings::neighbourThreshold,
                     "Neighbour radius as a multiple of d(start, goal) (1, the paper's; docs/deviations.md).")
      .def_readwrite("arm_trials", &PlannerSettings::armTrials, "n_A: arm configurations per hypercube.")
      .def_readwrite("hand_trials", &PlannerSettings::handTrials, "n_H: hand configurations per arm configuration.")
      .def_readwrite("min_sweep_visits", &PlannerSettings::sweepVisits,
                     "Hypercube visits a sweep makes before rho_a grows (10).")
      .def_readwrite("max_samples", &PlannerSettings::maxSamples,
                     "N: samples (hand-arm draws) after which the run fails.")
      .def_readwrite("time_limit", &PlannerSettings::timeLimit,
                     "Wall-clock bound of the roadmap construction, seconds.")
      .def_readwrite("seed", &PlannerSettings::seed, "Seed of the run's random numbers.")
      .def_property(
          "kappa", [](const PlannerSettings& p) { return p.pmdBox.kappa; },
          [](PlannerSettings& p, double v) { p.pmdBox.kappa = v; },
          "Half-width of the PMD hand box along PMD i, in standard deviations sigma_i (2).")
      .def_property(
          "max_pmds", [](const PlannerSettings& p) { return p.pmdBox.maxPmds; },
          [](PlannerSettings& p, int v) { p.pmdBox.maxPmds = v; }, "Most PMDs the hand dimension grows to (4).")
      .def_readwrite("smooth", &PlannerSettings::smooth, "Smooth the path (Sect. 5.3).")
      .def_property(
          "lazy_batch", [](const PlannerSettings& p) { return p.lazy.batch; },
          [](PlannerSettings& p, std::size_t v) { p.lazy.batch = v; },
          "pmd-lazy: arm boxes sampled along the segment per round, besides the four at its ends (2).")
      .def_property(
          "lazy_neighbours", [](const PlannerSettings& p) { return p.lazy.neighbours; },
          [](PlannerSettings& p, std::size_t v) { p.lazy.neighbours = v; },
          "pmd-lazy: most lazy edges from a new sample to its nearest nodes (10).")
      .def_property(
          "lazy_radius", [](const PlannerSettings& p) { return p.lazy.radius; },
          [](PlannerSettings& p, double v) { p.lazy.radius = v; },
          "pmd-lazy: lazy edges join nodes at most this multiple of d(start, goal) apart (1).")
      .def_property(
          "lazy_probes", [](const PlannerSettings& p) { return p.lazy.probes; },
          [](PlannerSettings& p, std::size_t v) { p.lazy.probes = v; },
          "pmd-lazy: inner states of each candidate edge checked before its motion check (10).")
      .def_property(
          "lazy_arm_growth", [](const PlannerSettings& p) { return p.lazy.armGrowth; },
          [](PlannerSettings& p, double v) { p.lazy.armGrowth = v; },
          "pmd-lazy: rho_a is multiplied by this after each round without a path (2).")
      .def_property(
          "sequence", [](const PlannerSettings& p) { return sampleSequenceName(p.sequence); },
          [](PlannerSettings& p, const std::string& name) {
            const std::optional<SampleSequence> sequence = parseSampleSequence(name);
            if (!sequence)
              throw InputError("", "--sequence",
                               "'" + name + "' is not a sample sequence; expected " + knownSampleSequenceNames());
            p.sequence = *sequence;
          },
          "Where the samplers' numbers come from: 'random' (default), 'halton' or 'sdk'.")
      .def_property(
          "connect_range", [](const PlannerSettings& p) { return p.connect.range; },
          [](PlannerSettings& p, double v) { p.connect.range = v; },
          "pmd-connect: longest tree step, as a multiple of d(start, goal) (1; inf: none).")
      .def_property(
          "connect_round", [](const PlannerSettings& p) { return p.connect.round; },
          [](PlannerSettings& p, std::size_t v) { p.connect.round = v; },
          "pmd-connect: samples per round; the arm region grows after each round that left the trees apart (2).")
      .def_property(
          "connect_arm_growth", [](const PlannerSettings& p) { return p.connect.armGrowth; },
          [](PlannerSettings& p, double v) { p.connect.armGrowth = v; },
          "pmd-connect: factor of the arm region's largest half-size after each such round (8).")
      .def_property(
          "connect_probes", [](const PlannerSettings& p) { return p.connect.probes; },
          [](PlannerSettings& p, std::size_t v) { p.connect.probes = v; },
          "pmd-connect: inner states of a new tree step checked before it joins its tree (4).")
      .def("check", &checkPlannerParameters, "Raises InputError (the CLI's message) for a value out of range.")
      .def("__repr__", [](const PlannerSettings& p) {
        std::ostringstream text;
        text << "PlannerSettings(initial_arm_half_size=" << p.rhoA << ", arm_box_growth='"
             << growthName(p.rhoAGrowth) << "', neighbour_count=" << p.neighbours
             << ", neighbour_threshold_factor=" << p.neighbourThreshold << ", arm_trials=" << p.armTrials
             << ", hand_trials=" << p.handTrials << ", min_sweep_visits=" << p.sweepVisits
             << ", max_samples=" << p.maxSamples << ", time_limit=" << p.timeLimit << ", seed=" << p.seed
             << ", smooth=" << (p.smooth ? "True" : "False") << ")";
        return text.str();
      });
}

}  // namespace pmdplan::python
