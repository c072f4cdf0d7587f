// The log is read back here by the rules of OMPL 1.5's ompl_benchmark_statistics (its
// readBenchmarkLog): the version line, "Experiment <name>", "Running on", "Starting at", the setup
// block between <<<| and |>>>, the seed / time / memory / runs / total-time lines, the enum, then per
// planner its name, common properties, "<n> properties for each run" with "<name words> <TYPE>",
// "<n> runs" rows of "<value>; " and a closing ".". The CLI test also loads a real log with the
// script when it is installed.
#include "pmdplan/bench/ompl_benchmark_log.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "record_samples.hpp"

namespace pmdplan {
namespace {

std::vector<std::string> words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> result;
  for (std::string w; in >> w;) result.push_back(w);
  return result;
}

std::vector<std::string> splitRunValues(const std::string& line) {
  // Python: line.split('; ')[:-1]
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (;;) {
    const std::size_t at = line.find("; ", start);
    if (at == std::string::npos) break;
    parts.push_back(line.substr(start, at - start));
    start = at + 2;
  }
  return parts;
}

struct ParsedPlanner {
  std::string name;
  std::vector<std::string> properties;
  std::vector<std::vector<std::string>> runs;
};

struct ParsedLog {
  std::string version, experiment, setup, enumLine;
  double timeLimit = 0.0;
  int seed = 0, runsPerPlanner = 0;
  std::vector<ParsedPlanner> planners;
};

ParsedLog parse(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  const auto next = [&] {
    if (!std::getline(in, line)) throw std::runtime_error("log ends early");
    return words(line);
  };
  ParsedLog log;
  auto w = next();
  if (w.size() < 3 || w[1] != "version") throw std::runtime_error("version line: " + line);
  log.version = w.back();
  w = next();
  if (w.size() != 2 || w[0] != "Experiment") throw std::runtime_error("experiment line: " + line);
  log.experiment = w[1];
  if (next()[0] != "Running") throw std::runtime_error("hostname line: " + line);
  next();
  if (line.rfind("Starting", 0) != 0) throw std::runtime_error("start line: " + line);
  next();
  if (line.rfind("<<<|", 0) != 0) throw std::runtime_error("setup block: " + line);
  for (next(); line.rfind("|>>>", 0) != 0; next()) log.setup += line + "\n";
  w = next();
  if (w.size() != 5 || w[3] != "random" || w[4] != "seed") throw std::runtime_error("seed line: " + line);
  log.seed = std::stoi(w[0]);
  w = next();
  if (w.size() != 4 || w[1] != "seconds" || w[2] != "per" || w[3] != "run")
    throw std::runtime_error("time line: " + line);
  log.timeLimit = std::stod(w[0]);
  w = next();
  if (w.size() != 4 || w[1] != "MB") throw std::runtime_error("memory line: " + line);
  w = next();
  if (w.size() != 4 || w[1] != "runs" || w[3] != "planner") throw std::runtime_error("runs line: " + line);
  log.runsPerPlanner = std::stoi(w[0]);
  w = next();
  if (w.back() != "data") throw std::runtime_error("total time line: " + line);
  std::stod(w[0]);
  w = next();
  if (w.size() < 2 || w[w.size() - 2] != "enum") throw std::runtime_error("enum count: " + line);
  const int enums = std::stoi(w[0]);
  for (int e = 0; e < enums; ++e) next(), log.enumLine = line;
  w = next();
  if (w.back() != "planners") throw std::runtime_error("planner count: " + line);
  const int planners = std::stoi(w[0]);
  for (int p = 0; p < planners; ++p) {
    ParsedPlanner planner;
    next();
    planner.name = line;
    const int common = std::stoi(next()[0]);
    for (int c = 0; c < common; ++c) next();
    const int properties = std::stoi(next()[0]);
    for (int i = 0; i < properties; ++i) {
      w = next();
      const std::string type = w.back();
      if (type != "REAL" && type != "INTEGER" && type != "BOOLEAN" && type != "ENUM")
        throw std::runtime_error("type: " + line);
      std::string name;
      for (std::size_t k = 0; k + 1 < w.size(); ++k) name += (k ? "_" : "") + w[k];
      planner.properties.push_back(name);
    }
    const int runs = std::stoi(next()[0]);
    for (int r = 0; r < runs; ++r) {
      next();
      planner.runs.push_back(splitRunValues(line));
    }
    next();
    if (line != ".") throw std::runtime_error("planner end: " + line);
    log.planners.push_back(planner);
  }
  if (std::getline(in, line)) throw std::runtime_error("text after the last planner: " + line);
  return log;
}

std::string valueOf(const ParsedPlanner& planner, std::size_t run, const std::string& property) {
  for (std::size_t i = 0; i < planner.properties.size(); ++i)
    if (planner.properties[i] == property) return planner.runs.at(run).at(i);
  throw std::runtime_error("no property " + property);
}

TEST(OmplBenchmarkLog, ReadsBackByTheRulesOfOmplBenchmarkStatistics) {
  RunRecord invalid = test::successfulRun("can_on_table", "ompl:RRTConnect", 1, 0.75);
  invalid.valid = false;
  invalid.failure = "invalid path: segment 1";
  const std::vector<RunRecord> records = {test::successfulRun("can_on_table", "pmd", 0, 1.5),
                                          test::failedRun("can_on_table", "pmd", 1, "not solved: time_limit"),
                                          test::successfulRun("can_on_table", "ompl:RRTConnect", 0, 0.5), invalid,
                                          test::successfulRun("can_in_box", "pmd", 0, 9.0)};
  const OmplLogContext context{"host", "2026-01-01 00:00:00 UTC", "pmdplan bench test\nsecond line", 7, 60.0, 2, 12.5};
  const ParsedLog log = parse(omplBenchmarkLog(records, "can_on_table", {"pmd", "ompl:RRTConnect"}, context));
  EXPECT_EQ(log.version, "1.5.2");
  EXPECT_EQ(log.experiment, "can_on_table");
  EXPECT_EQ(log.setup, "pmdplan bench test\nsecond line\n");
  EXPECT_EQ(log.seed, 7);
  EXPECT_EQ(log.timeLimit, 60.0);
  EXPECT_EQ(log.runsPerPlanner, 2);
  EXPECT_EQ(log.enumLine.rfind("status|Unknown status|", 0), 0u);
  ASSERT_EQ(log.planners.size(), 2u);
  const ParsedPlanner& pmd = log.planners[0];
  const ParsedPlanner& rrt = log.planners[1];
  EXPECT_EQ(pmd.name, "pmdplan_pmd");
  EXPECT_EQ(rrt.name, "geometric_RRTConnect");
  ASSERT_EQ(pmd.runs.size(), 2u);  // can_in_box's run is not in this task's log
  for (const auto& run : pmd.runs) EXPECT_EQ(run.size(), pmd.properties.size());
  EXPECT_EQ(valueOf(pmd, 0, "time"), "1.5");
  EXPECT_EQ(valueOf(pmd, 0, "solved"), "1");
  EXPECT_EQ(valueOf(pmd, 0, "status"), "6");          // Exact solution
  EXPECT_EQ(valueOf(pmd, 1, "status"), "4");          // Timeout
  EXPECT_EQ(valueOf(pmd, 1, "solution_length"), "");  // read as NULL
  EXPECT_EQ(valueOf(pmd, 0, "simplification_time"), "0.15");
  EXPECT_EQ(valueOf(pmd, 0, "solution_segments"), "3");
  EXPECT_EQ(valueOf(pmd, 0, "mahalanobis_distance_mean"), "2");
  EXPECT_EQ(valueOf(pmd, 0, "authors_pmd_distance_max"), "0.375");
  EXPECT_EQ(valueOf(pmd, 0, "joint_coupling"), "0.75");
  EXPECT_EQ(valueOf(rrt, 1, "solved"), "1");
  EXPECT_EQ(valueOf(rrt, 1, "correct_solution"), "0");
}

TEST(OmplBenchmarkLog, ACrashAndAKillGetTheirStatus) {
  const std::vector<RunRecord> records = {
      test::failedRun("t", "ompl:EST", 0, "crashed: signal 11 (Segmentation fault)"),
      test::failedRun("t", "ompl:EST", 1, "killed: no result within 120 s")};
  const ParsedLog log = parse(omplBenchmarkLog(records, "t", {"ompl:EST"}, OmplLogContext{}));
  EXPECT_EQ(valueOf(log.planners[0], 0, "status"), "7");
  EXPECT_EQ(valueOf(log.planners[0], 1, "status"), "4");
}

TEST(OmplBenchmarkLog, OneFilePerTaskWhenThereAreSeveral) {
  EXPECT_EQ(omplLogPathForTask("out/bench.log", "can_in_box", 1), "out/bench.log");
  EXPECT_EQ(omplLogPathForTask("out/bench.log", "can_in_box", 2), "out/bench.can_in_box.log");
}

}  // namespace
}  // namespace pmdplan
