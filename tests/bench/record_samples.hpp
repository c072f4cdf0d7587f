#pragma once
// Hand-made run records for the writer tests.
#include <string>
#include <vector>

#include "pmdplan/bench/run_record.hpp"

namespace pmdplan::test {

inline RunRecord successfulRun(const std::string& task, const std::string& planner, int run, double seconds) {
  RunRecord r;
  r.task = task;
  r.planner = planner;
  r.run = run;
  r.seed = static_cast<std::uint64_t>(1 + run);
  r.solved = r.valid = true;
  r.planningTimeSeconds = seconds;
  r.smoothingTimeSeconds = seconds / 10.0;
  r.certificationTimeSeconds = seconds / 25.0;
  r.samples = 100 + static_cast<std::size_t>(run);
  r.roadmapNodes = 20;
  r.pathNodes = 4;
  r.pathLength = 1.5;
  r.collisionChecks = 5000;
  r.humanLikeness = HumanLikeness{0.25, 0.5, 2.0, IndependentHumanLikeness{0.125, 0.375, 0.75}};
  return r;
}

inline RunRecord failedRun(const std::string& task, const std::string& planner, int run, const std::string& failure) {
  RunRecord r;
  r.task = task;
  r.planner = planner;
  r.run = run;
  r.seed = static_cast<std::uint64_t>(1 + run);
  r.planningTimeSeconds = 60.0;
  r.samples = 9999;
  r.failure = failure;
  return r;
}

}  // namespace pmdplan::test
