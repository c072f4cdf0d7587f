// pmdplan.PlannerSettings: every field of PlannerParameters (planning/planner_parameters.hpp),
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

PlannerParameters plannerParametersFrom(py::handle settings, HandSamplingMode mode, std::optional<std::uint64_t> seed,
                                        std::optional<double> timeLimit) {
  PlannerParameters parameters = PlannerParameters::defaultsFor(mode);
  if (!settings.is_none()) {
    try {
      parameters = settings.cast<PlannerParameters>();
    } catch (const py::cast_error&) {
      throw InputError("", "settings", "expected a pmdplan.PlannerSettings");
    }
  }
  if (seed) parameters.seed = *seed;
  if (timeLimit) parameters.timeLimit = *timeLimit;
  return parameters;
}

std::uint64_t seedOf(const PlannerParameters& parameters) { return parameters.seed; }

double defaultTimeLimit() { return PlannerParameters{}.timeLimit; }

void checkPlannerParameters(const PlannerParameters& parameters) {
  try {
    parameters.check();
  } catch (const InputError& e) {
    throw InputError("", "--" + e.field(), e.message());  // the field as the CLI names it
  }
}

void bindPlannerSettings(py::module_& m) {
  py::class_<PlannerParameters>(m, "PlannerSettings",
                                "Settings of the PMD roadmap planner (Algorithm 4); defaults from the paper's Table 3.")
      .def(py::init([](const std::string& planner) { return PlannerParameters::defaultsFor(modeFrom(planner)); }),
           py::arg("planner") = "pmd",
           "Table 3's values for planner 'pmd', 'pmd-lazy' or 'pmd-connect' (n_A = n_H = 10) or 'full' (20).")
      .def_readwrite("initial_arm_half_size", &PlannerParameters::initialArmHalfSize,
                     "rho_a: initial half-size of the arm hypercubes, normalised units (Table 3: 0.001).")
      .def_property(
          "arm_box_growth", [](const PlannerParameters& p) { return growthName(p.armBoxGrowth); },
          [](PlannerParameters& p, const std::string& name) { p.armBoxGrowth = growthFrom(name); },
          "'factorial' (rho_a(k) = k rho_a(k-1), Algorithm 4 read literally) or 'linear' (k rho_a(1)).")
      .def_readwrite("neighbour_count", &PlannerParameters::neighbourCount,
                     "K: most neighbours a new sample is connected to (10).")
      .def_readwrite("neighbour_threshold_factor", &PlannerParameters::neighbourThresholdFactor,
                     "Neighbour radius as a multiple of d(start, goal) (1, the paper's; docs/deviations.md).")
      .def_readwrite("arm_trials", &PlannerParameters::armTrials, "n_A: arm configurations per hypercube.")
      .def_readwrite("hand_trials", &PlannerParameters::handTrials, "n_H: hand configurations per arm configuration.")
      .def_readwrite("min_sweep_visits", &PlannerParameters::minSweepVisits,
                     "Hypercube visits a sweep makes before rho_a grows (10).")
      .def_readwrite("max_samples", &PlannerParameters::maxSamples,
                     "N: samples (hand-arm draws) after which the run fails.")
      .def_readwrite("time_limit", &PlannerParameters::timeLimit,
                     "Wall-clock bound of the roadmap construction, seconds.")
      .def_readwrite("seed", &PlannerParameters::seed, "Seed of the run's random numbers.")
      .def_property(
          "kappa", [](const PlannerParameters& p) { return p.pmdBox.kappa; },
          [](PlannerParameters& p, double v) { p.pmdBox.kappa = v; },
          "Half-width of the PMD hand box along PMD i, in standard deviations sigma_i (2).")
      .def_property(
          "max_pmds", [](const PlannerParameters& p) { return p.pmdBox.maxDirections; },
          [](PlannerParameters& p, int v) { p.pmdBox.maxDirections = v; }, "Most PMDs the hand dimension grows to (4).")
      .def_readwrite("smooth", &PlannerParameters::smooth, "Smooth the path (Sect. 5.3).")
      .def_property(
          "lazy_batch", [](const PlannerParameters& p) { return p.lazy.batch; },
          [](PlannerParameters& p, std::size_t v) { p.lazy.batch = v; },
          "pmd-lazy: arm boxes sampled along the segment per round, besides the four at its ends (2).")
      .def_property(
          "lazy_neighbours", [](const PlannerParameters& p) { return p.lazy.neighbours; },
          [](PlannerParameters& p, std::size_t v) { p.lazy.neighbours = v; },
          "pmd-lazy: most lazy edges from a new sample to its nearest nodes (10).")
      .def_property(
          "lazy_radius", [](const PlannerParameters& p) { return p.lazy.radiusFactor; },
          [](PlannerParameters& p, double v) { p.lazy.radiusFactor = v; },
          "pmd-lazy: lazy edges join nodes at most this multiple of d(start, goal) apart (1).")
      .def_property(
          "lazy_probes", [](const PlannerParameters& p) { return p.lazy.probes; },
          [](PlannerParameters& p, std::size_t v) { p.lazy.probes = v; },
          "pmd-lazy: inner states of each candidate edge checked before its motion check (10).")
      .def_property(
          "lazy_arm_growth", [](const PlannerParameters& p) { return p.lazy.armGrowth; },
          [](PlannerParameters& p, double v) { p.lazy.armGrowth = v; },
          "pmd-lazy: rho_a is multiplied by this after each round without a path (2).")
      .def_property(
          "sequence", [](const PlannerParameters& p) { return sampleSequenceName(p.sequence); },
          [](PlannerParameters& p, const std::string& name) {
            const std::optional<SampleSequence> sequence = parseSampleSequence(name);
            if (!sequence)
              throw InputError("", "--sequence",
                               "'" + name + "' is not a sample sequence; expected " + knownSampleSequenceNames());
            p.sequence = *sequence;
          },
          "Where the samplers' numbers come from: 'random' (default), 'halton' or 'sdk'.")
      .def_property(
          "connect_range", [](const PlannerParameters& p) { return p.connect.rangeFactor; },
          [](PlannerParameters& p, double v) { p.connect.rangeFactor = v; },
          "pmd-connect: longest tree step, as a multiple of d(start, goal) (1; inf: none).")
      .def_property(
          "connect_round", [](const PlannerParameters& p) { return p.connect.roundSamples; },
          [](PlannerParameters& p, std::size_t v) { p.connect.roundSamples = v; },
          "pmd-connect: samples per round; the arm region grows after each round that left the trees apart (2).")
      .def_property(
          "connect_arm_growth", [](const PlannerParameters& p) { return p.connect.armGrowth; },
          [](PlannerParameters& p, double v) { p.connect.armGrowth = v; },
          "pmd-connect: factor of the arm region's largest half-size after each such round (8).")
      .def_property(
          "connect_probes", [](const PlannerParameters& p) { return p.connect.probes; },
          [](PlannerParameters& p, std::size_t v) { p.connect.probes = v; },
          "pmd-connect: inner states of a new tree step checked before it joins its tree (4).")
      .def("check", &checkPlannerParameters, "Raises InputError (the CLI's message) for a value out of range.")
      .def("__repr__", [](const PlannerParameters& p) {
        std::ostringstream text;
        text << "PlannerSettings(initial_arm_half_size=" << p.initialArmHalfSize << ", arm_box_growth='"
             << growthName(p.armBoxGrowth) << "', neighbour_count=" << p.neighbourCount
             << ", neighbour_threshold_factor=" << p.neighbourThresholdFactor << ", arm_trials=" << p.armTrials
             << ", hand_trials=" << p.handTrials << ", min_sweep_visits=" << p.minSweepVisits
             << ", max_samples=" << p.maxSamples << ", time_limit=" << p.timeLimit << ", seed=" << p.seed
             << ", smooth=" << (p.smooth ? "True" : "False") << ")";
        return text.str();
      });
}

}  // namespace pmdplan::python
