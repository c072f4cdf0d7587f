#pragma once
// A benchmark campaign: the flat list of (task, planner, run) jobs, handed out one at a time to
// whichever rank is free (CampaignRanks::takeJob), each job run in a forked child
// (forked_run.hpp), the records gathered on rank 0 in job order. A job's record depends only on
// the job (its seed is the campaign's seed + its run), not on the rank or how many ranks ran the
// campaign, timings aside.
#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "pmdplan/bench/bench_options.hpp"
#include "pmdplan/bench/run_record.hpp"
#include "pmdplan/bench/task_bench.hpp"
#include "pmdplan/synergy/synergy_model.hpp"

namespace pmdplan {

class CampaignJournal;
class CampaignRanks;

struct CampaignJob {
  std::size_t task = 0;     ///< index into BenchSettings::tasks
  std::size_t planner = 0;  ///< index into BenchSettings::planners
  int run = 0;
};

/// Task-major, then planner, then run.
std::vector<CampaignJob> campaignJobs(const BenchSettings& options);
/// The next job index to run (CampaignRanks::takeJob): each index once, in increasing order over
/// all ranks; the campaign's job count or more when none is left.
using CampaignJobSource = std::function<std::size_t()>;

/// Called after each finished job of this rank: the campaign's jobs taken so far (by all ranks,
/// as far as this rank knows: its last job's index + 1), the campaign's job count, the record.
using CampaignProgress = std::function<void(std::size_t done, std::size_t total, const RunRecord& record)>;

/// Built once before any run, on every rank: the synergy model and each task's TaskBench, so a
/// missing task, a colliding start or a model for another hand is an InputError before any run.
struct CampaignInputs {
  /// The synergy models by file, behind pointers: the benches keep their addresses.
  std::map<std::string, std::unique_ptr<SynergyModel>> synergies;
  std::vector<std::unique_ptr<TaskBench>> tasks;  ///< one per BenchSettings::tasks entry
};
/// Reads the tasks and the synergy models (options.synergies for every task, or each task's robot's
/// shipped model, so tasks of several robots share a campaign) and builds the checkers of
/// options.checker.
CampaignInputs loadCampaignInputs(const BenchSettings& options);

/// Runs the jobs `nextJob` hands out (indices into campaignJobs(options)) until it hands out none,
/// each in a forked child that is killed after time limit + grace. Records come back by job index; a crashed,
/// killed or failing child gives a record with solved = false, the reason in `failure` and the
/// child's wall-clock time as its planning time. With a journal, jobs it holds are not run again
/// and every job run is added to it.
std::map<std::size_t, RunRecord> runCampaignJobs(const BenchSettings& options, CampaignInputs& inputs,
                                                 const CampaignJobSource& nextJob,
                                                 const CampaignProgress& progress = {},
                                                 CampaignJournal* journal = nullptr);

/// The records of the jobs options.journal holds, in job order, nothing run: the report of a
/// campaign part way. Throws InputError as CampaignJournal::finishedJobs does.
std::vector<RunRecord> finishedCampaignRecords(const BenchSettings& options);

/// The whole campaign on every rank of `ranks` (with options.journal, resumed from it): rank 0
/// returns all records in job order, the other ranks return nothing.
std::vector<RunRecord> runCampaign(const BenchSettings& options, CampaignInputs& inputs, CampaignRanks& ranks,
                                   const CampaignProgress& progress = {});

}  // namespace pmdplan
