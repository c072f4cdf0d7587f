#include "pmdplan/bench/run_record.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <vector>

namespace pmdplan {
namespace {

// Fields are separated by a tab; text fields have tabs, newlines and backslashes escaped.
constexpr char kSeparator = '\t';

std::string escapedText(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '\\')
      out += "\\\\";
    else if (c == '\t')
      out += "\\t";
    else if (c == '\n')
      out += "\\n";
    else if (c == '\r')
      out += "\\r";
    else
      out += c;
  }
  return out;
}

std::optional<std::string> unescapedText(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '\\') {
      out += text[i];
      continue;
    }
    if (++i >= text.size()) return std::nullopt;
    const char c = text[i];
    if (c == '\\')
      out += '\\';
    else if (c == 't')
      out += '\t';
    else if (c == 'n')
      out += '\n';
    else if (c == 'r')
      out += '\r';
    else
      return std::nullopt;
  }
  return out;
}

std::string number(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

template <typename T>
std::string number(T value) {
  return std::to_string(value);
}

template <typename T>
bool parse(const std::string& text, T& value) {
  const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
  return result.ec == std::errc() && result.ptr == text.data() + text.size();
}

bool parseDimensionCounts(const std::string& text, std::map<int, std::size_t>& counts) {
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = std::min(text.find(',', start), text.size());
    const std::string item = text.substr(start, end - start);
    const std::size_t colon = item.find(':');
    int dimension = 0;
    std::size_t nodes = 0;
    if (colon == std::string::npos || !parse(item.substr(0, colon), dimension) ||
        !parse(item.substr(colon + 1), nodes) || !counts.emplace(dimension, nodes).second)
      return false;
    start = end + 1;
  }
  return true;
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> fields(1);
  for (const char c : line) {
    if (c == kSeparator)
      fields.emplace_back();
    else
      fields.back() += c;
  }
  return fields;
}

}  // namespace

std::string nodesByHandDimensionText(const std::map<int, std::size_t>& counts) {
  std::string text;
  for (const auto& [dimension, nodes] : counts) {
    if (!text.empty()) text += ',';
    text += number(dimension);
    text += ':';
    text += number(nodes);
  }
  return text;
}

std::string encodeRunRecord(const RunRecord& r) {
  std::vector<std::string> fields = {"run-record-2",
                                     escapedText(r.task),
                                     escapedText(r.planner),
                                     number(r.run),
                                     number(r.seed),
                                     r.solved ? "1" : "0",
                                     r.valid ? "1" : "0",
                                     number(r.planningTimeSeconds),
                                     number(r.smoothingTimeSeconds),
                                     number(r.samples),
                                     number(r.armTrials),
                                     number(r.maxTrials),
                                     number(r.finalArmHalfSize),
                                     nodesByHandDimensionText(r.nodesByHandDimension),
                                     number(r.roadmapNodes),
                                     number(r.pathNodes),
                                     number(r.pathLength),
                                     number(r.collisionChecks),
                                     r.humanLikeness ? "1" : "0",
                                     number(r.humanLikeness ? r.humanLikeness->subspaceDistanceMean : 0.0),
                                     number(r.humanLikeness ? r.humanLikeness->subspaceDistanceMax : 0.0),
                                     number(r.humanLikeness ? r.humanLikeness->mahalanobisMean : 0.0),
                                     escapedText(r.failure)};
  // The measures independent of the planner's model (last, so older fields keep their places).
  const IndependentHumanLikeness* independent =
      r.humanLikeness && r.humanLikeness->independent ? &*r.humanLikeness->independent : nullptr;
  fields.push_back(independent ? "1" : "0");
  fields.push_back(number(independent ? independent->authorsSubspaceDistanceMean : 0.0));
  fields.push_back(number(independent ? independent->authorsSubspaceDistanceMax : 0.0));
  fields.push_back(number(independent ? independent->jointCoupling : 0.0));
  std::string line;
  for (std::size_t i = 0; i < fields.size(); ++i) line += (i ? std::string(1, kSeparator) : "") + fields[i];
  return line;
}

std::optional<RunRecord> decodeRunRecord(const std::string& text) {
  const auto f = split(text);
  if (f.size() != 27 || f[0] != "run-record-2") return std::nullopt;
  RunRecord r;
  const auto task = unescapedText(f[1]), planner = unescapedText(f[2]), failure = unescapedText(f[22]);
  if (!task || !planner || !failure) return std::nullopt;
  r.task = *task;
  r.planner = *planner;
  r.failure = *failure;
  const auto flag = [](const std::string& s, bool& value) {
    if (s != "0" && s != "1") return false;
    value = s == "1";
    return true;
  };
  bool hasHumanLikeness = false;
  HumanLikeness h;
  const bool ok = parse(f[3], r.run) && parse(f[4], r.seed) && flag(f[5], r.solved) && flag(f[6], r.valid) &&
                  parse(f[7], r.planningTimeSeconds) && parse(f[8], r.smoothingTimeSeconds) && parse(f[9], r.samples) &&
                  parse(f[10], r.armTrials) && parse(f[11], r.maxTrials) && parse(f[12], r.finalArmHalfSize) &&
                  parseDimensionCounts(f[13], r.nodesByHandDimension) && parse(f[14], r.roadmapNodes) &&
                  parse(f[15], r.pathNodes) && parse(f[16], r.pathLength) && parse(f[17], r.collisionChecks) &&
                  flag(f[18], hasHumanLikeness) && parse(f[19], h.subspaceDistanceMean) &&
                  parse(f[20], h.subspaceDistanceMax) && parse(f[21], h.mahalanobisMean);
  bool hasIndependent = false;
  IndependentHumanLikeness independent;
  const bool independentOk = flag(f[23], hasIndependent) && parse(f[24], independent.authorsSubspaceDistanceMean) &&
                             parse(f[25], independent.authorsSubspaceDistanceMax) &&
                             parse(f[26], independent.jointCoupling);
  if (!ok || !independentOk) return std::nullopt;
  if (hasIndependent) h.independent = independent;
  if (hasHumanLikeness) r.humanLikeness = h;
  return r;
}

}  // namespace pmdplan
