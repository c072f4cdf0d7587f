#include "pmdplan/io/path_file.hpp"

#include <cmath>
#include <set>
#include <stdexcept>

#include "json_reading.hpp"
#include "pmdplan/core/atomic_file.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/io/json_text.hpp"
#include "pmdplan/io/statistics_json.hpp"

namespace pmdplan {

std::string formatPathFile(const PathFile& path, const PathFileOptions& options) {
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
  nlohmann::ordered_json mimic = nlohmann::ordered_json::object();
  for (const MimicRelation& relation : path.mimic)
    mimic[relation.joint] = nlohmann::ordered_json::array({relation.source, relation.multiplier, relation.offset});
  document["mimic"] = std::move(mimic);
  document["statistics"] = statisticsToJson(path.statistics, options.includeTimings);
  return formatJson(document);
}

void writePathFile(const std::filesystem::path& file, const PathFile& path, const PathFileOptions& options) {
  writeFileAtomically(file, formatPathFile(path, options));
}

PathFile parsePathFile(const std::string& text, const std::string& file) {
  using namespace json_reading;
  nlohmann::json document;
  try {
    document = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& error) {  // a syntax error, or a number beyond a double
    throw InputError(file, "", std::string("not valid JSON (") + error.what() + ")");
  }
  const Place root{file, ""};
  requireObject(document, root);
  checkKeys(document, root, {"task", "planner", "seed", "joint_names", "points", "mimic", "statistics"},
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
    if (!seen.insert(name).second) namesPlace.index(i).fail("joint '" + name + "' appears twice");
    path.jointNames.push_back(std::move(name));
  }

  const Place pointsPlace = root.key("points");
  const nlohmann::json& points = requireArray(member(document, "points"), pointsPlace);
  if (points.size() < 2) pointsPlace.fail("expected at least two points (start and goal), found " + std::to_string(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Place pointPlace = pointsPlace.index(i);
    requireObject(points[i], pointPlace);
    checkKeys(points[i], pointPlace, {"positions"}, {"positions"});
    const Place positionsPlace = pointPlace.key("positions");
    const nlohmann::json& positions = requireArray(member(points[i], "positions"), positionsPlace);
    if (positions.size() != path.jointNames.size())
      positionsPlace.fail("expected " + std::to_string(path.jointNames.size()) + " values (one per joint name), found " +
                          std::to_string(positions.size()));
    Configuration q(static_cast<Eigen::Index>(positions.size()));
    for (std::size_t k = 0; k < positions.size(); ++k)
      q[static_cast<Eigen::Index>(k)] = readFinite(positions[k], positionsPlace.index(k));
    path.points.push_back(std::move(q));
  }

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
