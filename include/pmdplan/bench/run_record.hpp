#pragma once
// One benchmark run of a planner on a task: what every output (CSV, Markdown, OMPL log, plot) is
// made from. Records travel from the forked child that ran them, between MPI ranks and into the
// campaign journal as one JSON object (encodeRunRecord / decodeRunRecord) that restores every
// number exactly; one table in run_record.cpp lists its keys for writing and reading.
#include <cstddef>
#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace pmdplan {

/// Human-likeness measured without the planner's synergy model (docs/human_likeness.md).
struct IndependentHumanLikeness {
  /// Distance from the subspace of the authors' real-data PMDs (thumb base plus PMD 1-4 of the
  /// Kautham table), normalised joint units over the table's limits: mean along the path and max.
  double authorsSubspaceDistanceMean = 0.0;
  double authorsSubspaceDistanceMax = 0.0;
  /// Agreement of the hand's joint motion with the signs of the paper's Fig. 7 correlations, in
  /// [-1, 1]: 1 every correlated pair moves as the paper's correlation says, 0 as if independent,
  /// -1 against it (0 also when none of those joints moves).
  double jointCoupling = 0.0;
};

/// How far a path's hand postures are from the human data (human_likeness.hpp).
struct HumanLikeness {
  /// Distance from the synergy subspace the PMD planner samples, normalised joint units.
  double subspaceDistanceMean = 0.0;
  double subspaceDistanceMax = 0.0;
  /// Mahalanobis distance under the synergy model, mean along the path.
  double mahalanobisMean = 0.0;
  /// Absent for a robot without the SAH's 13 hand joints (named as in the Kautham table).
  std::optional<IndependentHumanLikeness> independent;
};

struct RunRecord {
  std::string task;
  std::string planner;
  int run = 0;             ///< 0 .. runs-1
  std::uint64_t seed = 0;  ///< S + run
  /// The planner returned an exact solution.
  bool solved = false;
  /// The returned path passed validatePath on a separate exact checker (false when not solved).
  bool valid = false;
  double planningTimeSeconds = 0.0;
  double smoothingTimeSeconds = 0.0;
  /// Seconds to certify the returned path with the planner's own motion checker: one motion check
  /// of each of its segments (up to the pre-grasp of a grasp), after the run (0 if not solved).
  double certificationTimeSeconds = 0.0;
  /// PMD planners: hand-arm draws (Table 2's and Table 4's "samples").
  /// OMPL planners: states their validity checker was asked about.
  std::size_t samples = 0;
  /// PMD planners only (0 for OMPL's): arm configurations tried (passes of the j loop), the most
  /// trials one hypercube needed (Table 2's "j × h loops"), rho_a of the last sweep, and the
  /// sampled roadmap nodes by the hand dimension that produced them.
  std::size_t armTrials = 0;
  std::size_t maxTrials = 0;
  double finalArmHalfSize = 0.0;
  std::map<int, std::size_t> nodesByHandDimension;
  /// PMD planners: roadmap nodes; OMPL planners: vertices of the planner data ("graph states").
  std::size_t roadmapNodes = 0;
  /// Of the smoothed path (0 if not solved).
  std::size_t pathNodes = 0;
  double pathLength = 0.0;  ///< normalised joint space
  /// Configurations checked by the state and motion validators during planning and smoothing.
  std::size_t collisionChecks = 0;
  /// Of the smoothed path; set when solved (valid or not).
  std::optional<HumanLikeness> humanLikeness;
  /// Empty for a success; otherwise why the run failed (not solved, invalid path, crash, ...).
  std::string failure;

  /// Solved and valid: the only runs that count as successes.
  bool succeeded() const { return solved && valid; }
};

/// "2:5,3:4": sampled nodes by hand dimension; "" for none.
std::string nodesByHandDimensionText(const std::map<int, std::size_t>& counts);

/// The keys of a record's JSON object, in order: task, planner, run, seed, solved, valid,
/// planning_time_s, ..., human_likeness ({subspace_distance_mean, ..., independent} or null), failure.
const std::vector<const char*>& runRecordKeys();
nlohmann::ordered_json runRecordToJson(const RunRecord& record);
/// Inverse of runRecordToJson; std::nullopt unless `json` holds exactly the record's keys (and
/// `otherKeys` more, which the caller reads) with values of their kind. A record written before
/// certification_time_s existed (an older campaign journal) reads with it 0.
std::optional<RunRecord> runRecordFromJson(const nlohmann::json& json, std::size_t otherKeys = 0);

/// One line of JSON (no newline inside) holding every field, numbers in their shortest exact form.
std::string encodeRunRecord(const RunRecord& record);
/// Inverse of encodeRunRecord; std::nullopt if the text is not one.
std::optional<RunRecord> decodeRunRecord(const std::string& text);

}  // namespace pmdplan
