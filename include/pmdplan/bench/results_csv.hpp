#pragma once
// Every run as one CSV row (RFC 4180 quoting). Columns: task, planner, run, seed, solved,
// planning_time_s, smoothing_time_s, valid, samples, roadmap_nodes, path_nodes, path_length,
// collision_checks, subspace_distance_mean, subspace_distance_max, mahalanobis_mean,
// authors_pmd_distance_mean, authors_pmd_distance_max, joint_coupling, failure.
// Booleans are 0/1; numbers in their shortest exact form; path metrics empty when not solved (the
// authors' PMD distance and the joint coupling also for a robot without the SAH's hand joints).
// Only the two time columns depend on the machine: the same seeds give the same other columns.
#include <string>
#include <vector>

#include "pmdplan/bench/run_record.hpp"

namespace pmdplan {

std::string runRecordsCsv(const std::vector<RunRecord>& records);

/// The names of the columns whose values are wall-clock times.
const std::vector<std::string>& timingCsvColumns();

}  // namespace pmdplan
