// Mesh collision geometry as the model reads it: STL (ASCII and binary), OBJ and Collada through
// assimp, scaled; URDF mesh paths relative to the URDF or absolute; a vertex that is not a finite
// number is bad input naming the mesh file and the vertex.
#include "pmdplan/model/mesh_file.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>

#include "pmdplan/core/input_error.hpp"
#include "pmdplan/model/resource_path.hpp"
#include "pmdplan/model/robot_model.hpp"
#include "support/input_error_matchers.hpp"
#include "support/temp_dir.hpp"

namespace pmdplan {
namespace {

const char* kTetraObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";

/// A binary STL of one triangle whose first vertex has x = `x`.
std::filesystem::path binaryStl(const test::TempDir& dir, const std::string& name, float x) {
  const auto file = dir.path() / name;
  std::ofstream out(file, std::ios::binary);
  char header[80] = {};
  out.write(header, 80);
  const std::uint32_t count = 1;
  out.write(reinterpret_cast<const char*>(&count), 4);
  const float values[12] = {0, 0, 1, x, 0, 0, 1, 0, 0, 0, 1, 0};
  out.write(reinterpret_cast<const char*>(values), sizeof values);
  const std::uint16_t attribute = 0;
  out.write(reinterpret_cast<const char*>(&attribute), 2);
  return file;
}

std::string urdfWithMesh(const std::string& filename, const std::string& scale) {
  return R"(<?xml version="1.0"?>
<robot name="toy">
  <link name="base"/>
  <link name="arm"><collision><geometry><mesh filename=")" +
         filename + R"(" scale=")" + scale + R"("/></geometry></collision></link>
  <joint name="shoulder" type="revolute"><parent link="base"/><child link="arm"/>
    <origin xyz="0 0 0.5" rpy="0 0 0"/><axis xyz="0 0 1"/><limit lower="-1" upper="2" effort="1" velocity="1"/></joint>
</robot>
)";
}

TEST(MeshFile, ReadsObjStlAndColladaScaled) {
  test::TempDir dir;
  const TriangleMesh obj = readMeshFile(dir.write("tetra.obj", kTetraObj), Eigen::Vector3d(2, 3, 4));
  EXPECT_EQ(obj.triangles.size(), 4u);
  Eigen::Vector3d high = Eigen::Vector3d::Zero();
  for (const auto& v : obj.vertices) high = high.cwiseMax(v);
  EXPECT_TRUE(high.isApprox(Eigen::Vector3d(2, 3, 4)));
  const TriangleMesh stl = readMeshFile(binaryStl(dir, "one.stl", 0.5f), Eigen::Vector3d::Ones());
  ASSERT_EQ(stl.triangles.size(), 1u);
  const std::string dae = R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit meter="1"/><up_axis>Z_UP</up_axis></asset>
  <library_geometries><geometry id="g"><mesh>
    <source id="p"><float_array id="pa" count="9">0 0 0 1 0 0 0 1 0</float_array>
      <technique_common><accessor source="#pa" count="3" stride="3"><param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/></accessor></technique_common></source>
    <vertices id="v"><input semantic="POSITION" source="#p"/></vertices>
    <triangles count="1"><input semantic="VERTEX" source="#v" offset="0"/><p>0 1 2</p></triangles>
  </mesh></geometry></library_geometries>
  <library_visual_scenes><visual_scene id="s"><node id="n"><instance_geometry url="#g"/></node></visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#s"/></scene>
</COLLADA>
)";
  const TriangleMesh collada = readMeshFile(dir.write("tri.dae", dae), Eigen::Vector3d::Ones());
  EXPECT_EQ(collada.triangles.size(), 1u);
}

TEST(MeshFile, AVertexThatIsNotANumberNamesTheFileAndTheVertex) {
  test::TempDir dir;
  const auto stl = binaryStl(dir, "bad.stl", std::numeric_limits<float>::quiet_NaN());
  test::expectInputError([&] { readMeshFile(stl, Eigen::Vector3d::Ones()); }, stl.string(), "vertex 1", "finite");
  const auto obj = dir.write("bad.obj", "v 0 0 0\nv 1 0 nan\nv 0 1 0\nf 1 2 3\n");
  test::expectInputError([&] { readMeshFile(obj, Eigen::Vector3d::Ones()); }, obj.string(), "vertex 2", "nan");
  // Through a URDF too: the robot is refused, not read with a broken mesh.
  std::filesystem::copy_file(stl, dir.path() / "meshes_bad.stl");
  const auto urdf = dir.write("bad.urdf", urdfWithMesh("meshes_bad.stl", "1 1 1"));
  test::expectInputError([&] { RobotModel::load(urdf); }, (dir.path() / "meshes_bad.stl").string(), "vertex", "finite");
}

TEST(MeshFile, NoTrianglesOrNoFileIsBadInput) {
  test::TempDir dir;
  const auto empty = dir.write("empty.obj", "v 0 0 0\nv 1 0 0\n");
  EXPECT_THROW(readMeshFile(empty, Eigen::Vector3d::Ones()), InputError);
  const auto urdf = dir.write("missing.urdf", urdfWithMesh("nowhere.stl", "1 1 1"));
  test::expectInputError([&] { RobotModel::load(urdf); }, urdf.string(), "link[arm].collision[0]", "nowhere.stl");
}

TEST(MeshFile, UrdfMeshPathsAreRelativeToTheUrdfOrAbsoluteAndTheExtentIsKnown) {
  test::TempDir dir;
  const auto mesh = dir.write("meshes/tetra.obj", kTetraObj);
  EXPECT_EQ(resolveResourcePath("meshes/tetra.obj", dir.path() / "robot.urdf", "f"), mesh);
  EXPECT_EQ(resolveResourcePath(mesh.string(), "/elsewhere/robot.urdf", "f"), mesh);
  EXPECT_EQ(resolveResourcePath("file://" + mesh.string(), "/elsewhere/robot.urdf", "f"), mesh);
  test::expectInputError([&] { resolveResourcePath("http://example.org/a.stl", dir.path() / "r.urdf", "link[x]"); },
                         (dir.path() / "r.urdf").string(), "link[x]", "not a URI");
  const RobotModel model = RobotModel::load(dir.write("robot.urdf", urdfWithMesh("meshes/tetra.obj", "0.5 0.5 2")));
  const auto& shapes = model.links()[static_cast<std::size_t>(model.linkIndex("arm"))].collisionShapes;
  ASSERT_EQ(shapes.size(), 1u);
  const auto& shape = std::get<MeshShape>(shapes[0].shape);
  ASSERT_TRUE(shape.triangles);
  EXPECT_EQ(shape.triangles->triangles.size(), 4u);
  EXPECT_DOUBLE_EQ(boundingRadius(shapes[0].shape), 2.0);  // the vertex (0, 0, 1) scaled by 2
}

}  // namespace
}  // namespace pmdplan
