#pragma once
// The suite also runs built with AddressSanitizer and UndefinedBehaviorSanitizer
// (scripts/test-sanitizers; tests/CMakeLists.txt defines PMDPLAN_SANITIZER_BUILD there), which slows
// the collision code 10-30 times. The random equivalence tests exist there to run every code path
// under the sanitizers, not for statistical coverage, which the normal build's full trial counts
// keep: they draw `trials(full, sanitized)` cases, the smaller count in the sanitizer build, with the
// same seeds (the sanitized cases are the first of the full run's) and the same assertions.
namespace pmdplan::test {

#ifdef PMDPLAN_SANITIZER_BUILD
inline constexpr bool kSanitizerBuild = true;
#else
inline constexpr bool kSanitizerBuild = false;
#endif

/// `full` in the normal build, `sanitized` in the sanitizer build.
constexpr int trials(int full, int sanitized) { return kSanitizerBuild ? sanitized : full; }

}  // namespace pmdplan::test
