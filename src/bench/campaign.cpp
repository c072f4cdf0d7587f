#include "pmdplan/bench/campaign.hpp"

#include <chrono>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>

#include "pmdplan/bench/benchmark_run.hpp"
#include "pmdplan/bench/campaign_journal.hpp"
#include "pmdplan/bench/campaign_ranks.hpp"
#include "pmdplan/bench/forked_run.hpp"
#include "pmdplan/bench/planner_roster.hpp"
#include "pmdplan/bench/task_bench.hpp"
#include "pmdplan/core/atomic_file.hpp"
#include "pmdplan/core/data_directory.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/io/viewer/path_set.hpp"
#include "pmdplan/synergy/synergy_model_file.hpp"

namespace pmdplan {

std::vector<CampaignJob> campaignJobs(const BenchSettings& options) {
  std::vector<CampaignJob> jobs;
  for (std::size_t t = 0; t < options.tasks.size(); ++t)
    for (std::size_t p = 0; p < options.planners.size(); ++p)
      for (int r = 0; r < options.runs; ++r) jobs.push_back({t, p, r});
  return jobs;
}

CampaignInputs loadCampaignInputs(const BenchSettings& options) {
  std::vector<Task> tasks;
  for (const auto& name : options.tasks) tasks.push_back(loadTaskByName(name));
  CampaignInputs inputs;
  for (Task& task : tasks) {
    const std::string file =
        (options.synergies.empty() ? shippedSynergyModelPath(task.robot->name()) : options.synergies).string();
    auto& model = inputs.synergies[file];
    if (!model) model = std::make_unique<SynergyModel>(loadSynergyModel(file));
    inputs.tasks.push_back(
        std::make_unique<TaskBench>(std::move(task), options.checker, options.toleranceMetres, *model, file));
  }
  return inputs;
}

std::map<std::size_t, RunRecord> runCampaignJobs(const BenchSettings& options, CampaignInputs& inputs,
                                                 const CampaignJobSource& nextJob, const CampaignProgress& progress,
                                                 CampaignJournal* journal) {
  const std::vector<CampaignJob> jobs = campaignJobs(options);
  std::vector<PlannerEntry> planners;
  for (const auto& name : options.planners) {
    planners.push_back(plannerNamed(name, "--planners"));
  }
  if (!options.paths.empty()) createOutputFolder(options.paths, "--paths");
  std::map<std::size_t, RunRecord> records;
  for (std::size_t index; (index = nextJob()) < jobs.size();) {
    if (const RunRecord* done = journal ? journal->find(index) : nullptr) {
      records[index] = *done;
      if (progress) progress(index + 1, jobs.size(), *done);
      continue;
    }
    const CampaignJob& job = jobs.at(index);
    TaskBench* bench = inputs.tasks.at(job.task).get();
    const PlannerEntry& planner = planners.at(job.planner);
    const std::uint64_t seed = options.seed + static_cast<std::uint64_t>(job.run);
    PlannerSettings parameters = options.roadmapParameters(planner.mode);
    parameters.seed = seed;
    parameters.timeLimit = options.timeLimit;
    const auto began = std::chrono::steady_clock::now();
    const ChildOutcome outcome = runInChildProcess(
        [&] {
          // The child writes the path itself: only the record travels back.
          PathFile path;
          const RunRecord run =
              runPlannerOnce(*bench, planner, job.run, parameters, options.paths.empty() ? nullptr : &path);
          if (!path.points.empty())
            writePathFile(options.paths / benchPathFileName(run.task, run.planner, run.seed), path);
          return encodeRunRecord(run);
        },
        options.timeLimit + options.graceSeconds);
    std::optional<RunRecord> record;
    if (outcome.finished()) record = decodeRunRecord(outcome.output);
    if (!record) {
      record = RunRecord{};
      record->task = bench->task().name;
      record->planner = planner.name;
      record->run = job.run;
      record->seed = seed;
      record->failure = outcome.finished() ? "error: unreadable result from the run" : outcome.problem;
      // Where the run stopped, so tables and plots show a killed run at its limit, not at zero.
      record->planningTimeSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
    }
    if (journal) journal->append(index, *record);
    records[index] = *record;
    if (progress) progress(index + 1, jobs.size(), *record);
  }
  return records;
}

std::vector<RunRecord> finishedCampaignRecords(const BenchSettings& options) {
  const std::size_t jobCount = campaignJobs(options).size();
  std::vector<RunRecord> records;
  for (auto& [index, record] : CampaignJournal::finishedJobs(options.journal, options)) {
    if (index >= jobCount)
      throw InputError(
          options.journal.string(), "--journal",
          "holds job " + std::to_string(index) + " but the campaign has " + std::to_string(jobCount) + " jobs");
    records.push_back(std::move(record));
  }
  return records;
}

std::vector<RunRecord> runCampaign(const BenchSettings& options, CampaignInputs& inputs, CampaignRanks& ranks,
                                   const CampaignProgress& progress) {
  const std::size_t jobCount = campaignJobs(options).size();
  std::optional<CampaignJournal> journal;
  if (!options.journal.empty()) journal.emplace(options.journal, options, ranks.rank());
  const std::map<std::size_t, RunRecord> mine = runCampaignJobs(
      options, inputs, [&ranks] { return ranks.takeJob(); }, progress, journal ? &*journal : nullptr);
  std::string text;
  for (const auto& [index, record] : mine) text += std::to_string(index) + "\t" + encodeRunRecord(record) + "\n";
  const std::vector<std::string> parts = ranks.gatherToFirst(text);
  if (!ranks.first()) return {};
  std::map<std::size_t, RunRecord> byJob;
  for (const std::string& part : parts) {
    std::size_t start = 0;
    while (start < part.size()) {
      const std::size_t end = part.find('\n', start);
      const std::string line = part.substr(start, end - start);
      start = end == std::string::npos ? part.size() : end + 1;
      const std::size_t tab = line.find('\t');
      const auto record = tab == std::string::npos ? std::nullopt : decodeRunRecord(line.substr(tab + 1));
      if (!record) throw std::runtime_error("runCampaign: a rank sent an unreadable record");
      byJob[std::stoul(line.substr(0, tab))] = *record;
    }
  }
  if (byJob.size() != jobCount) throw std::runtime_error("runCampaign: records of some jobs are missing");
  std::vector<RunRecord> all;
  for (auto& [index, record] : byJob) all.push_back(std::move(record));
  return all;
}

}  // namespace pmdplan
