#include "pmdplan/io/files/trajectory_file.hpp"

#include <cmath>
#include <stdexcept>

#include "json_reading.hpp"
#include "pmdplan/core/atomic_file.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/io/files/json_text.hpp"
#include "pmdplan/text/number_text.hpp"

namespace pmdplan {
namespace {

constexpr const char* kFormat = "pmdplan-joint-trajectory";

nlohmann::ordered_json values(const Eigen::VectorXd& v, std::size_t size, const char* what) {
  if (static_cast<std::size_t>(v.size()) != size)
    throw std::invalid_argument(std::string("trajectory: wrong number of ") + what);
  nlohmann::ordered_json array = nlohmann::ordered_json::array();
  for (Eigen::Index k = 0; k < v.size(); ++k) array.push_back(v[k]);
  return array;
}

Eigen::VectorXd readValues(const nlohmann::json& value, const json_reading::Place& place, std::size_t size) {
  const nlohmann::json& array = json_reading::requireArray(value, place);
  if (array.size() != size)
    place.fail("expected " + std::to_string(size) + " values (one per joint name), found " +
               std::to_string(array.size()));
  Eigen::VectorXd v(static_cast<Eigen::Index>(size));
  for (std::size_t k = 0; k < size; ++k)
    v[static_cast<Eigen::Index>(k)] = json_reading::readFinite(array[k], place.index(k));
  return v;
}

}  // namespace

std::string formatTrajectoryFile(const TrajectoryFile& file) {
  const std::size_t n = file.trajectory.jointNames.size();
  nlohmann::ordered_json document;
  document["format"] = kFormat;
  document["version"] = 1;
  document["task"] = file.task;
  document["planner"] = file.planner;
  document["seed"] = file.seed;
  document["joint_names"] = file.trajectory.jointNames;
  nlohmann::ordered_json mimic = nlohmann::ordered_json::object();
  for (const MimicRelation& relation : file.mimic)
    mimic[relation.joint] = nlohmann::ordered_json::array({relation.source, relation.multiplier, relation.offset});
  document["mimic"] = std::move(mimic);
  if (file.velocityLimits.size() != n || file.accelerationLimits.size() != n)
    throw std::invalid_argument("trajectory: one velocity and one acceleration limit per joint");
  document["limits"] = {{"velocity", file.velocityLimits}, {"acceleration", file.accelerationLimits}};
  document["blend_tolerance"] = file.blendTolerance;
  document["duration"] = file.trajectory.points.empty() ? 0.0 : file.trajectory.points.back().time;
  nlohmann::ordered_json points = nlohmann::ordered_json::array();
  for (const TimedState& state : file.trajectory.points) {
    nlohmann::ordered_json point;
    point["positions"] = values(state.position, n, "positions");
    point["velocities"] = values(state.velocity, n, "velocities");
    point["accelerations"] = values(state.acceleration, n, "accelerations");
    point["time_from_start"] = state.time;
    points.push_back(std::move(point));
  }
  document["points"] = std::move(points);
  return formatJson(document);
}

std::string formatTrajectoryCsv(const JointTrajectory& trajectory) {
  std::string out = "time_from_start";
  for (const char* suffix : {"", ".velocity", ".acceleration"})
    for (const auto& name : trajectory.jointNames) out += "," + name + suffix;
  out += '\n';
  for (const TimedState& state : trajectory.points) {
    out += exactNumberText(state.time);
    for (const Eigen::VectorXd* v : {&state.position, &state.velocity, &state.acceleration})
      for (Eigen::Index k = 0; k < v->size(); ++k) {
        if (!std::isfinite((*v)[k])) throw std::invalid_argument("trajectory CSV: a value is not finite");
        out += "," + exactNumberText((*v)[k]);
      }
    out += '\n';
  }
  return out;
}

void writeTrajectoryFile(const std::filesystem::path& path, const TrajectoryFile& file) {
  writeFileAtomically(path, formatTrajectoryFile(file));
}

void writeTrajectoryCsv(const std::filesystem::path& path, const JointTrajectory& trajectory) {
  writeFileAtomically(path, formatTrajectoryCsv(trajectory));
}

bool isTrajectoryFileText(const std::string& text) {
  const nlohmann::json document = nlohmann::json::parse(text, nullptr, false);
  return document.is_object() && document.contains("format") && document["format"] == kFormat;
}

TrajectoryFile parseTrajectoryFile(const std::string& text, const std::string& file) {
  using namespace json_reading;
  const nlohmann::json document = parseDocument(text, file);
  const Place root{file, ""};
  requireObject(document, root);
  checkKeys(document, root,
            {"format", "version", "task", "planner", "seed", "joint_names", "mimic", "limits", "blend_tolerance",
             "duration", "points"},
            {"format", "version", "task", "planner", "seed", "joint_names", "mimic", "limits", "blend_tolerance",
             "duration", "points"});
  if (readString(member(document, "format"), root.key("format")) != kFormat)
    root.key("format").fail(std::string("expected \"") + kFormat + "\"");
  if (readUnsigned(member(document, "version"), root.key("version")) != 1) root.key("version").fail("expected 1");
  TrajectoryFile out;
  out.task = readString(member(document, "task"), root.key("task"));
  out.planner = readString(member(document, "planner"), root.key("planner"));
  out.seed = readUnsigned(member(document, "seed"), root.key("seed"));
  const nlohmann::json& names = requireArray(member(document, "joint_names"), root.key("joint_names"));
  for (std::size_t i = 0; i < names.size(); ++i)
    out.trajectory.jointNames.push_back(readString(names[i], root.key("joint_names").index(i)));
  const std::size_t n = out.trajectory.jointNames.size();
  if (n == 0) root.key("joint_names").fail("expected at least one joint name");
  const Place mimicPlace = root.key("mimic");
  const nlohmann::json& mimic = requireObject(member(document, "mimic"), mimicPlace);
  for (auto item = mimic.begin(); item != mimic.end(); ++item) {
    const Place entryPlace = mimicPlace.key(item.key());
    const nlohmann::json& entry = requireArray(item.value(), entryPlace);
    if (entry.size() != 3) entryPlace.fail("expected [source joint, multiplier, offset]");
    out.mimic.push_back({item.key(), readString(entry[0], entryPlace.index(0)),
                         readFinite(entry[1], entryPlace.index(1)), readFinite(entry[2], entryPlace.index(2))});
  }
  const Place limitsPlace = root.key("limits");
  const nlohmann::json& limits = requireObject(member(document, "limits"), limitsPlace);
  checkKeys(limits, limitsPlace, {"velocity", "acceleration"}, {"velocity", "acceleration"});
  for (const char* key : {"velocity", "acceleration"}) {
    const Eigen::VectorXd v = readValues(member(limits, key), limitsPlace.key(key), n);
    for (Eigen::Index k = 0; k < v.size(); ++k)
      if (!(v[k] > 0.0)) limitsPlace.key(key).index(static_cast<std::size_t>(k)).fail("expected a positive limit");
    (std::string(key) == "velocity" ? out.velocityLimits : out.accelerationLimits)
        .assign(v.data(), v.data() + v.size());
  }
  out.blendTolerance = readFinite(member(document, "blend_tolerance"), root.key("blend_tolerance"));
  readFinite(member(document, "duration"), root.key("duration"));
  const Place pointsPlace = root.key("points");
  const nlohmann::json& points = requireArray(member(document, "points"), pointsPlace);
  if (points.size() < 2) pointsPlace.fail("expected at least two points");
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Place place = pointsPlace.index(i);
    requireObject(points[i], place);
    checkKeys(points[i], place, {"positions", "velocities", "accelerations", "time_from_start"},
              {"positions", "velocities", "accelerations", "time_from_start"});
    TimedState state;
    state.position = readValues(member(points[i], "positions"), place.key("positions"), n);
    state.velocity = readValues(member(points[i], "velocities"), place.key("velocities"), n);
    state.acceleration = readValues(member(points[i], "accelerations"), place.key("accelerations"), n);
    state.time = readFinite(member(points[i], "time_from_start"), place.key("time_from_start"));
    if (i == 0 ? state.time != 0.0 : !(state.time > out.trajectory.points.back().time))
      place.key("time_from_start")
          .fail(i == 0 ? "expected 0 for the first point" : "expected a time after the previous point's");
    out.trajectory.points.push_back(std::move(state));
  }
  return out;
}

}  // namespace pmdplan
