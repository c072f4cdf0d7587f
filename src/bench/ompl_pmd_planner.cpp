#include "pmdplan/bench/ompl_pmd_planner.hpp"

#include <ompl/base/PlannerData.h>
#include <ompl/base/goals/GoalSampleableRegion.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/PathGeometric.h>

#include <limits>
#include <memory>
#include <stdexcept>

#include "pmdplan/core/input_error.hpp"
#include "pmdplan/planning/planner_setting_table.hpp"
#include "pmdplan/planning/pmd_roadmap_planner.hpp"

namespace pmdplan {
namespace {

namespace ob = ompl::base;

/// Thrown from the progress callback when the termination condition holds: it ends solve().
struct TerminationRequested {};

/// Our StateValidator over the space information's validity checker.
class SpaceInformationStates final : public StateValidator {
 public:
  SpaceInformationStates(const ob::SpaceInformationPtr& si,
                         std::function<void(const Configuration&, ob::State*)> toState)
      : si_(si), toState_(std::move(toState)), scratch_(si->allocState()) {}
  SpaceInformationStates(const SpaceInformationStates&) = delete;
  ~SpaceInformationStates() override { si_->freeState(scratch_); }
  bool isValid(const Configuration& q) override {
    ++checks_;
    toState_(q, scratch_);
    return si_->satisfiesBounds(scratch_) && si_->isValid(scratch_);
  }
  bool isArmValid(const Configuration&) override {  // no arm-only check in OMPL (see the header)
    ++checks_;
    return true;
  }
  std::size_t checkCount() const override { return checks_; }

 private:
  ob::SpaceInformationPtr si_;
  std::function<void(const Configuration&, ob::State*)> toState_;
  ob::State* scratch_;
  std::size_t checks_ = 0;
};

/// Our MotionValidator over the space information's motion validator.
class SpaceInformationMotions final : public MotionValidator {
 public:
  SpaceInformationMotions(const ob::SpaceInformationPtr& si,
                          std::function<void(const Configuration&, ob::State*)> toState)
      : si_(si), toState_(std::move(toState)), from_(si->allocState()), to_(si->allocState()) {}
  SpaceInformationMotions(const SpaceInformationMotions&) = delete;
  ~SpaceInformationMotions() override {
    si_->freeState(from_);
    si_->freeState(to_);
  }
  bool isValid(const Configuration& from, const Configuration& to) override {
    ++checks_;
    toState_(from, from_);
    toState_(to, to_);
    return si_->checkMotion(from_, to_);
  }
  std::size_t statesChecked() const override { return checks_; }

 private:
  ob::SpaceInformationPtr si_;
  std::function<void(const Configuration&, ob::State*)> toState_;
  ob::State* from_;
  ob::State* to_;
  std::size_t checks_ = 0;
};

/// One row of plannerSettingTable() as an OMPL parameter of the planner's settings: OMPL's
/// parameters are text, and so are the table's setters and getters. A value the row rejects is
/// refused (setParam returns false) with OMPL's warning, as OMPL's own parameters do.
class TableSettingParam final : public ob::GenericParam {
 public:
  TableSettingParam(const PlannerSetting& row, PlannerSettings& settings)
      : ob::GenericParam(row.name()), row_(row), settings_(settings) {
    if (row.kind == SettingKind::Choice || row.kind == SettingKind::Switch) {
      std::string choices;
      for (const std::string& choice : row.choices) choices += (choices.empty() ? "" : ",") + choice;
      setRangeSuggestion(choices);  // OMPL's form of an enum's values
    }
  }
  bool setValue(const std::string& value) override {
    try {
      row_.set(settings_, value);
      return true;
    } catch (const InputError& e) {
      OMPL_WARN("Invalid value for parameter '%s': %s", name_.c_str(), e.message().c_str());
      return false;
    }
  }
  std::string getValue() const override { return row_.get(settings_); }

 private:
  const PlannerSetting& row_;
  PlannerSettings& settings_;
};

ob::PlannerStatus::StatusType omplStatus(PlannerStatus status) {
  switch (status) {
    case PlannerStatus::Solved:
      return ob::PlannerStatus::EXACT_SOLUTION;
    case PlannerStatus::InvalidStart:
      return ob::PlannerStatus::INVALID_START;
    case PlannerStatus::InvalidGoal:
      return ob::PlannerStatus::INVALID_GOAL;
    case PlannerStatus::SampleLimit:
      return ob::PlannerStatus::ABORT;
    default:
      return ob::PlannerStatus::TIMEOUT;
  }
}

}  // namespace

OmplPmdPlanner::OmplPmdPlanner(const ob::SpaceInformationPtr& si, PlanningSpace space, HandSamplingMode mode,
                               std::shared_ptr<const SynergyModel> synergies, const std::string& name)
    : ob::Planner(si, name.empty() ? (mode == HandSamplingMode::Synergy ? "PMD" : "PMDFull") : name),
      space_(std::move(space)),
      mode_(mode),
      synergies_(std::move(synergies)),
      parameters_(PlannerSettings::defaultsFor(mode)) {
  if (mode_ == HandSamplingMode::Synergy && !synergies_)
    throw std::invalid_argument("OmplPmdPlanner: the PMD mode needs a synergy model");
  specs_.recognizedGoal = ob::GOAL_SAMPLEABLE_REGION;
  specs_.approximateSolutions = false;
  specs_.optimizingPaths = false;
  specs_.multithreaded = false;
  parameters_.seed = 0;
  parameters_.timeLimit = std::numeric_limits<double>::infinity();
  declareParameters();
}

OmplPmdPlanner::~OmplPmdPlanner() { releaseDataStates(); }

void OmplPmdPlanner::declareParameters() {
  for (const PlannerSetting& row : plannerSettingTable())
    params().add(std::make_shared<TableSettingParam>(row, parameters_));
}

void OmplPmdPlanner::setup() {
  ob::Planner::setup();
  const auto* bounded = si_->getStateSpace()->as<ob::RealVectorStateSpace>();
  if (!bounded || si_->getStateDimension() != static_cast<unsigned>(space_.dof()))
    throw std::invalid_argument("OmplPmdPlanner: expected a RealVectorStateSpace of " + std::to_string(space_.dof()) +
                                " dimensions");
  const auto& bounds = bounded->getBounds();
  boundsLow_ = bounds.low;
  boundsExtent_.resize(bounds.low.size());
  for (std::size_t i = 0; i < bounds.low.size(); ++i) boundsExtent_[i] = bounds.high[i] - bounds.low[i];
}

Configuration OmplPmdPlanner::configurationOf(const ob::State* state) const {
  const double* values = state->as<ob::RealVectorStateSpace::StateType>()->values;
  Eigen::VectorXd unit(space_.dof());
  for (int i = 0; i < space_.dof(); ++i)
    unit[i] = (values[i] - boundsLow_[static_cast<std::size_t>(i)]) / boundsExtent_[static_cast<std::size_t>(i)];
  return space_.denormalise(unit);
}

void OmplPmdPlanner::setState(const Configuration& q, ob::State* state) const {
  double* values = state->as<ob::RealVectorStateSpace::StateType>()->values;
  const Eigen::VectorXd unit = space_.normalise(q);
  for (int i = 0; i < space_.dof(); ++i)
    values[i] = boundsLow_[static_cast<std::size_t>(i)] + unit[i] * boundsExtent_[static_cast<std::size_t>(i)];
}

ob::PlannerStatus OmplPmdPlanner::solve(const ob::PlannerTerminationCondition& ptc) {
  checkValidity();
  const ob::State* start = pis_.nextStart();
  if (!start) return ob::PlannerStatus::INVALID_START;
  const auto* goalRegion = pdef_->getGoal()->as<ob::GoalSampleableRegion>();
  if (!goalRegion || !goalRegion->canSample()) return ob::PlannerStatus::UNRECOGNIZED_GOAL_TYPE;
  ob::State* goal = si_->allocState();
  goalRegion->sampleGoal(goal);
  const Configuration startConfiguration = configurationOf(start);
  const Configuration goalConfiguration = configurationOf(goal);
  si_->freeState(goal);

  const auto toState = [this](const Configuration& q, ob::State* state) { setState(q, state); };
  // The validators outlive the planner kept for getPlannerData: its progress callback owns them.
  struct Run {
    Run(const ob::SpaceInformationPtr& si, const std::function<void(const Configuration&, ob::State*)>& toState)
        : states(si, toState), motions(si, toState) {}
    SpaceInformationStates states;
    SpaceInformationMotions motions;
  };
  releaseDataStates();
  auto run = std::make_shared<Run>(si_, toState);
  PlannerSettings parameters = parameters_;
  if (parameters.seed == 0)
    parameters.seed = static_cast<std::uint64_t>(rng_.uniformInt(1, std::numeric_limits<int>::max()));
  planner_ = std::make_unique<PmdRoadmapPlanner>(space_, run->states, run->motions,
                                                 makeHandSampler(mode_, space_, synergies_.get(), parameters.pmdBox),
                                                 parameters);
  planner_->setStartAndGoal(startConfiguration, goalConfiguration);
  planner_->setProgressCallback([run, &ptc](const PlannerProgress&) {
    if (ptc()) throw TerminationRequested{};
  });
  PlannerStatus status = PlannerStatus::TimeLimit;
  try {
    status = planner_->solve();
    statistics_ = planner_->statistics();
  } catch (const TerminationRequested&) {
    statistics_ = planner_->statistics();
    statistics_.status = PlannerStatus::TimeLimit;
  }
  if (status != PlannerStatus::Solved) return omplStatus(status);

  auto path = std::make_shared<ompl::geometric::PathGeometric>(si_);
  ob::State* state = si_->allocState();
  for (const Configuration& q : planner_->path()) {
    setState(q, state);
    path->append(state);
  }
  si_->freeState(state);
  pdef_->addSolutionPath(path, false, 0.0, getName());
  return ob::PlannerStatus::EXACT_SOLUTION;
}

void OmplPmdPlanner::releaseDataStates() const {
  for (ob::State* state : dataStates_) si_->freeState(state);
  dataStates_.clear();
}

void OmplPmdPlanner::clear() {
  ob::Planner::clear();
  releaseDataStates();
  planner_.reset();
  statistics_ = {};
}

void OmplPmdPlanner::getPlannerData(ob::PlannerData& data) const {
  ob::Planner::getPlannerData(data);
  data.properties["sweeps INTEGER"] = std::to_string(statistics_.sweeps);
  data.properties["samples INTEGER"] = std::to_string(statistics_.samples);
  data.properties["final_rho_a REAL"] = std::to_string(statistics_.finalArmHalfSize);
  if (!planner_) return;
  const Roadmap& roadmap = planner_->roadmap();
  // PlannerData keeps the states' addresses: they live until the next run or clear().
  releaseDataStates();
  for (NodeIndex i = 0; i < roadmap.nodeCount(); ++i) {
    ob::State* state = dataStates_.emplace_back(si_->allocState());
    setState(roadmap.node(i).configuration, state);
    // The planner adds c_ini first and c_goal second.
    if (i == 0)
      data.addStartVertex(ob::PlannerDataVertex(state, 1));
    else if (i == 1)
      data.addGoalVertex(ob::PlannerDataVertex(state, 2));
    else
      data.addVertex(ob::PlannerDataVertex(state));
  }
  for (NodeIndex i = 0; i < roadmap.nodeCount(); ++i)
    for (const RoadmapEdge& edge : roadmap.edges(i))
      data.addEdge(static_cast<unsigned>(i), static_cast<unsigned>(edge.target), ob::PlannerDataEdge(),
                   ob::Cost(edge.length));
}

}  // namespace pmdplan
