#include "pmdplan/bench/forked_run.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <stdexcept>
#include <thread>

namespace pmdplan {
namespace {

TEST(ForkedRun, BringsTheChildsTextBack) {
  const auto outcome = runInChildProcess([] { return std::string(100000, 'x') + "end"; }, 30.0);
  ASSERT_TRUE(outcome.finished()) << outcome.problem;
  EXPECT_EQ(outcome.output.size(), 100003u);
  EXPECT_EQ(outcome.output.substr(100000), "end");
}

TEST(ForkedRun, TheChildsChangesDoNotReachTheParent) {
  int counter = 1;
  const auto outcome = runInChildProcess([&] { return std::to_string(++counter); }, 30.0);
  EXPECT_EQ(outcome.output, "2");
  EXPECT_EQ(counter, 1);
}

TEST(ForkedRun, AnExceptionBecomesAFailureWithItsMessage) {
  const auto outcome = runInChildProcess([]() -> std::string { throw std::runtime_error("no luck"); }, 30.0);
  EXPECT_EQ(outcome.kind, ChildOutcome::Kind::Failed);
  EXPECT_EQ(outcome.problem, "error: no luck");
}

// Under AddressSanitizer a SIGSEGV is the sanitizer's: it prints its report and exits with code 1.
#if defined(__SANITIZE_ADDRESS__)
#define PMDPLAN_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define PMDPLAN_UNDER_ASAN 1
#endif
#endif

TEST(ForkedRun, ACrashIsReportedWithItsSignal) {
  const auto outcome = runInChildProcess(
      []() -> std::string {
        std::raise(SIGSEGV);
        return "unreachable";
      },
      30.0);
#ifdef PMDPLAN_UNDER_ASAN
  EXPECT_EQ(outcome.kind, ChildOutcome::Kind::Failed);
  EXPECT_EQ(outcome.problem, "error: the run ended without a result (exit code 1)");
#else
  EXPECT_EQ(outcome.kind, ChildOutcome::Kind::Crashed);
  EXPECT_EQ(outcome.problem.rfind("crashed: signal 11", 0), 0u) << outcome.problem;
#endif
}

TEST(ForkedRun, AChildPastTheDeadlineIsKilled) {
  const auto began = std::chrono::steady_clock::now();
  const auto outcome = runInChildProcess(
      [] {
        ::sleep(30);
        return std::string("late");
      },
      0.3);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  EXPECT_EQ(outcome.kind, ChildOutcome::Kind::TimedOut);
  EXPECT_EQ(outcome.problem.rfind("killed: no result within", 0), 0u) << outcome.problem;
  EXPECT_LT(seconds, 10.0);
}

}  // namespace
}  // namespace pmdplan
