#include "pmdplan/io/files/path_file.hpp"

#include <cmath>
#include <set>
#include <stdexcept>

#include "json_reading.hpp"
#include "pmdplan/core/atomic_file.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/core/message_text.hpp"
#include "pmdplan/io/files/json_text.hpp"
#include "pmdplan/io/files/statistics_json.hpp"

namespace pmdplan {

std::string formatPathFile(const PathFile& path, const PathFileSettings& options) {
  nlohmann::ordered_json document;
  document["task"] = path.task;
  document["planner"] = path.planner;
  document["seed"] = path.seed;
  document["joint_names"] = path.jointNames;
  nlohmann::ordered_json points = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < path.points.size(); ++i) {
    const Configuration& q = path.points[i];
    if (q.size() != static_cast<Eigen::Index>(path.jointNames.size()))
      throw std::invalid_argument("formatPathFile: point " + std::to_string(i) + " has " + std::to_string(q.size()) +
                                  " values for " + std::to_string(path.jointNames.size()) + " joints");
    nlohmann::ordered_json positions = nlohmann::ordered_json::array();
    for (Eigen::Index k = 0; k < q.size(); ++k) positions.push_back(q[k]);
    nlohmann::ordered_json point;
    point["positions"] = std::move(positions);
    points.push_back(std::move(point));
  }
  document["points"] = std::move(points);
  if (path.closingFrom) {
    const std::size_t k = *path.closingFrom, last = path.points.size() - 1;
    if (k == 0 || k >= last)
      throw std::invalid_argument("formatPathFile: the closing phase must start inside the path");
    nlohmann::ordered_json phases;
    phases["approach"] = nlohmann::ordered_json::array({0, k});
    phases["closing"] = nlohmann::ordered_json::array({k, last});
    document["phases"] = std::move(phases);
  }
  nlohmann::ordered_json mimic = nlohmann::ordered_json::object();
  for (const MimicRelation& relation : path.mimic)
    mimic[relation.joint] = nlohmann::ordered_json::array({relation.source, relation.multiplier, relation.offset});
  document["mimic"] = std::move(mimic);
  document["statistics"] = statisticsToJson(path.statistics, options.includeTimings);
  return formatJson(document);
}

void writePathFile(const std::filesystem::path& file, const PathFile& path, const PathFileSettings& options) {
  writeFileAtomically(file, formatPathFile(path, options));
}

namespace {

/// `{"approach": [0, k], "closing": [k, n - 1]}` with 0 < k < n - 1: returns k.
std::size_t readPhases(const nlohmann::json& value, const json_reading::Place& place, std::size_t points) {
  using namespace json_reading;
  requireObject(value, place);
  checkKeys(value, place, {"approach", "closing"}, {"approach", "closing"});
  std::size_t bounds[2][2];
  const char* names[2] = {"approach", "closing"};
  for (int p = 0; p < 2; ++p) {
    const Place phase = place.key(names[p]);
    const nlohmann::json& range = requireArray(member(value, names[p]), phase);
    if (range.size() != 2) phase.fail("expected [first point, last point]");
    for (int e = 0; e < 2; ++e)
      bounds[p][e] = readUnsigned(range[static_cast<std::size_t>(e)], phase.index(static_cast<std::size_t>(e)));
  }
  const std::size_t k = bounds[0][1];
  if (bounds[0][0] != 0 || bounds[1][0] != k || bounds[1][1] + 1 != points || k == 0 || k + 1 >= points)
    place.fail("expected {\"approach\": [0, k], \"closing\": [k, " + std::to_string(points - 1) + "]} with 0 < k < " +
               std::to_string(points - 1) + " (the pre-grasp's index)");
  return k;
}

}  // namespace

PathFile parsePathFile(const std::string& text, const std::string& file) {
  using namespace json_reading;
  const nlohmann::json document = parseDocument(text, file);
  const Place root{file, ""};
  requireObject(document, root);
  checkKeys(document, root, {"task", "planner", "seed", "joint_names", "points", "phases", "mimic", "statistics"},
            {"task", "planner", "seed", "joint_names", "points", "mimic", "statistics"});

  PathFile path;
  path.task = readString(member(document, "task"), root.key("task"));
  path.planner = readString(member(document, "planner"), root.key("planner"));
  if (path.planner.empty()) root.key("planner").fail("expected the planner's name (pmd, full, ...)");
  path.seed = readUnsigned(member(document, "seed"), root.key("seed"));

  const Place namesPlace = root.key("joint_names");
  const nlohmann::json& names = requireArray(member(document, "joint_names"), namesPlace);
  if (names.empty()) namesPlace.fail("expected at least one joint name");
  std::set<std::string> seen;
  for (std::size_t i = 0; i < names.size(); ++i) {
    std::string name = readString(names[i], namesPlace.index(i));
    if (name.empty()) namesPlace.index(i).fail("expected a joint name, found an empty string");
    if (!seen.insert(name).second) namesPlace.index(i).fail("joint " + quotedText(name) + " appears twice");
    path.jointNames.push_back(std::move(name));
  }

  const Place pointsPlace = root.key("points");
  const nlohmann::json& points = requireArray(member(document, "points"), pointsPlace);
  if (points.size() < 2)
    pointsPlace.fail("expected at least two points (start and goal), found " + std::to_string(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Place pointPlace = pointsPlace.index(i);
    requireObject(points[i], pointPlace);
    checkKeys(points[i], pointPlace, {"positions"}, {"positions"});
    const Place positionsPlace = pointPlace.key("positions");
    const nlohmann::json& positions = requireArray(member(points[i], "positions"), positionsPlace);
    if (positions.size() != path.jointNames.size())
      positionsPlace.fail("expected " + std::to_string(path.jointNames.size()) +
                          " values (one per joint name), found " + std::to_string(positions.size()));
    Configuration q(static_cast<Eigen::Index>(positions.size()));
    for (std::size_t k = 0; k < positions.size(); ++k)
      q[static_cast<Eigen::Index>(k)] = readFinite(positions[k], positionsPlace.index(k));
    path.points.push_back(std::move(q));
  }

  if (document.contains("phases"))
    path.closingFrom = readPhases(member(document, "phases"), root.key("phases"), path.points.size());

  const Place mimicPlace = root.key("mimic");
  const nlohmann::json& mimic = requireObject(member(document, "mimic"), mimicPlace);
  for (auto item = mimic.begin(); item != mimic.end(); ++item) {
    const Place entryPlace = mimicPlace.key(item.key());
    if (seen.count(item.key()) != 0) entryPlace.fail("a mimic joint cannot also be an active joint");
    const nlohmann::json& entry = requireArray(item.value(), entryPlace);
    if (entry.size() != 3) entryPlace.fail("expected [source joint, multiplier, offset]");
    MimicRelation relation;
    relation.joint = item.key();
    relation.source = readString(entry[0], entryPlace.index(0));
    if (relation.source.empty()) entryPlace.index(0).fail("expected the source joint's name");
    relation.multiplier = readFinite(entry[1], entryPlace.index(1));
    relation.offset = readFinite(entry[2], entryPlace.index(2));
    path.mimic.push_back(std::move(relation));
  }

  path.statistics = statisticsFromJson(member(document, "statistics"), file, "statistics");
  return path;
}

PathFile readPathFile(const std::filesystem::path& file) { return parsePathFile(readTextFile(file), file.string()); }

}  // namespace pmdplan
