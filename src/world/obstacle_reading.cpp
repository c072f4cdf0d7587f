#include "obstacle_reading.hpp"

#include <map>

#include "placement_reading.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/model/mesh_file.hpp"
#include "pmdplan/model/resource_path.hpp"

namespace pmdplan {
namespace {

constexpr const char* kObstacleForm =
    "an obstacle {name, one of box / cylinder / sphere / mesh, xyz, optional rpy_deg}";
/// Every check tests the robot against every obstacle it reaches; a task has a handful.
constexpr std::size_t kMaxObstacles = 1000;
constexpr const char* kLength = "a length in metres greater than 0";

Shape readBox(const YamlField& field) {
  return BoxShape{field.positiveVector3("full extents [x, y, z] in metres, each greater than 0")};
}

Shape readCylinder(const YamlField& field) {
  const std::string form = "{radius, length} in metres (the axis is the local z)";
  field.requireMapWithKeys({"radius", "length"}, form);
  CylinderShape cylinder;
  cylinder.radius = field.child("radius", kLength).positiveNumber(kLength);
  cylinder.length = field.child("length", kLength).positiveNumber(kLength);
  return cylinder;
}

Shape readSphere(const YamlField& field) {
  return SphereShape{field.positiveNumber("a radius in metres greater than 0")};
}

Shape readMesh(const YamlField& field, const std::filesystem::path& taskDirectory) {
  const std::string form = "{file, optional scale [x, y, z]} (file relative to the task file)";
  field.requireMapWithKeys({"file", "scale"}, form);
  const YamlField fileField = field.child("file", "a mesh file path");
  const std::string written = fileField.text("a mesh file path (relative to the task file)");
  if (written.empty()) fileField.fail("expected a mesh file path, got an empty string");
  std::filesystem::path resolved;
  try {
    resolved = resolveResourcePath(written, taskDirectory / std::filesystem::path(fileField.file()).filename(),
                                   fileField.path());
  } catch (const InputError& e) {
    fileField.fail(e.message() + " (relative paths are relative to the task file)");
  }
  Eigen::Vector3d scale = Eigen::Vector3d::Ones();
  if (const auto scaleField = field.optionalChild("scale")) {
    scale = scaleField->positiveVector3("scale factors [x, y, z], each greater than 0");
    // Before the mesh is read; the part ".mesh.scale[i]" becomes "[i]" of the scale field.
    if (auto problem = shapeBoundsProblem(MeshShape{resolved, scale, nullptr})) {
      problem->part = problem->part.substr(problem->part.find('['));
      failOnBoundsProblem(*scaleField, problem);
    }
  }
  return loadMeshShape(resolved, scale);
}

Obstacle readObstacle(const YamlField& field, const std::filesystem::path& taskDirectory) {
  field.requireMapWithKeys({"name", "box", "cylinder", "sphere", "mesh", "xyz", "rpy_deg"}, kObstacleForm,
                           "unknown obstacle type or key");
  Obstacle obstacle;
  const YamlField nameField = field.child("name", "a unique obstacle name");
  obstacle.name = nameField.text("a unique obstacle name");
  if (obstacle.name.empty()) nameField.fail("expected a unique obstacle name, got an empty one");

  std::optional<YamlField> shapeField;
  std::string type;
  for (const char* candidateType : {"box", "cylinder", "sphere", "mesh"}) {
    if (auto candidate = field.optionalChild(candidateType)) {
      if (shapeField) {
        candidate->fail("an obstacle has exactly one shape, but " + shapeField->path() + " is given too");
      }
      shapeField = candidate;
      type = candidateType;
    }
  }
  if (!shapeField) {
    field.fail(
        "no shape; expected one of box: [x, y, z], cylinder: {radius, length}, "
        "sphere: radius, mesh: {file, scale}");
  }
  if (type == "box")
    obstacle.shape = readBox(*shapeField);
  else if (type == "cylinder")
    obstacle.shape = readCylinder(*shapeField);
  else if (type == "sphere")
    obstacle.shape = readSphere(*shapeField);
  else
    obstacle.shape = readMesh(*shapeField, taskDirectory);
  failOnBoundsProblem(field, shapeBoundsProblem(obstacle.shape));

  obstacle.pose = readPlacement(field);
  return obstacle;
}

}  // namespace

std::vector<Obstacle> readObstacles(const YamlField& list, const std::filesystem::path& taskDirectory) {
  std::vector<Obstacle> obstacles;
  std::map<std::string, std::string> firstPath;
  MeshTriangleBudget meshBudget("obstacle meshes of the task");
  const std::vector<YamlField> items = list.elements(std::string("a list of ") + kObstacleForm);
  if (items.size() > kMaxObstacles)
    list.fail("more than " + std::to_string(kMaxObstacles) + " obstacles (" + std::to_string(items.size()) +
              "), the most a task may have");
  for (const YamlField& item : items) {
    Obstacle obstacle = readObstacle(item, taskDirectory);
    if (const auto* mesh = std::get_if<MeshShape>(&obstacle.shape)) meshBudget.add(*mesh, item.file(), item.location());
    if (const auto previous = firstPath.find(obstacle.name); previous != firstPath.end()) {
      item.child("name", "")
          .fail("obstacle name '" + obstacle.name + "' is already used by " + previous->second +
                "; names must be unique");
    }
    firstPath.emplace(obstacle.name, item.path());
    obstacles.push_back(std::move(obstacle));
  }
  return obstacles;
}

}  // namespace pmdplan
