// Issue 23, Done-when 1 (CLI): a URDF whose collision geometry is all meshes (the SAH + TX90 with
// every primitive a triangulated STL) checks, plans and validates with either checker; a mesh
// with a vertex that is not a number is bad input (exit 2) naming the file and the vertex.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "collision/primitive_meshes.hpp"
#include "support/run_cli.hpp"
#include "support/temp_dir.hpp"

namespace pmdplan {
namespace {

using test::quoted;
using test::runCli;

const std::filesystem::path kRobots = std::filesystem::path(PMDPLAN_TEST_DATA_DIR) / "robots" / "sah_tx90";

/// can_on_table with the mesh robot; returns the task file.
std::filesystem::path meshTask(const test::TempDir& dir) {
  const auto urdf = testing::writeMeshRobot(dir, kRobots / "sah_tx90.urdf", kRobots / "sah_tx90.srdf", "mesh_robot",
                                            testing::Tessellation::Circumscribed);
  return dir.write("mesh_task.yaml", testing::builtInTaskText("can_on_table", urdf.filename().string()));
}

TEST(MeshRobotCli, PlansAndValidatesWithBothCheckers) {
  test::TempDir dir;
  const auto task = meshTask(dir);
  const auto check = runCli("check " + quoted(task) + " --json");
  ASSERT_EQ(check.exitCode, 0) << check.out << check.err;
  for (const std::string checker : {"fast", "exact"}) {
    const auto path = dir.path() / (checker + ".path.json");
    const auto plan =
        runCli("plan " + quoted(task) + " --checker " + checker + " --seed 2 --time-limit 120 -o " + quoted(path));
    ASSERT_EQ(plan.exitCode, 0) << checker << ": " << plan.out << plan.err;
    const auto validate = runCli("validate " + quoted(task) + " " + quoted(path) + " --json");
    ASSERT_EQ(validate.exitCode, 0) << checker << ": " << validate.out << validate.err;
    EXPECT_TRUE(nlohmann::json::parse(validate.out)["valid"].get<bool>()) << checker;
  }
}

TEST(MeshRobotCli, AMeshWithANanVertexIsBadInputNamingTheFileAndTheVertex) {
  test::TempDir dir;
  const auto task = meshTask(dir);
  // The sphere mesh with one coordinate replaced by nan.
  std::string sphere = readTextFile(dir.path() / "meshes" / "sphere.stl");
  const auto at = sphere.find("vertex ") + 7;
  sphere.replace(at, sphere.find(' ', at) - at, "nan");
  dir.write("meshes/sphere.stl", sphere);
  const auto check = runCli("check " + quoted(task));
  EXPECT_EQ(check.exitCode, 2) << check.out << check.err;
  EXPECT_NE(check.err.find("sphere.stl"), std::string::npos) << check.err;
  EXPECT_NE(check.err.find("vertex"), std::string::npos) << check.err;
}

}  // namespace
}  // namespace pmdplan
