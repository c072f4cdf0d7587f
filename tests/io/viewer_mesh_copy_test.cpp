// What `pmdplan view` copies into its folder from a robot's <visual> meshes: only files that are
// meshes (a regular .stl, .obj or .dae file that passes the mesh reader's checks), never a secret a
// URDF names (file:///etc/shadow), nothing from outside a package, and never with wider permission
// bits than the source has.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "pmdplan/io/viewer/robot_mimic.hpp"
#include "pmdplan/io/viewer/viewer_data.hpp"
#include "pmdplan/io/viewer/viewer_folder.hpp"
#include "pmdplan/model/resource_path.hpp"
#include "pmdplan/world/task.hpp"
#include "support/temp_dir.hpp"

namespace pmdplan {
namespace {

const char* kTetraStl =
    "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 0.01 0 0\nvertex 0 0.01 0\nendloop\nendfacet\n"
    "endsolid t\n";

std::string visual(const std::string& filename) {
  return "<visual><geometry><mesh filename=\"" + filename + "\"/></geometry></visual>";
}

mode_t modeOf(const std::filesystem::path& file) {
  struct stat status {};
  EXPECT_EQ(::stat(file.c_str(), &status), 0) << file;
  return status.st_mode & 0777;
}

/// A task whose robot's tip link shows the visual meshes `visuals`.
Task taskWithVisuals(const test::TempDir& dir, const std::string& visuals) {
  dir.write("robot.urdf",
            "<robot name=\"r\"><link name=\"base\"><collision><geometry><box size=\"0.1 0.1 0.1\"/></geometry>"
            "</collision></link><link name=\"tip\">" +
                visuals +
                "<collision><geometry><sphere radius=\"0.02\"/></geometry></collision></link><joint name=\"a\" "
                "type=\"revolute\"><parent link=\"base\"/><child link=\"tip\"/><origin xyz=\"0 0 0.3\"/><axis xyz=\"0 "
                "0 1\"/><limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/></joint></robot>\n");
  dir.write("robot.srdf",
            "<robot name=\"r\"><group name=\"arm\"><joint name=\"a\"/></group><end_effector name=\"e\" "
            "parent_link=\"tip\" group=\"arm\"/></robot>\n");
  return loadTask(dir.write("task.yaml",
                            "name: t\nrobot: robot.urdf\nbase: {xyz: [0, 0, 0]}\nobstacles: []\n"
                            "start: {joints: {a: 0}}\ngoal: {joints: {a: 0.5}}\n"));
}

std::filesystem::path writeFolder(const test::TempDir& dir, const Task& task) {
  PathFile path;
  path.task = task.name;
  path.planner = "pmd";
  path.jointNames = task.robot->activeJointNames();
  path.points = {task.start, task.goal};
  path.mimic = mimicRelations(*task.robot);
  const ViewerData data = viewerData(task, path, nullptr, {dir.path() / "p.json", {}});
  for (const auto& file : viewerAssetFiles()) dir.write("assets/" + file, file);
  writeViewerFolder(dir.path() / "viewer", data, dir.path() / "assets");
  return dir.path() / "viewer";
}

TEST(ViewerMeshCopy, OnlyMeshesAreCopiedNeverAFileAUrdfNamesOtherwise) {
  test::TempDir dir;
  const auto secret = dir.write("private/shadow", "root:$6$secret:19000:0:99999:7:::\n");
  const auto disguised = dir.write("private/shadow.stl", "root:$6$secret:19000:0:99999:7:::\n");
  dir.write("packages/pkg/meshes/tip.stl", kTetraStl);
  dir.write("packages/escaped.stl", kTetraStl);
  setPackageSearchPath(PackageSearchPath::parse((dir.path() / "packages").string()));
  const Task task =
      taskWithVisuals(dir, visual("file://" + secret.string()) + visual("file://" + disguised.string()) +
                               visual("package://pkg/../escaped.stl") + visual("package://pkg/meshes/tip.stl"));
  const auto folder = writeFolder(dir, task);
  setPackageSearchPath({});
  std::vector<std::string> copied;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(folder))
    if (entry.is_regular_file() && entry.path().parent_path().filename() == "robot-meshes")
      copied.push_back(entry.path().filename().string());
  ASSERT_EQ(copied.size(), 1u);
  EXPECT_EQ(copied[0], "0-tip.stl");
  // No file of the folder holds the secret (viewer-data.js names the references, not the contents).
  for (const auto& entry : std::filesystem::recursive_directory_iterator(folder)) {
    if (!entry.is_regular_file()) continue;
    std::ifstream in(entry.path(), std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(text.find("root:$6$"), std::string::npos) << entry.path();
  }
}

TEST(ViewerMeshCopy, ACopyNeverHasWiderPermissionsThanItsSource) {
  test::TempDir dir;
  const auto mesh = dir.write("tip.stl", kTetraStl);
  std::filesystem::permissions(mesh, std::filesystem::perms(0644));
  const Task task = taskWithVisuals(dir, visual("tip.stl"));
  const auto copy = writeFolder(dir, task) / "robot-meshes" / "0-tip.stl";
  EXPECT_EQ(modeOf(copy) & ~0644u, 0u);
  // The source made private: the copy written again loses the bits too.
  std::filesystem::permissions(mesh, std::filesystem::perms(0600));
  writeFolder(dir, task);
  EXPECT_EQ(modeOf(copy) & 0077u, 0u) << std::oct << modeOf(copy);
  // A new folder from the private source.
  std::filesystem::remove_all(dir.path() / "viewer");
  writeFolder(dir, task);
  EXPECT_EQ(modeOf(copy) & 0077u, 0u) << std::oct << modeOf(copy);
}

}  // namespace
}  // namespace pmdplan
