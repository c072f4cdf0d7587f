#include "pmdplan/bench/run_record.hpp"

#include <cmath>
#include <functional>
#include <string_view>
#include <vector>

namespace pmdplan {
namespace {

using Json = nlohmann::ordered_json;

// Numbers keep every bit: nlohmann writes the shortest text that reads back to the same double;
// a non-finite one (JSON has none) is the string "inf", "-inf" or "nan".
Json toJson(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  return value;
}
bool fromJson(const nlohmann::json& json, double& value) {
  if (json.is_number()) {
    value = json.get<double>();
    return true;
  }
  if (!json.is_string()) return false;
  const auto& text = json.get_ref<const std::string&>();
  if (text == "nan")
    value = std::nan("");
  else if (text == "inf")
    value = HUGE_VAL;
  else if (text == "-inf")
    value = -HUGE_VAL;
  else
    return false;
  return true;
}

Json toJson(const std::string& value) { return value; }
bool fromJson(const nlohmann::json& json, std::string& value) {
  if (!json.is_string()) return false;
  value = json.get<std::string>();
  return true;
}

Json toJson(bool value) { return value; }
bool fromJson(const nlohmann::json& json, bool& value) {
  if (!json.is_boolean()) return false;
  value = json.get<bool>();
  return true;
}

Json toJson(int value) { return value; }
bool fromJson(const nlohmann::json& json, int& value) {
  if (!json.is_number_integer()) return false;
  const auto wide = json.get<long long>();
  value = static_cast<int>(wide);
  return wide == value;
}

template <typename T, std::enable_if_t<std::is_unsigned_v<T> && !std::is_same_v<T, bool>, int> = 0>
Json toJson(T value) {
  return value;
}
template <typename T, std::enable_if_t<std::is_unsigned_v<T> && !std::is_same_v<T, bool>, int> = 0>
bool fromJson(const nlohmann::json& json, T& value) {
  if (!json.is_number_unsigned()) return false;
  value = json.get<T>();
  return true;
}

/// Sampled nodes by hand dimension: {"2": 7, "3": 0}.
Json toJson(const std::map<int, std::size_t>& counts) {
  Json json = Json::object();
  for (const auto& [dimension, nodes] : counts) json[std::to_string(dimension)] = nodes;
  return json;
}
bool fromJson(const nlohmann::json& json, std::map<int, std::size_t>& counts) {
  if (!json.is_object()) return false;
  for (auto item = json.begin(); item != json.end(); ++item) {
    const std::string& key = item.key();
    if (key.empty() || key.size() > 4 || key.find_first_not_of("0123456789") != std::string::npos) return false;
    std::size_t nodes = 0;
    if (!fromJson(item.value(), nodes)) return false;
    counts[std::stoi(key)] = nodes;
  }
  return true;
}

/// One key of a record's JSON object and the member it holds.
template <typename S>
struct Field {
  const char* key;
  std::function<Json(const S&)> write;
  std::function<bool(const nlohmann::json&, S&)> read;
};

template <typename S>
const std::vector<Field<S>>& fieldsOf();

/// An absent part (a run without a path has no human-likeness) is null.
template <typename Part>
Json toJson(const std::optional<Part>& part) {
  if (!part) return nullptr;
  Json json = Json::object();
  for (const Field<Part>& f : fieldsOf<Part>()) json[f.key] = f.write(*part);
  return json;
}
template <typename Part>
bool fromJson(const nlohmann::json& json, std::optional<Part>& part) {
  part.reset();
  if (json.is_null()) return true;
  if (!json.is_object() || json.size() != fieldsOf<Part>().size()) return false;
  Part value;
  for (const Field<Part>& f : fieldsOf<Part>())
    if (!json.contains(f.key) || !f.read(json.at(f.key), value)) return false;
  part = value;
  return true;
}

template <typename S, typename T>
Field<S> field(const char* key, T S::*member) {
  return {key, [member](const S& s) { return toJson(s.*member); },
          [member](const nlohmann::json& json, S& s) { return fromJson(json, s.*member); }};
}

template <>
const std::vector<Field<IndependentHumanLikeness>>& fieldsOf() {
  using I = IndependentHumanLikeness;
  static const std::vector<Field<I>> fields = {
      field("authors_subspace_distance_mean", &I::authorsSubspaceDistanceMean),
      field("authors_subspace_distance_max", &I::authorsSubspaceDistanceMax),
      field("joint_coupling", &I::jointCoupling),
  };
  return fields;
}

template <>
const std::vector<Field<HumanLikeness>>& fieldsOf() {
  using H = HumanLikeness;
  static const std::vector<Field<H>> fields = {
      field("subspace_distance_mean", &H::subspaceDistanceMean),
      field("subspace_distance_max", &H::subspaceDistanceMax),
      field("mahalanobis_mean", &H::mahalanobisMean),
      field("independent", &H::independent),
  };
  return fields;
}

template <>
const std::vector<Field<RunRecord>>& fieldsOf() {
  using R = RunRecord;
  static const std::vector<Field<R>> fields = {
      field("task", &R::task),
      field("planner", &R::planner),
      field("run", &R::run),
      field("seed", &R::seed),
      field("solved", &R::solved),
      field("valid", &R::valid),
      field("planning_time_s", &R::planningTimeSeconds),
      field("smoothing_time_s", &R::smoothingTimeSeconds),
      field("certification_time_s", &R::certificationTimeSeconds),
      field("samples", &R::samples),
      field("arm_trials", &R::armTrials),
      field("max_trials", &R::maxTrials),
      field("final_rho_a", &R::finalArmHalfSize),
      field("nodes_by_hand_dimension", &R::nodesByHandDimension),
      field("roadmap_nodes", &R::roadmapNodes),
      field("path_nodes", &R::pathNodes),
      field("path_length", &R::pathLength),
      field("collision_checks", &R::collisionChecks),
      field("human_likeness", &R::humanLikeness),
      field("failure", &R::failure),
  };
  return fields;
}

}  // namespace

std::string nodesByHandDimensionText(const std::map<int, std::size_t>& counts) {
  std::string text;
  for (const auto& [dimension, nodes] : counts) {
    if (!text.empty()) text += ',';
    text += std::to_string(dimension);
    text += ':';
    text += std::to_string(nodes);
  }
  return text;
}

const std::vector<const char*>& runRecordKeys() {
  static const std::vector<const char*> keys = [] {
    std::vector<const char*> all;
    for (const auto& f : fieldsOf<RunRecord>()) all.push_back(f.key);
    return all;
  }();
  return keys;
}

nlohmann::ordered_json runRecordToJson(const RunRecord& record) {
  Json json = Json::object();
  for (const auto& f : fieldsOf<RunRecord>()) json[f.key] = f.write(record);
  return json;
}

std::optional<RunRecord> runRecordFromJson(const nlohmann::json& json, std::size_t otherKeys) {
  constexpr const char* kLaterKey = "certification_time_s";  // absent from older journals
  if (!json.is_object()) return std::nullopt;
  const bool older = !json.contains(kLaterKey);
  if (json.size() + (older ? 1 : 0) != fieldsOf<RunRecord>().size() + otherKeys) return std::nullopt;
  RunRecord record;
  for (const auto& f : fieldsOf<RunRecord>()) {
    if (older && std::string_view(f.key) == kLaterKey) continue;
    if (!json.contains(f.key) || !f.read(json.at(f.key), record)) return std::nullopt;
  }
  return record;
}

std::string encodeRunRecord(const RunRecord& record) {
  // Text that is not UTF-8 (a failure message quoting a file) cannot be JSON as it is: replaced.
  return runRecordToJson(record).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::optional<RunRecord> decodeRunRecord(const std::string& text) {
  const nlohmann::json json = nlohmann::json::parse(text, nullptr, false);
  if (json.is_discarded()) return std::nullopt;
  return runRecordFromJson(json);
}

}  // namespace pmdplan
