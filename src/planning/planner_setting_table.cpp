#include "pmdplan/planning/planner_setting_table.hpp"

#include <charconv>
#include <cmath>
#include <limits>
#include <type_traits>

#include "pmdplan/core/input_error.hpp"

namespace pmdplan {
namespace {

[[noreturn]] void reject(const std::string& flag, const std::string& text, const std::string& expected) {
  throw InputError("", "--" + flag, "'" + text + "' is not " + expected);
}

double parseNumber(const std::string& flag, const std::string& text) {
  double value = 0.0;
  if (text == "inf" || text == "infinity") return std::numeric_limits<double>::infinity();
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc{} || end != text.data() + text.size() || !std::isfinite(value))
    reject(flag, text, "a finite number");
  return value;
}

unsigned long long parseWhole(const std::string& flag, const std::string& text) {
  unsigned long long value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc{} || end != text.data() + text.size())
    reject(flag, text,
           "a whole number >= 0 (at most " + std::to_string(std::numeric_limits<unsigned long long>::max()) + ")");
  return value;
}

/// The shortest text that reads back to the same double.
std::string numberText(double value) {
  if (std::isinf(value)) return "inf";
  char buffer[40];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

template <typename Whole>
Whole narrow(const std::string& flag, const std::string& text, unsigned long long value) {
  if (value > static_cast<unsigned long long>(std::numeric_limits<Whole>::max()))
    reject(flag, text, "a whole number up to " + std::to_string(std::numeric_limits<Whole>::max()));
  return static_cast<Whole>(value);
}

/// A setting held in the field `access` reaches (a generic lambda, so const and not).
template <typename Field, typename Access>
PlannerSetting setting(std::string flag, std::string symbol, std::string help, Access access) {
  PlannerSetting s{flag, std::move(symbol), std::move(help), std::is_floating_point_v<Field> ? "NUMBER" : "COUNT", {},
                   {}};
  if constexpr (std::is_floating_point_v<Field>) {
    s.set = [flag, access](PlannerSettings& p, const std::string& text) { access(p) = parseNumber(flag, text); };
    s.get = [access](const PlannerSettings& p) { return numberText(access(p)); };
  } else {
    s.set = [flag, access](PlannerSettings& p, const std::string& text) {
      access(p) = narrow<Field>(flag, text, parseWhole(flag, text));
    };
    s.get = [access](const PlannerSettings& p) { return std::to_string(access(p)); };
  }
  return s;
}

PlannerSetting growthSetting() {
  PlannerSetting s{"rho-a-growth",
                   "",
                   "how rho_a grows per sweep: factorial (rho_a = k·rho_a, Algorithm 4) or linear (k·rho_a(1))",
                   "factorial|linear",
                   {},
                   {}};
  s.set = [](PlannerSettings& p, const std::string& text) {
    if (text == "factorial")
      p.rhoAGrowth = ArmBoxGrowth::Factorial;
    else if (text == "linear")
      p.rhoAGrowth = ArmBoxGrowth::Linear;
    else
      reject("rho-a-growth", text, "a growth rule; expected factorial or linear");
  };
  s.get = [](const PlannerSettings& p) {
    return std::string(p.rhoAGrowth == ArmBoxGrowth::Factorial ? "factorial" : "linear");
  };
  return s;
}

PlannerSetting smoothingSetting() {
  PlannerSetting s{"smooth", "", "smooth the path as in Sect. 5.3", "on|off", {}, {}};
  s.set = [](PlannerSettings& p, const std::string& text) {
    if (text == "on")
      p.smooth = true;
    else if (text == "off")
      p.smooth = false;
    else
      reject("smooth", text, "on or off");
  };
  s.get = [](const PlannerSettings& p) { return std::string(p.smooth ? "on" : "off"); };
  return s;
}

PlannerSetting sequenceSetting() {
  PlannerSetting s{
      "sequence",          "", "the samplers' numbers: random, halton or sdk (the paper's toolkit, Sect. 6)",
      "random|halton|sdk", {}, {}};
  s.set = [](PlannerSettings& p, const std::string& text) {
    const std::optional<SampleSequence> sequence = parseSampleSequence(text);
    if (!sequence) reject("sequence", text, "a sample sequence; expected " + knownSampleSequenceNames());
    p.sequence = *sequence;
  };
  s.get = [](const PlannerSettings& p) { return sampleSequenceName(p.sequence); };
  return s;
}

}  // namespace

const std::vector<PlannerSetting>& plannerSettingTable() {
  static const std::vector<PlannerSetting> table = {
      setting<double>(
          "rho-a", "rho_a", "initial half-size of the arm hypercubes, normalised arm-joint units",
          [](auto& p) -> auto& { return p.rhoA; }),
      growthSetting(),
      setting<std::size_t>(
          "neighbours", "K", "most neighbours a new sample is connected to",
          [](auto& p) -> auto& { return p.neighbours; }),
      setting<double>(
          "neighbour-threshold", "", "neighbour radius as a multiple of d(c_ini, c_goal) (Sect. 5.2: 1)",
          [](auto& p) -> auto& { return p.neighbourThreshold; }),
      setting<int>(
          "arm-trials", "n_A", "arm configurations tried per hypercube", [](auto& p) -> auto& { return p.armTrials; }),
      setting<int>(
          "hand-trials", "n_H", "hand configurations tried per arm configuration",
          [](auto& p) -> auto& { return p.handTrials; }),
      setting<std::size_t>(
          "max-samples", "N", "the run fails after this many samples (hand-arm draws)",
          [](auto& p) -> auto& { return p.maxSamples; }),
      setting<std::size_t>(
          "sweep-visits", "", "hypercube visits per sweep before rho_a grows, at least (1: the paper's one pass)",
          [](auto& p) -> auto& { return p.sweepVisits; }),
      setting<double>(
          "kappa", "kappa", "half-width of the PMD hand box along PMD i, in standard deviations sigma_i",
          [](auto& p) -> auto& { return p.pmdBox.kappa; }),
      setting<int>(
          "max-pmds", "", "most PMDs the hand dimension grows to (with the thumb base)",
          [](auto& p) -> auto& { return p.pmdBox.maxPmds; }),
      smoothingSetting(),
      setting<double>(
          "time-limit", "", "wall-clock limit of the roadmap construction in seconds (inf: none)",
          [](auto& p) -> auto& { return p.timeLimit; }),
      setting<std::uint64_t>(
          "seed", "", "random seed", [](auto& p) -> auto& { return p.seed; }),
      sequenceSetting(),
      setting<std::size_t>(
          "lazy-batch", "", "for pmd-lazy: arm boxes sampled along the segment per round, besides the four at its ends",
          [](auto& p) -> auto& { return p.lazy.batch; }),
      setting<std::size_t>(
          "lazy-neighbours", "", "for pmd-lazy: most lazy edges from a new sample to its nearest nodes",
          [](auto& p) -> auto& { return p.lazy.neighbours; }),
      setting<double>(
          "lazy-radius", "", "for pmd-lazy: lazy edges join nodes at most this multiple of d(c_ini, c_goal) apart",
          [](auto& p) -> auto& { return p.lazy.radius; }),
      setting<std::size_t>(
          "lazy-probes", "", "for pmd-lazy: inner states of each candidate edge checked before its motion check",
          [](auto& p) -> auto& { return p.lazy.probes; }),
      setting<double>(
          "lazy-arm-growth", "", "for pmd-lazy: rho_a is multiplied by this after each round without a path",
          [](auto& p) -> auto& { return p.lazy.armGrowth; }),
      setting<double>(
          "connect-range", "", "for pmd-connect: longest tree step, as a multiple of d(c_ini, c_goal) (inf: none)",
          [](auto& p) -> auto& { return p.connect.range; }),
      setting<std::size_t>(
          "connect-round", "",
          "for pmd-connect: samples per round; the arm region grows after each round that left the trees apart",
          [](auto& p) -> auto& { return p.connect.round; }),
      setting<double>(
          "connect-arm-growth", "",
          "for pmd-connect: the arm region's largest half-size is multiplied by this after each round that left the "
          "trees apart",
          [](auto& p) -> auto& { return p.connect.armGrowth; }),
      setting<std::size_t>(
          "connect-probes", "",
          "for pmd-connect: inner states of a new tree step checked before it joins its tree (its motion check waits "
          "for a path)",
          [](auto& p) -> auto& { return p.connect.probes; }),
  };
  return table;
}

std::string describePlannerSettings(const PlannerSettings& parameters) {
  std::string text;
  for (const PlannerSetting& s : plannerSettingTable())
    text += (text.empty() ? "" : " ") + s.flag + "=" + s.get(parameters);
  return text;
}

}  // namespace pmdplan
