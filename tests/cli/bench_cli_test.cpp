#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <set>
#include <sstream>

#include "support/run_cli.hpp"
#include "support/temp_dir.hpp"

namespace pmdplan {
namespace {

using test::contents;
using test::quoted;
using test::runCli;

// The CI form of the campaign: short, on the exact checker (the same answers as the fast one).
const std::string kCampaign = "bench can_on_table --planners pmd,ompl:RRTConnect --runs 4 --seed 1 --time-limit 20";

/// The CSV without its timing columns (planning_time_s, smoothing_time_s: the 6th and 7th).
std::string withoutTimings(const std::string& csv) {
  std::istringstream in(csv);
  std::string result;
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> fields(1);
    for (const char c : line) {
      if (c == ',')
        fields.emplace_back();
      else
        fields.back() += c;
    }
    for (std::size_t i = 0; i < fields.size(); ++i)
      if (i < 5 || i > 7) result += fields[i] + (i + 1 < fields.size() ? "," : "");  // not the three timings
    result += "\n";
  }
  return result;
}

void expectBadInput(const std::string& arguments, const std::string& field, const std::string& message) {
  const auto result = runCli(arguments);
  EXPECT_EQ(result.exitCode, 2) << arguments << "\n" << result.out << result.err;
  EXPECT_NE(result.err.find(field), std::string::npos) << result.err;
  EXPECT_NE(result.err.find(message), std::string::npos) << result.err;
}

TEST(BenchCli, AnUnknownPlannerIsBadInputThatListsTheKnownOnes) {
  expectBadInput(
      "bench can_on_table --planners pmd,RRTConnect", "--planners",
      "'RRTConnect' is not a planner; known planners: pmd, full, pmd-lazy, pmd-connect, ompl:RRTConnect, ompl:PRM");
}

TEST(BenchCli, ZeroOrNegativeRunsAreBadInput) {
  expectBadInput("bench can_on_table --runs 0", "--runs", "expected a whole number of runs >= 1");
  expectBadInput("bench can_on_table --runs -2", "--runs", ">= 1");
}

// Checked before the first run, not when a long campaign ends and writes its outputs.
TEST(BenchCli, AnOutputInAMissingFolderIsBadInputBeforeAnyRun) {
  for (const std::string option : {"--csv", "--markdown", "--ompl-log", "--plot"})
    expectBadInput("bench can_on_table --runs 1 " + option + " /no/such/folder/out", option,
                   "the folder /no/such/folder does not exist");
}

TEST(BenchCli, AMissingTaskIsBadInput) {
  const auto result = runCli("bench can_on_table no_such_task --runs 1");
  EXPECT_EQ(result.exitCode, 2) << result.out << result.err;
  EXPECT_NE(result.err.find("no_such_task"), std::string::npos) << result.err;
}

TEST(BenchCli, ABadTimeLimitSeedCheckerToleranceOrGraceIsBadInput) {
  expectBadInput("bench can_on_table --time-limit 0", "--time-limit", "positive");
  expectBadInput("bench can_on_table --time-limit -5", "--time-limit", "positive");
  EXPECT_EQ(runCli("bench can_on_table --time-limit soon").exitCode, 2);
  expectBadInput("bench can_on_table --seed 0", "--seed", ">= 1");
  expectBadInput("bench can_on_table --checker fastest", "--checker", "expected exact or fast");
  expectBadInput("bench can_on_table --tolerance-mm 0", "--tolerance-mm", "0.01 to 100");
  expectBadInput("bench can_on_table --grace -5", "--grace", "non-negative");
}

TEST(BenchCli, WritesEveryOutputAndTheOmplLogLoadsWhenTheReaderIsInstalled) {
  test::TempDir dir;
  const auto csv = dir.path() / "runs.csv", md = dir.path() / "table.md", log = dir.path() / "runs.log",
             plot = dir.path() / "time.svg";
  const auto result =
      runCli(dir, "bench can_on_table --planners pmd,ompl:RRTConnect --runs 2 --time-limit 20 --csv " + quoted(csv) +
                      " --markdown " + quoted(md) + " --ompl-log " + quoted(log) + " --plot " + quoted(plot));
  ASSERT_EQ(result.exitCode, 0) << result.out << result.err;
  EXPECT_NE(result.out.find("| success (solved and valid) | 2/2 (100 %) | 2/2 (100 %) |"), std::string::npos)
      << result.out;
  EXPECT_EQ(contents(md), result.out.substr(0, contents(md).size()));
  EXPECT_EQ(contents(csv).rfind("task,planner,run,seed,solved,planning_time_s,smoothing_time_s,", 0), 0u);
  EXPECT_NE(contents(log).find("geometric_RRTConnect\n"), std::string::npos);
  EXPECT_NE(contents(plot).find("<svg"), std::string::npos);
  EXPECT_NE(contents(plot).find(">can_on_table</text>"), std::string::npos);

  // Debian's ompl-demos ships the reader; when it is installed, load the log into its database.
  if (std::system("command -v ompl_benchmark_statistics >/dev/null 2>&1") != 0) return;
  const auto db = dir.path() / "runs.db";
  ASSERT_EQ(std::system(("ompl_benchmark_statistics " + quoted(log) + " -d " + quoted(db) + " >/dev/null").c_str()), 0);
  const std::string query =
      "python3 -c \"import sqlite3,sys; c=sqlite3.connect(sys.argv[1]); "
      "sys.exit(0 if c.execute('select count(*) from runs where solved=1').fetchone()[0]==4 else 1)\" " +
      quoted(db);
  EXPECT_EQ(std::system(query.c_str()), 0);
}

// A campaign stopped part way resumes from its journal: the runs it holds are not run again (their
// rows, timings included, come back as they were), the missing one is, and a journal of another
// campaign is refused.
TEST(BenchCli, AJournalledCampaignResumesWhereItStopped) {
  test::TempDir dir;
  const auto journal = dir.path() / "journal", first = dir.path() / "first.csv", again = dir.path() / "again.csv";
  const std::string campaign =
      "bench can_on_table --planners pmd --runs 3 --time-limit 20 --journal " + quoted(journal);
  ASSERT_EQ(runCli(dir, campaign + " --csv " + quoted(first)).exitCode, 0);
  const std::string lines = contents(journal / "rank0.jsonl");
  ASSERT_EQ(std::count(lines.begin(), lines.end(), '\n'), 4) << lines;  // the campaign's line, then 3 runs
  ASSERT_EQ(runCli(dir, campaign + " --csv " + quoted(again)).exitCode, 0);
  EXPECT_EQ(contents(again), contents(first)) << "every run came from the journal";

  // Drop run 1 (and cut the next line short, as a crash would): those two are run again.
  std::istringstream in(lines);
  std::string header, run0, run1, run2;
  std::getline(in, header), std::getline(in, run0), std::getline(in, run1), std::getline(in, run2);
  dir.write("journal/rank0.jsonl", header + "\n" + run0 + "\n" + run2.substr(0, run2.size() / 2));
  const auto resumed = dir.path() / "resumed.csv";
  ASSERT_EQ(runCli(dir, campaign + " --csv " + quoted(resumed)).exitCode, 0);
  EXPECT_EQ(withoutTimings(contents(resumed)), withoutTimings(contents(first)));
  std::istringstream rows(contents(resumed)), firstRows(contents(first));
  std::string row, firstRow;
  std::getline(rows, row), std::getline(firstRows, firstRow);  // headers
  std::getline(rows, row), std::getline(firstRows, firstRow);
  EXPECT_EQ(row, firstRow) << "run 0 was kept, timing and all";

  expectBadInput("bench can_on_table --planners pmd --runs 4 --time-limit 20 --journal " + quoted(journal), "--journal",
                 "belongs to another campaign");
}

// A journal folder of an older pmdplan (tab-separated rank files) is bad input naming the file and line.
TEST(BenchCli, AnOldFormatJournalIsRefused) {
  test::TempDir dir;
  dir.write("journal/rank0.tsv", "# pmdplan bench journal: tasks=can_on_table\n0\trun-record-2\n");
  expectBadInput("bench can_on_table --planners pmd --runs 1 --journal " + quoted(dir.path() / "journal"), "rank0.tsv",
                 "line 1");
}

// --report writes the outputs of a journal's finished runs without running the others: the rows
// are the journal's, the tables say how much is finished, and the journal is left as it was.
TEST(BenchCli, AReportShowsAJournalsFinishedRunsAndRunsNothing) {
  test::TempDir dir;
  const auto journal = dir.path() / "journal", full = dir.path() / "full.csv";
  const std::string campaign =
      "bench can_on_table --planners pmd,full --runs 2 --time-limit 20 --journal " + quoted(journal);
  ASSERT_EQ(runCli(dir, campaign + " --csv " + quoted(full)).exitCode, 0);
  std::istringstream in(contents(journal / "rank0.jsonl"));
  std::string header, run0, run1, run2;
  std::getline(in, header), std::getline(in, run0), std::getline(in, run1), std::getline(in, run2);
  dir.write("journal/rank0.jsonl", header + "\n" + run0 + "\n" + run2 + "\n");  // pmd run 0 and full run 0
  const std::string before = contents(journal / "rank0.jsonl");

  const auto csv = dir.path() / "part.csv", markdown = dir.path() / "part.md", plot = dir.path() / "part.svg";
  const auto result = runCli(
      dir, campaign + " --report --csv " + quoted(csv) + " --markdown " + quoted(markdown) + " --plot " + quoted(plot));
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_EQ(contents(journal / "rank0.jsonl"), before) << "a report adds nothing to the journal";
  std::istringstream fullRows(contents(full));
  std::string fullHeader, pmd0, pmd1, full0, full1;
  std::getline(fullRows, fullHeader), std::getline(fullRows, pmd0), std::getline(fullRows, pmd1),
      std::getline(fullRows, full0);
  EXPECT_EQ(contents(csv), fullHeader + "\n" + pmd0 + "\n" + full0 + "\n") << "the two finished runs, timings and all";
  const std::string tables = contents(markdown);
  EXPECT_NE(tables.find("Partial campaign: 2 of 4 runs finished"), std::string::npos) << tables;
  EXPECT_NE(tables.find("1/1 (100 %)"), std::string::npos) << tables;
  EXPECT_NE(contents(plot).find("<svg"), std::string::npos);

  expectBadInput("bench can_on_table --planners pmd --runs 2 --report", "--report", "needs --journal");
  expectBadInput("bench can_on_table --planners pmd --runs 2 --report --journal " + quoted(dir.path() / "none"),
                 "--journal", "no such journal folder");
}

#ifdef PMDPLAN_MPIEXEC
TEST(BenchCli, TwoMpiRanksGiveTheOneProcessCsvTimingsAside) {
  test::TempDir dir;
  const auto single = dir.path() / "single.csv", split = dir.path() / "split.csv";
  const auto one = runCli(dir, kCampaign + " --csv " + quoted(single));
  ASSERT_EQ(one.exitCode, 0) << one.out << one.err;
  // As root OpenMPI wants --allow-run-as-root; --oversubscribe lets 2 ranks run on any machine.
  const auto onTwoRanks = [&](const std::string& more) {
    const std::string command = std::string(PMDPLAN_MPIEXEC) + (::geteuid() == 0 ? " --allow-run-as-root" : "") +
                                " --oversubscribe -np 2 " + quoted(PMDPLAN_CLI_PATH) + " " + kCampaign + " --csv " +
                                quoted(split) + more + " >" + quoted(dir.path() / "mpi.out") + " 2>&1";
    return std::system(command.c_str());
  };
  ASSERT_EQ(onTwoRanks(""), 0) << contents(dir.path() / "mpi.out");
  EXPECT_NE(contents(dir.path() / "mpi.out").find("8 runs in"), std::string::npos);
  const std::string a = contents(single), b = contents(split);
  EXPECT_EQ(std::count(a.begin(), a.end(), '\n'), 9);
  EXPECT_EQ(withoutTimings(a), withoutTimings(b));
  EXPECT_NE(a.find("\ncan_on_table,ompl:RRTConnect,3,4,1,"), std::string::npos) << a;

  // With a journal: the ranks take the jobs as they free up, so each job is in one rank's file,
  // and the same command again resumes from both files, runs nothing and writes the same records.
  const auto journal = dir.path() / "journal";
  for (int pass = 0; pass < 2; ++pass) {
    ASSERT_EQ(onTwoRanks(" --journal " + quoted(journal)), 0) << contents(dir.path() / "mpi.out");
    std::multiset<std::string> jobs;
    for (const char* file : {"rank0.jsonl", "rank1.jsonl"}) {
      std::istringstream in(contents(journal / file));
      std::string line;
      std::getline(in, line);  // the campaign's header
      while (std::getline(in, line)) jobs.insert(line.substr(0, line.find(',')));
    }
    EXPECT_EQ(jobs.size(), 8u) << "pass " << pass;
    EXPECT_EQ(std::set<std::string>(jobs.begin(), jobs.end()).size(), 8u) << "each job once, pass " << pass;
    EXPECT_EQ(withoutTimings(contents(split)), withoutTimings(a)) << "pass " << pass;
  }
}
#endif

}  // namespace
}  // namespace pmdplan
