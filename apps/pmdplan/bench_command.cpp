// `pmdplan bench [TASK...]`: planners side by side on the same tasks with the same checks: every
// run's CSV row, the Markdown tables (also printed), an OMPL benchmark log and a box plot of the
// planning times, and with --paths each solved run's path. Under `mpirun -np P` the runs are split
// across the ranks and rank 0 writes the outputs; with --report nothing is run and they are
// written from a journal's finished runs.
// Exit 0 done (whatever the runs' outcomes unless --require), 1 a --require planner failed a run,
// 2 bad input.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <iostream>
#include <optional>

#include "command_registry.hpp"
#include "package_path_option.hpp"
#include "planner_setting_options.hpp"
#include "pmdplan/bench/bench_options.hpp"
#include "pmdplan/bench/campaign.hpp"
#include "pmdplan/bench/campaign_ranks.hpp"
#include "pmdplan/bench/ompl_benchmark_log.hpp"
#include "pmdplan/bench/planner_roster.hpp"
#include "pmdplan/bench/planning_time_plot.hpp"
#include "pmdplan/bench/results_csv.hpp"
#include "pmdplan/bench/results_markdown.hpp"
#include "pmdplan/core/atomic_file.hpp"
#include "pmdplan/core/data_directory.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/core/progress_line.hpp"

namespace pmdplan::cli::bench_command {
namespace {

struct CommandLine {
  std::vector<std::string> tasks;
  std::string planners = "pmd";
  int runs = 10;
  PlannerSettingOptions settings;
  std::optional<double> grace;  // unset: max(60 s, time limit)
  std::string checker = "fast";
  double toleranceMm = 1.0;
  std::string synergies, csv, markdown, omplLog, plot, journal, paths;
  std::string require;  // planners every run of which must succeed, else exit 1
  bool report = false;
};

BenchSettings benchOptions(const CommandLine& c) {
  BenchSettings o;
  if (!c.tasks.empty()) o.tasks = c.tasks;
  o.planners = splitList(c.planners);
  o.runs = c.runs;
  o.pmdParameters = resolvePlannerSettings(c.settings, HandSamplingMode::Synergy);
  o.fullParameters = resolvePlannerSettings(c.settings, HandSamplingMode::FullSpace);
  o.seed = o.pmdParameters.seed;
  o.timeLimit = o.pmdParameters.timeLimit;
  o.graceSeconds = c.grace ? *c.grace : std::max(60.0, o.timeLimit);
  o.checker = checkerKindNamed(c.checker, "--checker");
  o.toleranceMetres = c.toleranceMm / 1000.0;
  o.synergies = c.synergies;
  o.csv = c.csv;
  o.markdown = c.markdown;
  o.omplLog = c.omplLog;
  o.plot = c.plot;
  o.journal = c.journal;
  o.paths = c.paths;
  o.reportOnly = c.report;
  checkBenchOptions(o);
  for (const std::string& name : splitList(c.require))
    if (!c.require.empty() && std::find(o.planners.begin(), o.planners.end(), name) == o.planners.end())
      throw InputError("", "--require", "'" + name + "' is not one of the --planners of this run");
  return o;
}

/// Runs of the --require planners that did not solve with a valid path.
std::size_t requiredFailures(const std::vector<RunRecord>& records, const std::string& require) {
  if (require.empty()) return 0;
  const auto required = splitList(require);
  return static_cast<std::size_t>(std::count_if(records.begin(), records.end(), [&](const RunRecord& r) {
    return !r.succeeded() && std::find(required.begin(), required.end(), r.planner) != required.end();
  }));
}

std::string utcNow() {
  const std::time_t now = std::time(nullptr);
  std::tm parts{};
  gmtime_r(&now, &parts);
  char text[64];
  std::strftime(text, sizeof text, "%Y-%m-%d %H:%M:%S UTC", &parts);
  return text;
}

std::string hostName() {
  char name[256] = {};
  if (::gethostname(name, sizeof name - 1) != 0) return "unknown";
  return name;
}

/// The OMPL log of the i-th task: named after the task as the command line gives it (a task file by
/// its file name), never after the name inside the file.
std::filesystem::path omplLogFile(const BenchSettings& o, std::size_t i) {
  return omplLogPathForTask(o.omplLog, resolveTaskPath(o.tasks[i]).stem().string(), o.tasks.size());
}

/// Once the inputs are read (the tasks, their robots' files, the synergy models), before the runs:
/// no output may be one of them or another output (core/command_files.hpp).
void checkOutputsAgainstInputs(const BenchSettings& o) {
  const std::pair<const std::filesystem::path*, const char*> outputs[] = {
      {&o.csv, "--csv"}, {&o.markdown, "--markdown"}, {&o.plot, "--plot"}};
  for (const auto& [path, option] : outputs)
    if (!path->empty()) checkOutputPath(*path, option);
  if (!o.omplLog.empty())
    for (std::size_t i = 0; i < o.tasks.size(); ++i)
      checkOutputPath(omplLogFile(o, i), o.tasks.size() > 1 ? "--ompl-log for " + o.tasks[i] : "--ompl-log");
}

/// `taskNames`: the tasks' own names (a task given as a file is known by the name inside it).
void writeOutputs(const BenchSettings& o, const std::vector<std::string>& taskNames,
                  const std::vector<RunRecord>& records, const std::string& markdown, const std::string& started,
                  double totalSeconds, int ranks) {
  StagedOutputs staged;  // renamed together once every output is written
  if (!o.csv.empty()) writeFileAtomically(o.csv, runRecordsCsv(records));
  if (!o.markdown.empty()) writeFileAtomically(o.markdown, markdown);
  if (!o.plot.empty()) writeFileAtomically(o.plot, planningTimeBoxPlotSvg(records, taskNames, o.planners, o.timeLimit));
  if (!o.omplLog.empty()) {
    char setup[256];
    std::snprintf(
        setup, sizeof setup,
        "pmdplan bench: checker %s, tolerance %g mm, %d rank(s); paths smoothed by pmdplan's shortcut smoothing "
        "(Sect. 5.3) and re-validated by the exact checker",
        checkerKindName(o.checker).c_str(), o.toleranceMetres * 1000.0, ranks);
    for (std::size_t i = 0; i < taskNames.size(); ++i) {
      const OmplLogContext context{hostName(), started, setup, o.seed, o.timeLimit, o.runs, totalSeconds};
      writeFileAtomically(omplLogFile(o, i), omplBenchmarkLog(records, taskNames[i], o.planners, context));
    }
  }
  staged.commit();
}

/// The tasks' own names (a task given as a file is known by the name inside it).
std::vector<std::string> taskNamesOf(const CampaignInputs& inputs) {
  std::vector<std::string> names;
  for (const auto& bench : inputs.tasks) names.push_back(bench->task().name);
  return names;
}

/// --report: the outputs of the journal's finished runs, nothing run.
int report(const BenchSettings& o, const CampaignInputs& inputs) {
  const auto records = finishedCampaignRecords(o);
  const std::size_t jobs = campaignJobs(o).size();
  const std::vector<std::string> taskNames = taskNamesOf(inputs);
  const std::string now = utcNow();
  const std::string markdown = "**Partial campaign: " + std::to_string(records.size()) + " of " + std::to_string(jobs) +
                               " runs finished** (the journal as of " + now +
                               "); success counts are over the finished runs.\n\n" +
                               benchMarkdown(records, taskNames, o.planners);
  double runSeconds = 0.0;
  for (const RunRecord& r : records) runSeconds += r.planningTimeSeconds + r.smoothingTimeSeconds;
  writeOutputs(o, taskNames, records, markdown, now, runSeconds, 1);
  std::cout << markdown;
  return 0;
}

int run(const CommandLine& c) {
  const BenchSettings o = benchOptions(c);
  CampaignRanks ranks;
  CampaignInputs inputs = loadCampaignInputs(o);
  checkOutputsAgainstInputs(o);
  if (o.reportOnly) return ranks.first() ? report(o, inputs) : 0;
  const std::string started = utcNow();
  const auto began = std::chrono::steady_clock::now();
  ProgressLine progress(ranks.size() > 1 ? "bench (rank 0 of " + std::to_string(ranks.size()) + ")" : "bench");
  const auto records = runCampaign(o, inputs, ranks, [&](std::size_t done, std::size_t total, const RunRecord& r) {
    if (!ranks.first()) return;
    progress.update(static_cast<double>(done), static_cast<double>(total),
                    r.task + " " + r.planner + " run " + std::to_string(r.run) + (r.succeeded() ? " ok" : " failed"));
  });
  progress.finish();
  if (!ranks.first()) return 0;
  const double totalSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  const std::vector<std::string> taskNames = taskNamesOf(inputs);
  const std::string markdown = benchMarkdown(records, taskNames, o.planners);
  writeOutputs(o, taskNames, records, markdown, started, totalSeconds, ranks.size());
  std::cout << markdown;
  std::printf("\n%zu runs in %.1f s on %d rank(s), checker %s, time limit %g s, seeds %llu..%llu\n", records.size(),
              totalSeconds, ranks.size(), checkerKindName(o.checker).c_str(), o.timeLimit,
              static_cast<unsigned long long>(o.seed),
              static_cast<unsigned long long>(o.seed + static_cast<std::uint64_t>(o.runs) - 1));
  if (const std::size_t failed = requiredFailures(records, c.require); failed > 0) {
    std::fprintf(stderr, "pmdplan: %zu run(s) of the --require planners (%s) did not solve with a valid path\n", failed,
                 c.require.c_str());
    return 1;
  }
  return 0;
}

const CommandRegistrar registrar{
    "bench", "Compare planners on tasks: many seeded runs, tables, CSV, OMPL log, plot (MPI-aware)", [](CLI::App& app) {
      auto c = std::make_shared<CommandLine>();
      addPackagePathOption(app);
      app.add_option("task", c->tasks, "Built-in task names or task files (default: the five paper tasks)");
      app.add_option("--planners", c->planners, "Comma-separated planners: " + knownPlannerNames() + " (default pmd)");
      app.add_option("--runs", c->runs, "Runs per task and planner; run i uses seed S + i (default 10)");
      app.add_option("--grace", c->grace,
                     "Seconds past the time limit before a run's process is killed (default max(60, limit))");
      app.add_option("--checker", c->checker, "exact (FCL) or fast (default fast)");
      app.add_option("--tolerance-mm", c->toleranceMm,
                     "Motion check and validation tolerance in millimetres (default 1)");
      app.add_option("--synergies", c->synergies, "Synergy model file (default: the robot's shipped model)");
      app.add_option("--require", c->require,
                     "Comma-separated planners whose every run must solve with a valid path (else exit 1)");
      app.add_option("--csv", c->csv, "Write every run as a CSV row");
      app.add_option("--markdown", c->markdown, "Write the tables as Markdown");
      app.add_option("--ompl-log", c->omplLog,
                     "Write OMPL benchmark logs (one per task: NAME.TASK.log when several, TASK the task file's name)");
      app.add_option("--plot", c->plot, "Write the planning-time box plot (SVG)");
      app.add_option(
          "--paths", c->paths,
          "Write each solved run's path to this folder as TASK.PLANNER.seedN.path.json (pmdplan view DIR --seed N)");
      addPlannerSettingOptions(app, c->settings, "First seed S, >= 1: run i uses seed S + i");
      app.add_option("--journal", c->journal,
                     "Keep finished runs in this folder as they finish; the same command again resumes there");
      app.add_flag("--report", c->report,
                   "Run nothing: write the outputs from the --journal's finished runs (a campaign part way)");
      return [c] { return run(*c); };
    }};

}  // namespace
}  // namespace pmdplan::cli::bench_command
