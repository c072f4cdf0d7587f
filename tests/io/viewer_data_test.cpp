#include "pmdplan/io/viewer/viewer_data.hpp"

#include <gtest/gtest.h>

#include "pmdplan/io/viewer/robot_mimic.hpp"
#include "pmdplan/io/viewer/viewer_folder.hpp"
#include "support/temp_dir.hpp"

namespace pmdplan {
namespace {

PathFile startToGoal(const Task& task) {
  PathFile path;
  path.task = task.name;
  path.planner = "pmd";
  path.jointNames = task.robot->activeJointNames();
  path.points = {task.start, task.goal};
  path.mimic = mimicRelations(*task.robot);
  return path;
}

TEST(ViewerData, AMeshObstacleTravelsWithTheFolderAndARobotWithoutModelHasNoSynergies) {
  test::TempDir dir;
  Task task = loadTaskByName("can_on_table");
  const auto mesh = dir.write("part.stl", "solid part\nendsolid part\n");
  Obstacle part;
  part.name = "part";
  part.shape = MeshShape{mesh, Eigen::Vector3d(0.001, 0.001, 0.001), nullptr};
  part.pose.translation() << 0.1, 0.2, 0.3;
  task.obstacles.push_back(part);

  const ViewerData data = viewerData(task, startToGoal(task), nullptr, {dir.path() / "p.json", {}});
  const auto& shape = data.document["task"]["obstacles"].back()["shape"];
  EXPECT_EQ(shape["type"], "mesh");
  EXPECT_EQ(shape["file"], "meshes/4-part.stl");
  EXPECT_EQ(shape["scale"], nlohmann::ordered_json({0.001, 0.001, 0.001}));
  EXPECT_EQ(data.document["task"]["obstacles"].back()["quaternion"], nlohmann::ordered_json({0.0, 0.0, 0.0, 1.0}));
  EXPECT_TRUE(data.document["synergies"].is_null());
  EXPECT_TRUE(data.document["sources"]["synergy_file"].is_null());
  // The checker cannot load a mesh without triangles: no clearance, and the page says why.
  EXPECT_TRUE(data.document["path"]["clearance"].is_null());
  ASSERT_EQ(data.document["warnings"].size(), 1u);
  EXPECT_NE(data.document["warnings"][0].get<std::string>().find("no collisions or clearance shown"),
            std::string::npos);

  const auto assets = dir.path() / "assets";
  for (const auto& file : viewerAssetFiles()) dir.write("assets/" + file, file);
  const auto written = writeViewerFolder(dir.path() / "viewer", data, assets);
  EXPECT_EQ(written.size(), viewerAssetFiles().size() + 2);
  EXPECT_TRUE(std::filesystem::is_regular_file(dir.path() / "viewer" / "meshes" / "4-part.stl"));
  EXPECT_TRUE(std::filesystem::is_regular_file(dir.path() / "viewer" / "viewer-data.js"));
}

}  // namespace
}  // namespace pmdplan
