// URDF geometry within ShapeBounds (model/collision_shape.hpp), xacro left in a URDF, and
// package:// paths that would leave their package: each refused with an InputError naming the
// URDF and the link, joint or line.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "pmdplan/core/input_error.hpp"
#include "pmdplan/model/resource_path.hpp"
#include "pmdplan/model/robot_model.hpp"
#include "support/input_error_matchers.hpp"
#include "support/temp_dir.hpp"

namespace pmdplan {
namespace {

using test::expectInputError;

std::string urdf(const std::string& geometry, const std::string& origin = "0 0 0.1", const std::string& extra = "") {
  return "<robot name=\"r\"" + std::string(extra.empty() ? "" : " xmlns:xacro=\"http://www.ros.org/wiki/xacro\"") +
         ">\n<link name=\"base\"/>\n<link name=\"arm\"><collision><origin xyz=\"" + origin + "\"/><geometry>" +
         geometry + "</geometry></collision></link>\n" + extra +
         "<joint name=\"j\" type=\"revolute\"><parent link=\"base\"/><child link=\"arm\"/><axis xyz=\"0 0 1\"/>"
         "<limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/></joint>\n</robot>\n";
}

TEST(UrdfGeometryBounds, ShapeSizesOutsideTheBoundsAreRefused) {
  test::TempDir dir;
  const auto file = dir.path() / "r.urdf";
  const auto refused = [&](const std::string& geometry, const std::string& field, const std::string& message) {
    dir.write("r.urdf", urdf(geometry));
    expectInputError([&] { RobotModel::load(file); }, file.string(), field, message);
  };
  refused("<box size=\"1e300 1 1\"/>", "link[arm].collision[0].box[0]", "from 1e-06 to 100, got 1e+300");
  refused("<box size=\"0.1 100.5 0.1\"/>", "link[arm].collision[0].box[1]", "got 100.5");
  refused("<sphere radius=\"1e20\"/>", "link[arm].collision[0].sphere", "a radius in metres");
  refused("<sphere radius=\"1e-7\"/>", "link[arm].collision[0].sphere", "got 1e-07");
  refused("<cylinder radius=\"0.1\" length=\"1e10\"/>", "link[arm].collision[0].cylinder.length", "a length");
  refused("<cylinder radius=\"-0.1\" length=\"1\"/>", "link[arm].collision[0].cylinder.radius", "got -0.1");
  // The largest allowed shapes load.
  dir.write("r.urdf", urdf("<box size=\"100 100 100\"/>"));
  EXPECT_NO_THROW(RobotModel::load(file));
  dir.write("r.urdf", urdf("<cylinder radius=\"0.000001\" length=\"100\"/>"));
  EXPECT_NO_THROW(RobotModel::load(file));
}

TEST(UrdfGeometryBounds, OriginsBeyondTheBoundAndNonPositiveMeshScalesAreRefused) {
  test::TempDir dir;
  const auto file = dir.path() / "r.urdf";
  dir.write("r.urdf", urdf("<sphere radius=\"0.1\"/>", "1001 0 0"));
  expectInputError([&] { RobotModel::load(file); }, file.string(), "link[arm].collision[0].origin.xyz[0]", "got 1001");
  dir.write("r.urdf", urdf("<sphere radius=\"0.1\"/>", "0 0 -1e300"));
  expectInputError([&] { RobotModel::load(file); }, file.string(), "origin.xyz[2]", "from -1000 to 1000");
  dir.write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  // A negative scale used to be accepted (a mirrored mesh, its triangles turned inside out).
  for (const std::string scale : {"1 -1 1", "0 1 1", "1e9 1 1"}) {
    dir.write("r.urdf", urdf("<mesh filename=\"tri.obj\" scale=\"" + scale + "\"/>"));
    expectInputError([&] { RobotModel::load(file); }, file.string(), "link[arm].collision[0].mesh.scale",
                     "scale factor");
  }
  dir.write("r.urdf", urdf("<mesh filename=\"tri.obj\" scale=\"0.001 0.001 0.001\"/>"));
  EXPECT_NO_THROW(RobotModel::load(file));
}

TEST(UrdfGeometryBounds, XacroLeftInTheUrdfIsRefusedNamingTheElement) {
  test::TempDir dir;
  const auto file = dir.path() / "r.urdf";
  dir.write("r.urdf", urdf("<sphere radius=\"0.1\"/>", "0 0 0.1", "<xacro:property name=\"side\" value=\"0.1\"/>\n"));
  expectInputError([&] { RobotModel::load(file); }, file.string(), "line 4", "<xacro:property> is a xacro element");
  dir.write("r.urdf", urdf("<sphere radius=\"${side}\"/>"));
  expectInputError([&] { RobotModel::load(file); }, file.string(), "<sphere radius>", "run xacro first");
  dir.write("r.urdf", urdf("<mesh filename=\"$(find pkg)/m.stl\"/>"));
  expectInputError([&] { RobotModel::load(file); }, file.string(), "<mesh filename>", "run xacro first");
}

TEST(UrdfGeometryBounds, APackagePathMayNotLeaveItsPackage) {
  test::TempDir dir;
  const auto mesh = dir.write("packages/pkg/meshes/tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  dir.write("secret.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  setPackageSearchPath(PackageSearchPath::parse((dir.path() / "packages").string()));
  const auto urdfFile = dir.path() / "r.urdf";
  EXPECT_EQ(resolveResourcePath("package://pkg/meshes/tri.obj", urdfFile, "f"), mesh);
  EXPECT_EQ(resolveResourcePath("package://pkg/meshes/../meshes/tri.obj", urdfFile, "f"), mesh);
  for (const std::string& escape :
       std::vector<std::string>{"package://pkg/../../secret.obj", "package://pkg/meshes/../../../secret.obj",
                                "package://../secret.obj", "package://pkg/" + (dir.path() / "secret.obj").string()})
    expectInputError([&] { resolveResourcePath(escape, urdfFile, "link[x]"); }, urdfFile.string(), "link[x]",
                     "'" + escape + "'");
  setPackageSearchPath({});
}

}  // namespace
}  // namespace pmdplan
