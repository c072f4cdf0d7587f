#pragma once
// The runs of one planner on one task summed up as the paper's tables do: the success rate over
// all runs, and the mean and median of each metric over the successful runs (solved and valid).
#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "pmdplan/bench/run_record.hpp"

namespace pmdplan {

struct MetricSummary {
  std::size_t count = 0;  ///< successful runs that have the value (0: mean and median undefined)
  double mean = 0.0;
  double median = 0.0;
};

struct RunSummary {
  std::string task;
  std::string planner;
  std::size_t runs = 0;
  std::size_t solved = 0;     ///< planner said solved
  std::size_t succeeded = 0;  ///< solved and valid
  MetricSummary planningTime, smoothingTime, certificationTime, samples, armTrials, maxTrials, finalArmHalfSize,
      roadmapNodes, pathNodes, pathLength, collisionChecks, subspaceDistanceMean, subspaceDistanceMax, mahalanobisMean;
  /// Per hand dimension (2 = thumb base + 1 PMD, ...): the share of a run's sampled nodes that
  /// dimension produced, in %, over the successful runs that sampled any node (Table 2's rows).
  std::map<int, MetricSummary> nodeShareByHandDimension;
  /// The measures independent of the planner's model, over the successful runs that have them.
  MetricSummary authorsSubspaceDistanceMean, authorsSubspaceDistanceMax, jointCoupling;

  double successRate() const { return runs ? static_cast<double>(succeeded) / static_cast<double>(runs) : 0.0; }
};

/// Summary of the records of `task` and `planner` among `records`.
RunSummary summariseRuns(const std::vector<RunRecord>& records, const std::string& task, const std::string& planner);

/// Mean and median of the values (count 0 for none).
MetricSummary summariseValues(std::vector<double> values);

}  // namespace pmdplan
