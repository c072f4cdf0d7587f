#include "pmdplan/planning/planner_setting_table.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>

#include "pmdplan/core/input_error.hpp"

namespace pmdplan {
namespace {

[[noreturn]] void reject(const std::string& key, const std::string& text, const std::string& expected) {
  throw InputError("", key, "'" + text + "' is not " + expected);
}

double parseNumber(const std::string& key, const std::string& text) {
  double value = 0.0;
  if (text == "inf" || text == "infinity") return std::numeric_limits<double>::infinity();
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc{} || end != text.data() + text.size() || !std::isfinite(value))
    reject(key, text, "a finite number");
  return value;
}

unsigned long long parseWhole(const std::string& key, const std::string& text) {
  unsigned long long value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc{} || end != text.data() + text.size())
    reject(key, text,
           "a whole number >= 0 (at most " + std::to_string(std::numeric_limits<unsigned long long>::max()) + ")");
  return value;
}

/// The shortest text that reads back to the same double ("-inf" stays negative, and is rejected).
std::string numberText(double value) {
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buffer[40];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

template <typename Whole>
Whole narrow(const std::string& key, const std::string& text, unsigned long long value) {
  if (value > static_cast<unsigned long long>(std::numeric_limits<Whole>::max()))
    reject(key, text, "a whole number up to " + std::to_string(std::numeric_limits<Whole>::max()));
  return static_cast<Whole>(value);
}

/// A Number (double field) or Count (whole field) held in the field `access` reaches (a generic
/// lambda, so const and not).
template <typename Field, typename Access>
PlannerSetting setting(std::string key, std::string symbol, std::string help, Access access) {
  PlannerSetting s;
  s.flag = key;
  s.symbol = std::move(symbol);
  s.help = std::move(help);
  if constexpr (std::is_floating_point_v<Field>) {
    s.kind = SettingKind::Number;
    s.set = [key, access](PlannerSettings& p, const std::string& text) { access(p) = parseNumber(key, text); };
    s.get = [access](const PlannerSettings& p) { return numberText(access(p)); };
  } else {
    s.kind = SettingKind::Count;
    s.set = [key, access](PlannerSettings& p, const std::string& text) {
      access(p) = narrow<Field>(key, text, parseWhole(key, text));
    };
    s.get = [access](const PlannerSettings& p) { return std::to_string(access(p)); };
  }
  return s;
}

/// "a, b or c".
std::string choiceList(const std::vector<std::string>& choices) {
  std::string text;
  for (std::size_t i = 0; i < choices.size(); ++i)
    text += (i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ") + choices[i];
  return text;
}

/// A Choice (or, with the choices "on" and "off", a Switch) held in the field `access` reaches,
/// whose values `names` lists with their texts.
template <typename Field, typename Access>
PlannerSetting choiceSetting(std::string key, std::string help, std::vector<std::pair<std::string, Field>> names,
                             Access access, const std::string& what) {
  PlannerSetting s;
  s.flag = key;
  s.help = std::move(help);
  for (const auto& entry : names) s.choices.push_back(entry.first);
  s.kind = s.choices == std::vector<std::string>{"on", "off"} ? SettingKind::Switch : SettingKind::Choice;
  const std::string expected =
      s.kind == SettingKind::Switch ? "on or off" : what + "; expected " + choiceList(s.choices);
  s.set = [key, names, access, expected](PlannerSettings& p, const std::string& text) {
    for (const auto& [name, value] : names)
      if (name == text) {
        access(p) = value;
        return;
      }
    reject(key, text, expected);
  };
  s.get = [names, access](const PlannerSettings& p) {
    for (const auto& [name, value] : names)
      if (access(p) == value) return name;
    return names.front().first;  // unreachable: every value of the field has a name
  };
  return s;
}

std::vector<std::pair<std::string, SampleSequence>> sequenceNames() {
  std::vector<std::pair<std::string, SampleSequence>> names;
  const std::string known = knownSampleSequenceNames();  // "random, halton, sdk"
  for (std::size_t from = 0; from <= known.size();) {
    const std::size_t comma = std::min(known.find(", ", from), known.size());
    const std::string name = known.substr(from, comma - from);
    names.emplace_back(name, *parseSampleSequence(name));
    from = comma + 2;
  }
  return names;
}

}  // namespace

const std::vector<PlannerSetting>& plannerSettingTable() {
  static const std::vector<PlannerSetting> table = {
      setting<double>(
          "rho-a", "rho_a", "initial half-size of the arm hypercubes, normalised arm-joint units",
          [](auto& p) -> auto& { return p.rhoA; }),
      choiceSetting<ArmBoxGrowth>(
          "rho-a-growth", "how rho_a grows per sweep: factorial (rho_a = k·rho_a, Algorithm 4) or linear (k·rho_a(1))",
          {{"factorial", ArmBoxGrowth::Factorial}, {"linear", ArmBoxGrowth::Linear}},
          [](auto& p) -> auto& { return p.rhoAGrowth; }, "a growth rule"),
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
      choiceSetting<bool>(
          "smooth", "smooth the path as in Sect. 5.3", {{"on", true}, {"off", false}},
          [](auto& p) -> auto& { return p.smooth; }, "on or off"),
      setting<double>(
          "time-limit", "", "wall-clock limit of the roadmap construction in seconds (inf: none)",
          [](auto& p) -> auto& { return p.timeLimit; }),
      setting<std::uint64_t>(
          "seed", "", "random seed", [](auto& p) -> auto& { return p.seed; }),
      choiceSetting<SampleSequence>(
          "sequence", "the samplers' numbers: random, halton or sdk (the paper's toolkit, Sect. 6)", sequenceNames(),
          [](auto& p) -> auto& { return p.sequence; }, "a sample sequence"),
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

std::string settingKindName(SettingKind kind) {
  switch (kind) {
    case SettingKind::Number:
      return "number";
    case SettingKind::Count:
      return "count";
    case SettingKind::Choice:
      return "choice";
    case SettingKind::Switch:
      return "switch";
  }
  return "number";
}

std::string settingName(const std::string& key) {
  std::string name = key;
  std::replace(name.begin(), name.end(), '-', '_');
  return name;
}

std::string PlannerSetting::valueName() const {
  if (kind == SettingKind::Number) return "NUMBER";
  if (kind == SettingKind::Count) return "COUNT";
  std::string text;
  for (const std::string& choice : choices) text += (text.empty() ? "" : "|") + choice;
  return text;
}

const PlannerSetting* findPlannerSetting(const std::string& keyOrName) {
  for (const PlannerSetting& s : plannerSettingTable())
    if (s.flag == keyOrName || s.name() == keyOrName) return &s;
  return nullptr;
}

std::string describePlannerSettings(const PlannerSettings& parameters) {
  std::string text;
  for (const PlannerSetting& s : plannerSettingTable())
    text += (text.empty() ? "" : " ") + s.flag + "=" + s.get(parameters);
  return text;
}

}  // namespace pmdplan
